// The pore-scale flow (core/pore_flow.h) on specimens of fix sequential/pack's
// packer. A benchmark, not a test: it prints figures and checks nothing.
//
//   pore_flow_bench time [max-N] [psd-file]
//       Cu 2.5 (or the PSD given) at porosity 0.35, DA, seed 1, N = 1e4, 1e5
//       .. max-N (default 1e5) grains: the packer's seconds against the flow's
//       (triangulation, network, solve) and the triangulation's alone (with
//       the walls, timed apart), pores, iterations, K against Kozeny-Carman
//       with the Sauter diameter.
//   pore_flow_bench export side porosity seed FILE [psd-file]
//       equal spheres of 1 mm in a cube of `side` diameters, or the PSD's
//       grains in a cube of `side` d50: FILE gets the box (first line: x0 y0
//       z0 x1 y1 z1) and one sphere a line (x y z r).
//   pore_flow_bench solve FILE p_in p_out viscosity CELLS FORCES
//       the flow on FILE's spheres: prints the permeability and the flows,
//       writes each cell (x y z pressure kind pore) and each sphere's force.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>

#include "front_packer.h"
#include "pore_flow.h"
#include "psd.h"
#include "regular_triangulation.h"

using namespace fabric;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t)
      .count();
}

std::vector<Sphere> spheres_of(const PackingResult& r) {
  std::vector<Sphere> s;
  for (std::size_t i = 0; i < r.centre.size(); ++i)
    s.push_back({r.centre[i], r.radius[i]});
  return s;
}

int time_flow(double max_n, const std::string& psd_path) {
  const auto psd = ParticleSizeDistribution::read(psd_path);
  const auto intervals = psd.equal_mass_intervals(20);
  const auto unit = particle_list(intervals, 1.0, 0.35);
  double per_volume = 0.0;
  for (double t : unit.target_count) per_volume += t;
  std::printf("# %s (Cu %.2f), porosity 0.35, discrete, seed 1; water, "
              "1 Pa across the height\n",
              psd_path.c_str(), psd.uniformity_coefficient());
  std::printf("%9s %9s %8s %8s %8s %9s %7s %10s %9s\n", "grains", "pores",
              "pack_s", "flow_s", "tri_s", "flow/pack", "cg_its", "K_m2", "K/K_KC");
  for (double n = 1e4; n <= max_n * 1.001; n *= 10) {
    const double L = std::cbrt(n / per_volume);
    PackingSpec spec = packing_spec(particle_list(intervals, L * L * L, 0.35),
                                    Vec3::Zero(), Vec3::Constant(L));
    spec.start = default_start(spec.arrangement);
    auto t0 = std::chrono::steady_clock::now();
    const std::vector<Sphere> s = spheres_of(pack(spec));
    const double pack_s = seconds_since(t0);
    PoreFlowOptions o;
    o.box = Box{spec.lo, spec.hi};
    t0 = std::chrono::steady_clock::now();
    const PoreFlow f = pore_flow(s, o);
    const double flow_s = seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    regular_triangulation(s, o.box);
    const double tri_s = seconds_since(t0);
    // Kozeny-Carman with the Sauter mean diameter (volume / surface) of the
    // grains, the usual choice for a graded soil.
    double v = 0.0, a = 0.0;
    for (const Sphere& x : s) v += std::pow(x.radius, 3), a += x.radius * x.radius;
    const double d32 = 2.0 * v / a, por = 1.0 - 4.0 / 3.0 * M_PI * v / (L * L * L);
    const double kc = d32 * d32 * std::pow(por, 3) / (180.0 * std::pow(1.0 - por, 2));
    std::printf("%9zu %9ld %8.2f %8.2f %8.2f %9.2f %7d %10.3e %9.3f\n", s.size(),
                f.pores, pack_s, flow_s, tri_s, flow_s / pack_s, f.iterations,
                f.permeability, f.permeability / kc);
    std::fflush(stdout);
  }
  return 0;
}

