// Which target porosities the packer reaches completely and uniformly, per
// soil and arrangement. A benchmark, not a test: it prints figures and
// checks nothing. Run from the repository root:
//   build/bench/pack_range [psd-file ...] [--side S] [--targets a,b,...]
//                          [--seed K] [--rules discrete,layerwise]
//                          [--layering W] [--profile N] [--no-full]
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
//      distance from the centre), the size assortativity of touching pairs
//      over the container and over the interior's pairs (asrt_in), the
//      local grading (loc_cu: the mean over the 27 sub-cubes of their Cu,
//      d60/d10 by volume, over the whole specimen's Cu: 1 for a mixture,
//      below 1 where like sizes lie together),
//      the full-packing porosity of that run, the time, and whether the
//      case is complete and uniform:
//        placed >= 99.5 % of the list, |achieved - target| <= 0.005,
//        all 27 sub-cubes within 0.03 of the target, interior within 0.01.
//      The flags name what fails: P placed, A achieved, S sub-cubes,
//      I interior (a layer-wise specimen is layered, not uniform: S and I
//      are expected there). Then LA's schedule width (width, 0 for DA) and the largest error of an interval's mass share in
//      percentage points (share).
//  --no-full: skip (a), the packing full (the summary's "full" is then nan).
//  --profile N: after each row, the porosity and mass-weighted mean
//      diameter (over the coarsest interval's) of N layers by height,
//      floor first, by volume.
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
  ParticleList list;
  double layering = 0.0;  // LA: the schedule's width packed with
};

// The largest difference, in percentage points, between an interval's share
// of the placed solid mass and its share in the list.
double max_share_error(const PackingResult& p, const ParticleList& list) {
  const std::size_t n = list.count.size();
  std::vector<double> placed(n, 0.0);
  double placed_total = 0.0, listed_total = 0.0;
  for (int i = 0; i < p.placed(); ++i) {
    double v = sphere_volume(2.0 * p.radius[i]);
    placed[p.size_class[i]] += v, placed_total += v;
  }
  for (std::size_t k = 0; k < n; ++k)
    listed_total += list.count[k] * sphere_volume(list.diameter[k]);
  double worst = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    worst = std::max(worst, std::fabs(placed[k] / placed_total -
                                      list.count[k] * sphere_volume(list.diameter[k]) /
                                          listed_total));
  return 100.0 * worst;
}

// The porosity and mass-weighted mean diameter (over the coarsest
// interval's) of `layers` slabs by height, floor first, by volume.
void print_profile(const PackingMeasure& m, int layers, double dmax) {
  auto prof = m.layer_profile(layers, 2);
  std::printf("#   profile by height (floor first), porosity / mean diameter over d_N:");
  for (const RegionPorosity& l : prof)
    std::printf(" %.3f/%.2f", l.porosity, l.mean_diameter / dmax);
  std::printf("\n");
}

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
  out.list = list;
  out.layering = spec.layering;
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

struct Options {
  std::vector<std::string> psds;
  double side = 6.0;
  std::uint64_t seed = 1;
  double layering = NAN;  // not given: the packer's default
  int profile = 0;        // layers of the height profile printed (0: none)
  bool full = true;       // pack each soil full first (--no-full: not)
  std::vector<Arrangement> rules = {Arrangement::discrete, Arrangement::layerwise};
  std::vector<double> targets;
};

// The command line; exits with status 2 and a message on a bad one.
Options parse_options(int argc, char** argv) {
  Options o;
  for (double t = 0.33; t < 0.4550; t += 0.01) o.targets.push_back(std::round(t * 100) / 100);
  auto fail = [](const std::string& what) {
    std::fprintf(stderr, "pack_range: %s\n", what.c_str());
    std::exit(2);
  };
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--side" && i + 1 < argc) o.side = std::atof(argv[++i]);
    else if (a == "--targets" && i + 1 < argc) o.targets = parse_list(argv[++i]);
    else if (a == "--seed" && i + 1 < argc) o.seed = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--layering" && i + 1 < argc) o.layering = std::atof(argv[++i]);
    else if (a == "--profile" && i + 1 < argc) o.profile = std::atoi(argv[++i]);
    else if (a == "--no-full") o.full = false;
    else if (a == "--rules" && i + 1 < argc) {
      o.rules.clear();
      std::stringstream ss(argv[++i]);
      std::string r;
      while (std::getline(ss, r, ','))
        if (r == "discrete") o.rules.push_back(Arrangement::discrete);
        else if (r == "layerwise") o.rules.push_back(Arrangement::layerwise);
        else fail("rule " + r + ": use discrete or layerwise");
    } else if (a.rfind("--", 0) == 0) {
      fail("usage: pack_range [psd-file ...] [--side S] [--targets a,b,...] "
           "[--seed K] [--rules discrete,layerwise] [--layering W] [--profile N] "
           "[--no-full]");
    } else o.psds.push_back(a);
  }
  if (o.psds.empty())
    for (const char* c : {"2.0", "2.5", "3.0", "3.5"})
      o.psds.push_back(std::string("input_scripts/psd/cu") + c + ".txt");
  if (!(o.side > 0) || o.targets.empty() || o.rules.empty() ||
      !(std::isnan(o.layering) || o.layering > 0) || o.profile < 0)
    fail("side must be > 0, targets and rules not empty, layering > 0, profile >= 0");
  return o;
}

