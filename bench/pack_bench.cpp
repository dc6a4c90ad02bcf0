// Packing throughput in the paper's setting: porosity 0.35, Cu = 2.5 by
// default, both arrangements, N = 1e4, 1e5, 1e6 grains listed. A benchmark,
// not a test: it prints figures and checks nothing. Run from the repository
// root:
//   build/bench/pack_bench [psd-file] [max-N]
// (defaults input_scripts/psd/cu2.5.txt and 1e6). Per run it prints the
// grains listed, placed and unplaced, the time, particles per second and
// microseconds per particle (placed), the packer's peak data per placed
// particle, the achieved porosity and the porosity of the container packed
// full (1 - packed_volume / V, vacancies included), the lowest porosity the
// packing reaches in that container, and the sites opened and grains offered
// to a site per grain placed (sites/p, tries/p: the work, in counts).
// `seconds` is wall time, `cpu_s` the process's CPU time; the rates are
// from CPU time, so that other jobs on the machine slow them less (the
// packer is serial, so on an idle machine the two agree).
#include <sys/resource.h>

#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "front_packer.h"
#include "psd.h"

using namespace fabric;

int main(int argc, char** argv) {
  std::string path = argc > 1 ? argv[1] : "input_scripts/psd/cu2.5.txt";
  double max_n = argc > 2 ? std::atof(argv[2]) : 1e6;
  if (!(max_n >= 1e4) || path.rfind("-", 0) == 0) {
    std::fprintf(stderr, "usage: pack_bench [psd-file] [max-N >= 1e4]\n");
    return 2;
  }
  auto psd = [&] {
    try {
      return ParticleSizeDistribution::read(path);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "pack_bench: %s\n", e.what());
      std::exit(2);
    }
  }();
  auto intervals = psd.equal_mass_intervals(20);
  const double porosity = 0.35;
  // Particles per unit volume at this porosity, to size the container.
  auto unit = particle_list(intervals, 1.0, porosity);
  double per_volume = 0.0;
  for (double t : unit.target_count) per_volume += t;
  std::printf("# %s (Cu %.2f), porosity %.2f, 20 intervals, seed 1, default start (DA auto, LA floor)\n",
              path.c_str(), psd.uniformity_coefficient(), porosity);
  std::printf("%-10s %9s %9s %8s %9s %9s %12s %11s %10s %9s %9s %7s %7s\n", "rule",
              "N", "placed", "unplaced", "seconds", "cpu_s", "particles/s",
              "us/particle", "B/particle", "porosity", "full", "sites/p",
              "tries/p");
  std::fflush(stdout);
  for (double n = 1e4; n <= max_n * 1.001; n *= 10) {
    for (Arrangement a : {Arrangement::discrete, Arrangement::layerwise}) {
      double L = std::cbrt(n / per_volume);
      double V = L * L * L;
      auto list = particle_list(intervals, V, porosity);
      PackingSpec spec = packing_spec(list, Vec3(0, 0, 0), Vec3(L, L, L));
      spec.arrangement = a;
      spec.start = default_start(a);  // as fix sequential/pack does
      spec.seed = 1;
      std::clock_t c0 = std::clock();
      auto t0 = std::chrono::steady_clock::now();
      PackingResult r = pack(spec);
      double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      double s = double(std::clock() - c0) / CLOCKS_PER_SEC;
      double vol = 0.0;
      for (double rr : r.radius) vol += sphere_volume(2.0 * rr);
      std::printf("%-10s %9lld %9lld %8lld %9.3f %9.3f %12.0f %11.2f %10.0f %9.4f %9.4f %7.1f %7.1f\n",
                  to_string(a).c_str(), list.total(), r.placed(), r.unplaced(), wall, s,
                  r.placed() / s, 1e6 * s / r.placed(),
                  double(r.peak_bytes) / r.placed(), 1.0 - vol / V,
                  1.0 - r.packed_volume / V, double(r.sites) / r.placed(),
                  double(r.attempts) / r.placed());
      std::fflush(stdout);
    }
  }
  struct rusage u;
  getrusage(RUSAGE_SELF, &u);
  std::printf("# peak resident set of the whole run: %.1f MiB\n", u.ru_maxrss / 1024.0);
  return 0;
}