// Equal spheres of 1 mm (psd_path empty) or the PSD's grains (20 intervals).
PackingSpec export_spec(double side, double porosity, const std::string& psd_path) {
  if (!psd_path.empty()) {
    const auto psd = ParticleSizeDistribution::read(psd_path);
    const double L = side * psd.diameter_at_percent(50.0);
    return packing_spec(particle_list(psd.equal_mass_intervals(20), L * L * L,
                                      porosity),
                        Vec3::Zero(), Vec3::Constant(L));
  }
  const double d = 1e-3, r = d / 2.0, L = side * d;
  PackingSpec spec;
  spec.lo = Vec3::Zero();
  spec.hi = Vec3::Constant(L);
  spec.radius = {r};
  spec.count = {std::llround((1.0 - porosity) * L * L * L /
                             (4.0 / 3.0 * M_PI * r * r * r))};
  return spec;
}

int export_spheres(double side, double porosity, unsigned seed,
                   const std::string& path, const std::string& psd_path) {
  PackingSpec spec = export_spec(side, porosity, psd_path);
  spec.start = default_start(spec.arrangement);
  spec.seed = seed;
  const std::vector<Sphere> s = spheres_of(pack(spec));
  std::ofstream out(path);
  out.precision(17);
  const double L = spec.hi.x();
  out << 0 << ' ' << 0 << ' ' << 0 << ' ' << L << ' ' << L << ' ' << L << '\n';
  double solid = 0.0;
  for (const Sphere& x : s) {
    out << x.centre.x() << ' ' << x.centre.y() << ' ' << x.centre.z() << ' '
        << x.radius << '\n';
    solid += 4.0 / 3.0 * M_PI * std::pow(x.radius, 3);
  }
  std::printf("%zu spheres, porosity %.4f\n", s.size(), 1.0 - solid / (L * L * L));
  return 0;
}

int solve_file(char** argv) {
  std::ifstream in(argv[2]);
  PoreFlowOptions o;
  in >> o.box.lo.x() >> o.box.lo.y() >> o.box.lo.z() >> o.box.hi.x() >>
      o.box.hi.y() >> o.box.hi.z();
  std::vector<Sphere> s;
  Sphere x;
  while (in >> x.centre.x() >> x.centre.y() >> x.centre.z() >> x.radius)
    s.push_back(x);
  o.inflow_pressure = std::atof(argv[3]);
  o.outflow_pressure = std::atof(argv[4]);
  o.viscosity = std::atof(argv[5]);
  const PoreFlow f = pore_flow(s, o);
  std::printf("spheres %zu pores %ld merged %ld inflow %.9e outflow %.9e "
              "permeability %.9e\n",
              s.size(), f.pores, f.merged, f.inflow, f.outflow, f.permeability);
  std::ofstream cells(argv[6]);
  cells.precision(12);
  for (std::size_t c = 0; c < f.pressure.size(); ++c)
    cells << f.centre[c].x() << ' ' << f.centre[c].y() << ' ' << f.centre[c].z()
          << ' ' << f.pressure[c] << ' ' << static_cast<int>(f.kind[c]) << ' '
          << f.pore[c] << '\n';
  std::ofstream forces(argv[7]);
  forces.precision(12);
  for (const Vec3& F : f.force)
    forces << F.x() << ' ' << F.y() << ' ' << F.z() << '\n';
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "time";
  try {
    if (mode == "time")
      return time_flow(argc > 2 ? std::atof(argv[2]) : 1e5,
                       argc > 3 ? argv[3] : "input_scripts/psd/cu2.5.txt");
    if (mode == "export" && (argc == 6 || argc == 7))
      return export_spheres(std::atof(argv[2]), std::atof(argv[3]),
                            static_cast<unsigned>(std::atoi(argv[4])), argv[5],
                            argc == 7 ? argv[6] : "");
    if (mode == "solve" && argc == 8) return solve_file(argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pore_flow_bench: %s\n", e.what());
    return 2;
  }
  std::fprintf(stderr,
               "usage: pore_flow_bench time [max-N] [psd-file]\n"
               "       pore_flow_bench export side porosity seed FILE [psd-file]\n"
               "       pore_flow_bench solve FILE p_in p_out viscosity CELLS "
               "FORCES\n");
  return 2;
}
