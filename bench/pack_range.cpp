// Which target porosities the packer reaches completely and uniformly, per
// soil and arrangement. A benchmark, not a test: it prints figures and
// checks nothing. Run from the repository root:
//   build/bench/pack_range [psd-file ...] [--side S] [--targets a,b,...]
//                          [--seed K] [--rules discrete,layerwise]
//                          [--layering W]
// Defaults: the four shipped soils (input_scripts/psd/cu2.0.txt .. cu3.5.txt),
// side 6 coarsest-interval diameters, targets 0.33, 0.34, ..., 0.45, seed 1.
//
// Per soil and rule:
//  (a) the porosity of the container packed full, the lowest porosity the
//      packing reaches: packed at target 0.25 (a list longer than the
//      container holds), 1 - packed_volume / V;
//  (b) per target: the share of the list placed, the achieved porosity
//      (placed spheres only), min and max of the 27 sub-cube porosities, the
//      interior porosity (layer one coarsest diameter), Spearman(radius,
//      distance from the centre), the size assortativity of touching pairs,
//      the local grading (median over 4 x 4 x 4 sub-cubes of their Cu,
//      d60/d10 by volume, over the whole specimen's Cu: 1 for a mixture,
//      below 1 where like sizes lie together),
//      the full-packing porosity of that run, the time, and whether the
//      case is complete and uniform:
//        placed >= 99.5 % of the list, |achieved - target| <= 0.005,
//        all 27 sub-cubes within 0.03 of the target, interior within 0.01.
//      The flags name what fails: P placed, A achieved, S sub-cubes,
//      I interior.
// At the end, per soil and rule, the lowest and highest target tested that
// is complete and uniform.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <cstdlib>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "front_packer.h"
#include "psd.h"
#include "specimen_measure.h"

using namespace fabric;

namespace {

struct Run {
  long long listed = 0;
  PackingResult result;
  double volume = 0.0;
  double seconds = 0.0;
  Box box;
  double dmax = 0.0;
};

Run run(const std::vector<SizeInterval>& intervals, double side, double porosity,
        Arrangement a, std::uint64_t seed, double layering) {
  Run out;
  double L = side * intervals.back().d_mean;
  out.volume = L * L * L;
  auto list = particle_list(intervals, out.volume, porosity);
  PackingSpec spec = packing_spec(list, Vec3(0, 0, 0), Vec3(L, L, L));
  spec.arrangement = a;
  spec.start = default_start(a);  // as fix sequential/pack does
  spec.seed = seed;
  if (!std::isnan(layering)) spec.layering = layering;
  out.listed = list.total();
  out.box = Box{spec.lo, spec.hi};
  out.dmax = *std::max_element(list.diameter.begin(), list.diameter.end());
  auto t0 = std::chrono::steady_clock::now();
  out.result = pack(spec);
  out.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

std::vector<double> parse_list(const std::string& s) {
  std::vector<double> v;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) v.push_back(std::atof(item.c_str()));
  return v;
}

std::string base_name(const std::string& path) {
  std::string f = path.substr(path.find_last_of('/') + 1);
  return f.substr(0, f.rfind('.'));
}

struct Summary {
  std::string soil, rule;
  double full = NAN;
  std::vector<double> ok, tested;
};

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> psds;
  double side = 6.0;
  std::uint64_t seed = 1;
  double layering = NAN;  // not given: the packer's default
  std::vector<Arrangement> rules = {Arrangement::discrete, Arrangement::layerwise};
  std::vector<double> targets;
  for (double t = 0.33; t < 0.4550; t += 0.01) targets.push_back(std::round(t * 100) / 100);
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--side" && i + 1 < argc) side = std::atof(argv[++i]);
    else if (a == "--targets" && i + 1 < argc) targets = parse_list(argv[++i]);
    else if (a == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--layering" && i + 1 < argc) layering = std::atof(argv[++i]);
    else if (a == "--rules" && i + 1 < argc) {
      rules.clear();
      std::stringstream ss(argv[++i]);
      std::string r;
      while (std::getline(ss, r, ','))
        if (r == "discrete") rules.push_back(Arrangement::discrete);
        else if (r == "layerwise") rules.push_back(Arrangement::layerwise);
        else {
          std::fprintf(stderr, "pack_range: rule %s: use discrete or layerwise\n", r.c_str());
          return 2;
        }
    } else if (a.rfind("--", 0) == 0) {
      std::fprintf(stderr,
                   "usage: pack_range [psd-file ...] [--side S] "
                   "[--targets a,b,...] [--seed K] [--rules discrete,layerwise] "
                   "[--layering W]\n");
      return 2;
    } else psds.push_back(a);
  }
  if (psds.empty())
    for (const char* c : {"2.0", "2.5", "3.0", "3.5"})
      psds.push_back(std::string("input_scripts/psd/cu") + c + ".txt");
  if (!(side > 0) || targets.empty() || rules.empty() || !(std::isnan(layering) || layering > 0)) {
    std::fprintf(stderr, "pack_range: side must be > 0, targets and rules not empty, layering > 0\n");
    return 2;
  }