// One row of the table: the specimen packed at `target`, measured.
bool print_row(const Summary& sm, const Run& r, double target, Arrangement a,
               int profile) {
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
  double assort_in = m.size_assortativity(m.interior(r.dmax));
  double loc_cu = m.mean_local_cu_ratio(3);
  double full = 1.0 - p.packed_volume / r.volume;
  std::string fails;
  if (!(placed >= 0.995)) fails += "P";
  if (!(std::fabs(achieved - target) <= 0.005)) fails += "A";
  if (!(lo >= target - 0.03 && hi <= target + 0.03)) fails += "S";
  if (!(std::fabs(interior - target) <= 0.01)) fails += "I";
  const bool ok = fails.empty();
  std::printf("%-6s %-9s %6.2f %8lld %8.2f %8.4f %7.4f %7.4f %8.4f %8.3f %7.3f %7.3f %7.3f %7.4f %7.1f %7s %-4s %6.3f %6.3f\n",
              sm.soil.c_str(), sm.rule.c_str(), target, r.listed,
              100.0 * placed, achieved, lo, hi, interior, spearman, assort,
              assort_in, loc_cu, full, r.seconds, ok ? "yes" : "no",
              fails.empty() ? "-" : fails.c_str(),
              a == Arrangement::layerwise ? r.layering : 0.0,
              max_share_error(p, r.list));
  if (profile > 0) print_profile(m, profile, r.dmax);
  std::fflush(stdout);
  return ok;
}

void print_summary(const std::vector<Summary>& summary) {
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
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse_options(argc, argv);
  std::printf("# side %.3g coarsest-interval diameters, 20 intervals, seed %llu, "
              "default start (discrete auto, layerwise floor); complete and uniform: placed >= 99.5 %%, "
              "|achieved - target| <= 0.005, 27 sub-cubes within 0.03, interior "
              "(layer 1 coarsest diameter) within 0.01\n",
              o.side, static_cast<unsigned long long>(o.seed));
  if (!std::isnan(o.layering)) std::printf("# layering %g\n", o.layering);
  std::printf("%-6s %-9s %6s %8s %8s %8s %7s %7s %8s %8s %7s %7s %7s %7s %7s %7s %-4s %6s %6s\n",
              "soil", "rule", "target", "listed", "placed%", "achieved",
              "sub_min", "sub_max", "interior", "spearman", "assort", "asrt_in",
              "loc_cu", "full", "seconds", "c&u", "fail", "width", "share");
  std::fflush(stdout);
  std::vector<Summary> summary;
  for (const std::string& path : o.psds) {
    auto psd = [&] {
      try {
        return ParticleSizeDistribution::read(path);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "pack_range: %s\n", e.what());
        std::exit(2);
      }
    }();
    auto intervals = psd.equal_mass_intervals(20);
    for (Arrangement a : o.rules) {
      Summary sm;
      sm.soil = base_name(path);
      sm.rule = to_string(a);
      if (o.full) {
        Run f = run(intervals, o.side, 0.25, a, o.seed, o.layering);
        sm.full = 1.0 - f.result.packed_volume / f.volume;
        std::printf("%-6s %-9s %6s %8lld %8.2f %8s %7s %7s %8s %8s %7s %7s %7s %7.4f %7.1f %7s %s\n",
                    sm.soil.c_str(), sm.rule.c_str(), "0.25", f.listed,
                    100.0 * f.result.placed() / f.listed, "-", "-", "-", "-",
                    "-", "-", "-", "-", sm.full, f.seconds, "-", "(packed full)");
        std::fflush(stdout);
      }
      for (double target : o.targets) {
        Run r = run(intervals, o.side, target, a, o.seed, o.layering);
        sm.tested.push_back(target);
        if (print_row(sm, r, target, a, o.profile)) sm.ok.push_back(target);
      }
      summary.push_back(sm);
    }
  }
  print_summary(summary);
  return 0;
}
