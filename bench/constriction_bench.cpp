// Cost of the constriction size distribution (compute constriction/size's
// core, constriction_network) on specimens of fix sequential/pack's packer:
// porosity 0.35, Cu 2.5 by default, discrete arrangement, N = 1e4, 1e5 and
// (max-N) 1e6 grains listed. A benchmark, not a test: it prints figures and
// checks nothing. Run from the repository root:
//   build/bench/constriction_bench [psd-file] [max-N]
// Per specimen: grains, pores, constrictions counted, seconds (wall and CPU)
// of the triangulation and constrictions, microseconds per grain, the peak
// resident memory that the CSD adds (VmHWM after resetting it with
// /proc/self/clear_refs, minus the resident set before), bytes per grain,
// and D_c35, D_c50 and the percolation opening against d50 of the PSD.
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <fstream>
#include <string>

#include "constriction_network.h"
#include "front_packer.h"
#include "psd.h"

using namespace fabric;

namespace {
// A field of /proc/self/status in kB (VmRSS, VmHWM); -1 if unreadable.
long status_kb(const std::string& field) {
  std::ifstream f("/proc/self/status");
  std::string key;
  while (f >> key) {
    if (key == field + ":") {
      long kb;
      f >> kb;
      return kb;
    }
    std::getline(f, key);
  }
  return -1;
}

void reset_peak() {  // Linux >= 4.0: VmHWM := VmRSS
  std::ofstream f("/proc/self/clear_refs");
  f << "5";
}
}  // namespace

int main(int argc, char** argv) {
  std::string path = argc > 1 ? argv[1] : "input_scripts/psd/cu2.5.txt";
  double max_n = argc > 2 ? std::atof(argv[2]) : 1e6;
  if (!(max_n >= 1e4) || path.rfind("-", 0) == 0) {
    std::fprintf(stderr, "usage: constriction_bench [psd-file] [max-N >= 1e4]\n");
    return 2;
  }
  ParticleSizeDistribution psd({{1.0, 0.0}, {2.0, 100.0}});
  try {
    psd = ParticleSizeDistribution::read(path);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "constriction_bench: %s\n", e.what());
    return 2;
  }
  auto intervals = psd.equal_mass_intervals(20);
  auto unit = particle_list(intervals, 1.0, 0.35);
  double per_volume = 0.0;
  for (double t : unit.target_count) per_volume += t;
  const double d50 = psd.diameter_at_percent(50.0);
  std::printf("# %s (Cu %.2f, d50 %.4g m), porosity 0.35, discrete, seed 1; "
              "merge coincident, wall margin one coarsest diameter\n",
              path.c_str(), psd.uniformity_coefficient(), d50);
  std::printf("%9s %9s %9s %9s %9s %9s %11s %10s %10s %8s %8s %8s\n", "grains",
              "pores", "counted", "on_edge", "seconds", "cpu_s", "us/grain",
              "peak_MiB", "B/grain", "Dc35/d50", "Dc50/d50", "perc/d50");
  std::fflush(stdout);
  for (double n = 1e4; n <= max_n * 1.001; n *= 10) {
    double L = std::cbrt(n / per_volume);
    auto list = particle_list(intervals, L * L * L, 0.35);
    PackingSpec spec = packing_spec(list, Vec3(0, 0, 0), Vec3(L, L, L));
    spec.arrangement = Arrangement::discrete;
    spec.start = default_start(spec.arrangement);
    spec.seed = 1;
    std::vector<Sphere> spheres;
    {
      PackingResult r = pack(spec);
      for (std::size_t i = 0; i < r.centre.size(); ++i)
        spheres.push_back({r.centre[i], r.radius[i]});
    }
    ConstrictionOptions o;
    o.container = Box{Vec3(0, 0, 0), Vec3(L, L, L)};
    long rss0 = status_kb("VmRSS");
    reset_peak();
    std::clock_t c0 = std::clock();
    auto t0 = std::chrono::steady_clock::now();
    ConstrictionNetwork net = constriction_network(spheres, o);
    auto p = csd_percentiles(net.discs, {35.0, 50.0}, false);
    double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
    long peak = status_kb("VmHWM") - rss0;
    double ng = double(spheres.size());
    std::printf("%9.0f %9ld %9zu %9ld %9.2f %9.2f %11.2f %10.1f %10.0f %8.3f %8.3f %8.3f\n",
                ng, net.pores, net.discs.size(), net.on_edge, wall, cpu,
                1e6 * cpu / ng, peak / 1024.0, 1024.0 * peak / ng, p[0] / d50,
                p[1] / d50, net.percolation_diameter / d50);
    std::fflush(stdout);
  }
  return 0;
}