  std::printf("# side %.3g coarsest-interval diameters, 20 intervals, seed %llu, "
              "default start (discrete auto, layerwise floor); complete and uniform: placed >= 99.5 %%, "
              "|achieved - target| <= 0.005, 27 sub-cubes within 0.03, interior "
              "(layer 1 coarsest diameter) within 0.01\n",
              side, static_cast<unsigned long long>(seed));
  if (!std::isnan(layering)) std::printf("# layering %g\n", layering);
  std::printf("%-6s %-9s %6s %8s %8s %8s %7s %7s %8s %8s %7s %7s %7s %7s %7s %s\n",
              "soil", "rule", "target", "listed", "placed%", "achieved",
              "sub_min", "sub_max", "interior", "spearman", "assort", "loc_cu", "full",
              "seconds", "c&u", "fails");
  std::fflush(stdout);

  std::vector<Summary> summary;
  for (const std::string& path : psds) {
    auto psd = [&] {
      try {
        return ParticleSizeDistribution::read(path);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "pack_range: %s\n", e.what());
        std::exit(2);
      }
    }();
    auto intervals = psd.equal_mass_intervals(20);
    for (Arrangement a : rules) {
      Summary sm;
      sm.soil = base_name(path);
      sm.rule = to_string(a);
      {
        Run f = run(intervals, side, 0.25, a, seed, layering);
        sm.full = 1.0 - f.result.packed_volume / f.volume;
        std::printf("%-6s %-9s %6s %8lld %8.2f %8s %7s %7s %8s %8s %7s %7s %7.4f %7.1f %7s %s\n",
                    sm.soil.c_str(), sm.rule.c_str(), "0.25", f.listed,
                    100.0 * f.result.placed() / f.listed, "-", "-", "-", "-",
                    "-", "-", "-", sm.full, f.seconds, "-", "(packed full)");
        std::fflush(stdout);
      }
      for (double target : targets) {
        Run r = run(intervals, side, target, a, seed, layering);
        const PackingResult& p = r.result;
        double vol = 0.0;
        for (double rr : p.radius) vol += sphere_volume(2.0 * rr);
        double achieved = 1.0 - vol / r.volume;
        double placed = double(p.placed()) / r.listed;
        PackingMeasure m(p.centre, p.radius, r.box);
        auto sub = m.subcube_porosity(3);
        double lo = *std::min_element(sub.begin(), sub.end());
        double hi = *std::max_element(sub.begin(), sub.end());
        double interior = m.interior_porosity(r.dmax);
        double spearman = m.radius_distance_spearman();
        double assort = m.size_assortativity();
        std::vector<double> lcu;
        {
          const int n = 4;
          Vec3 e = (r.box.hi - r.box.lo) / n;
          for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
              for (int k = 0; k < n; ++k) {
                Vec3 lo = r.box.lo + Vec3(i * e[0], j * e[1], k * e[2]);
                double c = m.local_cu(Box{lo, lo + e});
                if (std::isfinite(c)) lcu.push_back(c);
              }
        }
        double loc_cu = NAN;
        if (!lcu.empty()) {
          std::nth_element(lcu.begin(), lcu.begin() + lcu.size() / 2, lcu.end());
          loc_cu = lcu[lcu.size() / 2] / m.cu();
        }
        double full = 1.0 - p.packed_volume / r.volume;
        std::string fails;
        if (!(placed >= 0.995)) fails += "P";
        if (!(std::fabs(achieved - target) <= 0.005)) fails += "A";
        if (!(lo >= target - 0.03 && hi <= target + 0.03)) fails += "S";
        if (!(std::fabs(interior - target) <= 0.01)) fails += "I";
        bool ok = fails.empty();
        sm.tested.push_back(target);
        if (ok) sm.ok.push_back(target);
        std::printf("%-6s %-9s %6.2f %8lld %8.2f %8.4f %7.4f %7.4f %8.4f %8.3f %7.3f %7.3f %7.4f %7.1f %7s %s\n",
                    sm.soil.c_str(), sm.rule.c_str(), target, r.listed,
                    100.0 * placed, achieved, lo, hi, interior, spearman, assort,
                    loc_cu, full, r.seconds, ok ? "yes" : "no", fails.c_str());
        std::fflush(stdout);
      }
      summary.push_back(sm);
    }
  }

  std::printf("\n# per soil and rule: porosity packed full, and the lowest and "
              "highest target tested that is complete and uniform\n");
  std::printf("%-6s %-9s %7s %7s %7s %s\n", "soil", "rule", "full", "lowest",
              "highest", "complete and uniform / tested");
  for (const Summary& s : summary) {
    std::string which;
    for (double t : s.ok) {
      char b[16];
      std::snprintf(b, sizeof b, "%s%.2f", which.empty() ? "" : " ", t);
      which += b;
    }
    if (s.ok.empty())
      std::printf("%-6s %-9s %7.4f %7s %7s 0 / %zu\n", s.soil.c_str(),
                  s.rule.c_str(), s.full, "-", "-", s.tested.size());
    else
      std::printf("%-6s %-9s %7.4f %7.2f %7.2f %zu / %zu: %s\n", s.soil.c_str(),
                  s.rule.c_str(), s.full, s.ok.front(), s.ok.back(), s.ok.size(),
                  s.tested.size(), which.c_str());
  }
  std::fflush(stdout);
  return 0;
}
