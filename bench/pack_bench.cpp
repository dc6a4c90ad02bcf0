// Packing throughput: particles per second, time per particle and peak
// memory for N = 1e3 .. 1e6 (Cu = 2.5, both arrangements). A benchmark, not
// a test: it prints figures. Run from the repository root:
//   build/bench/pack_bench [psd-file] [max-N]
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "front_packer.h"
#include "psd.h"

using namespace fabric;

int main(int argc, char** argv) {
  std::string path = argc > 1 ? argv[1] : "input_scripts/psd/cu2.5.txt";
  double max_n = argc > 2 ? std::atof(argv[2]) : 1e6;
  auto psd = ParticleSizeDistribution::read(path);
  auto intervals = psd.equal_mass_intervals(20);
  const double porosity = 0.42;
  // Particles per unit volume at this porosity, to size the container.
  auto unit = particle_list(intervals, 1.0, porosity);
  double per_volume = 0.0;
  for (double t : unit.target_count) per_volume += t;
  std::printf("# %s, porosity %.2f, 20 intervals\n", path.c_str(), porosity);
  std::printf("%-10s %9s %9s %8s %12s %10s %10s %9s\n", "rule", "N", "placed",
              "seconds", "particles/s", "us/particle", "B/particle", "porosity");
  for (double n = 1e3; n <= max_n * 1.001; n *= 10) {
    for (Arrangement a : {Arrangement::discrete, Arrangement::layerwise}) {
      double L = std::cbrt(n / per_volume);
      auto list = particle_list(intervals, L * L * L, porosity);
      PackingSpec spec;
      spec.lo = Vec3(0, 0, 0);
      spec.hi = Vec3(L, L, L);
      for (size_t k = 0; k < intervals.size(); ++k) {
        spec.radius.push_back(0.5 * list.diameter[k]);
        spec.count.push_back(list.count[k]);
      }
      spec.arrangement = a;
      auto t0 = std::chrono::steady_clock::now();
      PackingResult r = pack(spec);
      double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      double vol = 0.0;
      for (double rr : r.radius) vol += 4.0 / 3.0 * M_PI * rr * rr * rr;
      std::printf("%-10s %9lld %9lld %8.3f %12.0f %10.2f %10.0f %9.4f\n",
                  to_string(a).c_str(), list.total(), r.placed(), s,
                  r.placed() / s, 1e6 * s / r.placed(),
                  double(r.peak_bytes) / r.placed(), 1.0 - vol / (L * L * L));
    }
  }
  struct rusage u;
  getrusage(RUSAGE_SELF, &u);
  std::printf("# peak resident set of the whole run: %.1f MiB\n", u.ru_maxrss / 1024.0);
  return 0;
}
