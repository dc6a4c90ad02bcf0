#include "pore_flow.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <deque>
#include <sstream>
#include <stdexcept>
#include <string>

#include "regular_triangulation.h"
#include "union_find.h"

namespace fabric {
namespace {

std::string str(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

void validate(const std::vector<Sphere>& spheres, const PoreFlowOptions& o) {
  if (spheres.size() < 4)
    throw std::invalid_argument("pore flow: " + std::to_string(spheres.size()) +
                                " spheres; a pore network needs at least 4");
  const Box& b = o.box;
  if (!(b.lo.allFinite() && b.hi.allFinite() && (b.hi - b.lo).minCoeff() > 0.0))
    throw std::invalid_argument("pore flow: the box is empty or not finite");
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const Sphere& s = spheres[i];
    if (!s.centre.allFinite() || !(s.radius > 0.0) || !std::isfinite(s.radius))
      throw std::invalid_argument(
          "pore flow: sphere " + std::to_string(i) + " has radius " +
          str(s.radius) + " or a centre that is not finite");
    if ((s.centre.array() <= b.lo.array()).any() ||
        (s.centre.array() >= b.hi.array()).any())
      throw std::invalid_argument("pore flow: sphere " + std::to_string(i) +
                                  " has its centre outside the box");
  }
  if (!(o.viscosity > 0.0) || !std::isfinite(o.viscosity))
    throw std::invalid_argument("pore flow: the viscosity " + str(o.viscosity) +
                                " Pa s must be positive and finite");
  const double dp = o.inflow_pressure - o.outflow_pressure;
  if (!(dp > 0.0) || !std::isfinite(dp))
    throw std::invalid_argument(
        "pore flow: the pressure drop (inflow - outflow) " + str(dp) +
        " Pa must be positive and finite");
  if (!(o.tolerance > 0.0 && o.tolerance < 1.0))
    throw std::invalid_argument("pore flow: the solver tolerance " +
                                str(o.tolerance) + " must lie in (0, 1)");
}

// Solid angle of the triangle (p, q, r) seen from o (van Oosterom and
// Strackee 1983); atan2 keeps angles above pi/2 right.
double solid_angle(const Vec3& o, const Vec3& p, const Vec3& q, const Vec3& r) {
  const Vec3 a = p - o, b = q - o, c = r - o;
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double num = std::abs(a.dot(b.cross(c)));
  const double den =
      la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return 2.0 * std::atan2(num, den);
}

double angle(const Vec3& u, const Vec3& v) {
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

PoreKind kind_of(const std::array<long, 4>& v, const RegularTriangulation& t) {
  int walls_on_axis[3] = {0, 0, 0};
  bool lo_z = false, hi_z = false;
  for (long id : v) {
    if (!t.is_wall(id)) continue;
    const int w = t.wall_of(id);
    ++walls_on_axis[wall_axis(w)];
    lo_z |= w == 4;
    hi_z |= w == 5;
  }
  if (*std::max_element(walls_on_axis, walls_on_axis + 3) > 1)
    return PoreKind::solid;
  if (lo_z) return PoreKind::inflow;
  if (hi_z) return PoreKind::outflow;
  return PoreKind::unknown;
}

// A face as the polygon its spheres span down to its walls: the sphere
// centres and their projections on the walls (FlowEngine's fictitious
// vertices). Empty when the face has no sphere or two opposite walls.
struct Polygon {
  std::vector<Vec3> corner;
  std::vector<long> sphere;  // -1: a point on a wall
};

Vec3 project(Vec3 p, int w, const Box& box) {
  p[wall_axis(w)] = wall_side(w) ? box.hi[wall_axis(w)] : box.lo[wall_axis(w)];
  return p;
}

Polygon face_polygon(const std::array<long, 3>& v, const RegularTriangulation& t,
                     const std::vector<Sphere>& s) {
  std::vector<long> real;
  std::vector<int> wall;
  for (long id : v) {
    if (t.is_wall(id)) wall.push_back(t.wall_of(id));
    else real.push_back(id);
  }
  Polygon p;
  const Box& box = *t.walls;
  if (wall.empty()) {
    for (long id : real) p.corner.push_back(s[id].centre), p.sphere.push_back(id);
  } else if (wall.size() == 1) {
    const Vec3 &a = s[real[0]].centre, &b = s[real[1]].centre;
    p.corner = {a, b, project(b, wall[0], box), project(a, wall[0], box)};
    p.sphere = {real[0], real[1], -1, -1};
  } else if (wall.size() == 2 && wall_axis(wall[0]) != wall_axis(wall[1])) {
    const Vec3& a = s[real[0]].centre;
    const Vec3 a1 = project(a, wall[0], box);
    p.corner = {a, a1, project(a1, wall[1], box), project(a, wall[1], box)};
    p.sphere = {real[0], -1, -1, -1};
  }
  return p;
}

// A point on the far side of vertex v from the box's inside: v's centre, or
// beyond its wall.
Vec3 vertex_point(long v, const RegularTriangulation& t,
                  const std::vector<Sphere>& s, const Vec3& near) {
  if (!t.is_wall(v)) return s[v].centre;
  const Box& box = *t.walls;
  const int w = t.wall_of(v), a = wall_axis(w);
  Vec3 p = near;
  const double size = (box.hi - box.lo).maxCoeff();
  p[a] = wall_side(w) ? box.hi[a] + size : box.lo[a] - size;
  return p;
}

}  // namespace

double throat_conductance(double fluid_area, double hydraulic_radius,
                          double length, double viscosity) {
  return fluid_area * hydraulic_radius * hydraulic_radius /
         (2.0 * viscosity * length);
}

ThroatGeometry throat_geometry(const std::vector<Vec3>& corner,
                               const std::vector<double>& radius,
                               const Vec3& a, const Vec3& b,
                               const Vec3& behind_a) {
  ThroatGeometry g;
  const std::size_t m = corner.size();
  Vec3 area = Vec3::Zero();  // Newell's area vector, about corner 0
  for (std::size_t k = 1; k + 1 < m; ++k)
    area += 0.5 * (corner[k] - corner[0]).cross(corner[k + 1] - corner[0]);
  g.area = area.norm();
  if (!(g.area > 0.0)) return g;
  g.normal = area / g.area;
  if (g.normal.dot(behind_a - corner[0]) > 0.0) g.normal = -g.normal;
  g.length = (a - b).norm();
  double sections = 0.0, solid = 0.0;
  for (std::size_t k = 0; k < m; ++k) {
    const Vec3 &prev = corner[(k + m - 1) % m], &next = corner[(k + 1) % m];
    const double r = radius[k];
    if (r <= 0.0) continue;
    // The sphere's section in the face: the sector of the corner's angle.
    g.section[k] = 0.5 * r * r * angle(prev - corner[k], next - corner[k]);
    sections += g.section[k];
    // Omega seen from the corner: the tetrahedra (corner, neighbour, a, b)
    // of the two polygon edges that meet there.
    const double omega = solid_angle(corner[k], prev, a, b) +
                         solid_angle(corner[k], next, a, b);
    g.wetted[k] = omega * r * r;
    g.wetted_surface += g.wetted[k];
    solid += omega * r * r * r / 3.0;
  }
  // Overlapping spheres can section more than the face (FlowEngine takes the
  // absolute value there); none is left for the fluid.
  g.fluid_area = std::max(0.0, g.area - sections);
  g.fluid_volume = std::max(0.0, std::abs(area.dot(a - b)) / 3.0 - solid);
  return g;
}

namespace {

// The network: cells as pores, faces as throats with their geometry. Cells
// whose orthocentres coincide (within 1e-6 of the face's largest radius, as
// the constrictions merge them) are one pore: a lattice's octahedron, or the
// packer's many local lattices of equal spheres, split into tetrahedra
// without a throat length between them. `pore` is each cell's pore, named by
// its first cell.
struct Network {
  RegularTriangulation t;
  std::vector<PoreKind> kind;  // per cell; a pore's is its first cell's
  std::vector<long> pore;
  long merged = 0;
  struct Throat {
    long a, b;  // cells; b = -1: a's face against a solid cell
    Polygon polygon;
    ThroatGeometry geometry;
    double conductance = 0.0;
  };
  std::vector<Throat> throats;
};

// As compute constriction/size's default (ConstrictionOptions).
constexpr double kCoincidentTolerance = 1e-6;
// A throat is at least this many hydraulic radii long (FlowEngine's
// distance correction, with a factor of its own): pore centres that nearly
// coincide, without merging, would give conductances a million times the
// others', which slowed conjugate gradients 3.4-fold on 1e4 grains (Cu 2.5)
// while this floor moves K by 0.03 % there.
constexpr double kMinLengthInHydraulicRadii = 0.1;

// Joins the cells with coincident orthocentres into pores; an imposed
// pressure on any of a pore's cells holds for the whole pore.
void merge_coincident(const std::vector<Sphere>& s, Network& net) {
  const RegularTriangulation& t = net.t;
  const long n = static_cast<long>(t.cell.size());
  UnionFind uf(n);
  for (const RegularTriangulation::Face& f : t.faces) {
    if (f.across < 0 || net.kind[f.cell] == PoreKind::solid ||
        net.kind[f.across] == PoreKind::solid)
      continue;
    if (same_pore(t, f.cell, f.across, f.vertex, s, kCoincidentTolerance))
      uf.join(f.cell, f.across);
  }
  net.pore.resize(n);
  for (long c = 0; c < n; ++c) {
    const long r = net.pore[c] = uf.find(c);
    if (r == c) continue;
    ++net.merged;
    if (net.kind[c] == PoreKind::inflow || net.kind[r] == PoreKind::unknown)
      net.kind[r] = net.kind[c];
  }
  for (long c = 0; c < n; ++c) net.kind[c] = net.kind[net.pore[c]];
}

Network build_network(const std::vector<Sphere>& s, const PoreFlowOptions& o) {
  Network net;
  net.t = regular_triangulation(s, o.box);
  const RegularTriangulation& t = net.t;
  net.kind.reserve(t.cell.size());
  for (const auto& c : t.cell) net.kind.push_back(kind_of(c, t));
  merge_coincident(s, net);
  for (const RegularTriangulation::Face& f : t.faces) {
    long a = f.cell, b = f.across;
    const bool pa = net.kind[a] != PoreKind::solid;
    const bool pb = b >= 0 && net.kind[b] != PoreKind::solid;
    if ((!pa && !pb) || (pa && pb && net.pore[a] == net.pore[b])) continue;
    Polygon poly = face_polygon(f.vertex, t, s);
    if (poly.corner.size() < 3) continue;
    Vec3 mid = Vec3::Zero();
    for (const Vec3& c : poly.corner) mid += c;
    mid /= static_cast<double>(poly.corner.size());
    Vec3 behind = vertex_point(f.opposite, t, s, mid);
    if (!pa) {  // seen from b, the only pore
      std::swap(a, b);
      behind = 2.0 * mid - behind;
    }
    std::vector<double> r;
    for (long id : poly.sphere) r.push_back(id >= 0 ? s[id].radius : 0.0);
    Network::Throat th{a, pa && pb ? b : -1, std::move(poly), {}, 0.0};
    th.geometry = throat_geometry(th.polygon.corner, r, t.orthocentre[a],
                                  th.b >= 0 ? t.orthocentre[th.b] : mid, behind);
    if (th.b >= 0)
      th.conductance = throat_conductance(
          th.geometry.fluid_area, th.geometry.hydraulic_radius(),
          std::max(th.geometry.length,
                   kMinLengthInHydraulicRadii * th.geometry.hydraulic_radius()),
          o.viscosity);
    net.throats.push_back(std::move(th));
  }
  return net;
}

double imposed_pressure(PoreKind k, const PoreFlowOptions& o) {
  return k == PoreKind::inflow ? o.inflow_pressure : o.outflow_pressure;
}

// Unknown pores that open throats join to a pore of imposed pressure; the
// others would make the system singular.
std::vector<char> reached(const Network& net) {
  const long n = static_cast<long>(net.kind.size());
  std::vector<std::vector<long>> next(n);
  for (const Network::Throat& th : net.throats)
    if (th.b >= 0 && th.conductance > 0.0) {
      const long a = net.pore[th.a], b = net.pore[th.b];
      next[a].push_back(b), next[b].push_back(a);
    }
  std::vector<char> seen(n, 0);
  std::deque<long> queue;
  for (long c = 0; c < n; ++c)
    if (net.pore[c] == c && (net.kind[c] == PoreKind::inflow ||
                             net.kind[c] == PoreKind::outflow))
      seen[c] = 1, queue.push_back(c);
  while (!queue.empty()) {
    long c = queue.front();
    queue.pop_front();
    for (long d : next[c])
      if (!seen[d] && net.kind[d] == PoreKind::unknown)
        seen[d] = 1, queue.push_back(d);
  }
  return seen;
}

// Conjugate gradients on the symmetric positive definite system; the
// diagonal preconditioner is robust where the conductances span many orders
// of magnitude (incomplete Cholesky broke down on such systems) and needs no
// fill-in at 1e5 grains.
Eigen::VectorXd solve(const std::vector<Eigen::Triplet<double>>& entries,
                      const Eigen::VectorXd& rhs, const PoreFlowOptions& o,
                      PoreFlow& out) {
  const long rows = rhs.size();
  Eigen::SparseMatrix<double> A(rows, rows);
  A.setFromTriplets(entries.begin(), entries.end());
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>,
                           Eigen::Lower | Eigen::Upper,
                           Eigen::DiagonalPreconditioner<double>>
      cg;
  cg.setTolerance(o.tolerance);
  cg.setMaxIterations(static_cast<int>(std::min<long>(10 * rows, 1000000)));
  cg.compute(A);
  const double mean = 0.5 * (o.inflow_pressure + o.outflow_pressure);
  Eigen::VectorXd x =
      cg.solveWithGuess(rhs, Eigen::VectorXd::Constant(rows, mean));
  out.iterations = static_cast<int>(cg.iterations());
  out.solver_error = cg.error();
  if (cg.info() != Eigen::Success)
    throw std::runtime_error("pore flow: conjugate gradients stopped at a "
                             "relative residual of " + str(cg.error()) +
                             " after " + str(cg.iterations()) + " iterations");
  return x;
}

// The mass balance of every reached unknown pore, sum_j g_ij (p_i - p_j) = 0,
// solved by conjugate gradients with an incomplete Cholesky preconditioner
// (the system is symmetric positive definite; a direct factorisation fills
// in too much at 1e5 grains).
void solve_pressures(const Network& net, const PoreFlowOptions& o,
                     PoreFlow& out) {
  const long n = static_cast<long>(net.kind.size());
  const std::vector<char> seen = reached(net);
  const double mean = 0.5 * (o.inflow_pressure + o.outflow_pressure);
  std::vector<long> row(n, -1);
  long rows = 0;
  out.pressure.assign(n, mean);
  for (long c = 0; c < n; ++c) {
    if (net.pore[c] != c) continue;  // a pore is solved at its first cell
    if (net.kind[c] == PoreKind::unknown && seen[c]) row[c] = rows++;
    else if (net.kind[c] == PoreKind::unknown) ++out.isolated;
    else if (net.kind[c] != PoreKind::solid)
      out.pressure[c] = imposed_pressure(net.kind[c], o);
  }
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(rows);
  for (const Network::Throat& th : net.throats) {
    if (th.b < 0 || !(th.conductance > 0.0)) continue;
    const long a = net.pore[th.a], b = net.pore[th.b];
    const long ra = row[a], rb = row[b];
    const double g = th.conductance;
    if (ra >= 0) entries.emplace_back(ra, ra, g);
    if (rb >= 0) entries.emplace_back(rb, rb, g);
    if (ra >= 0 && rb >= 0) {
      entries.emplace_back(ra, rb, -g), entries.emplace_back(rb, ra, -g);
    } else if (ra >= 0 && net.kind[b] != PoreKind::unknown) {
      rhs[ra] += g * out.pressure[b];
    } else if (rb >= 0 && net.kind[a] != PoreKind::unknown) {
      rhs[rb] += g * out.pressure[a];
    }
  }
  Eigen::VectorXd x = rows > 0 ? solve(entries, rhs, o, out) : Eigen::VectorXd();
  for (long c = 0; c < n; ++c) {
    const long r = net.pore[c];
    out.pressure[c] = row[r] >= 0 ? x[row[r]] : out.pressure[r];
  }
}
// Fluxes, the inflow and outflow, and the forces on the spheres.
void fluxes_and_forces(const Network& net, PoreFlow& out) {
  out.force.assign(net.t.spheres, Vec3::Zero());
  out.viscous_force.assign(net.t.spheres, Vec3::Zero());
  std::vector<double> section(net.t.spheres, 0.0);
  out.grain_pressure.assign(net.t.spheres, 0.0);
  for (const Network::Throat& th : net.throats) {
    const ThroatGeometry& g = th.geometry;
    const Polygon& poly = th.polygon;
    const double pa = out.pressure[th.a];
    const double dp = th.b >= 0 ? pa - out.pressure[th.b] : pa;
    const double face_p = th.b >= 0 ? 0.5 * (pa + out.pressure[th.b]) : pa;
    for (std::size_t k = 0; k < poly.sphere.size(); ++k)
      if (poly.sphere[k] >= 0) {
        out.force[poly.sphere[k]] += dp * g.section[k] * g.normal;
        out.grain_pressure[poly.sphere[k]] += face_p * g.section[k];
        section[poly.sphere[k]] += g.section[k];
      }
    if (th.b < 0) continue;
    const double q = th.conductance * dp;
    out.throats.push_back({th.a, th.b, th.conductance, q});
    const PoreKind ka = net.kind[th.a], kb = net.kind[th.b];
    if (ka == PoreKind::inflow && kb != PoreKind::inflow) out.inflow += q;
    if (kb == PoreKind::inflow && ka != PoreKind::inflow) out.inflow -= q;
    if (kb == PoreKind::outflow && ka != PoreKind::outflow) out.outflow += q;
    if (ka == PoreKind::outflow && kb != PoreKind::outflow) out.outflow -= q;
    if (!(g.wetted_surface > 0.0)) continue;
    const Vec3 drag = dp * g.fluid_area * g.normal;
    for (std::size_t k = 0; k < poly.sphere.size(); ++k)
      if (poly.sphere[k] >= 0)
        out.viscous_force[poly.sphere[k]] += g.wetted[k] / g.wetted_surface * drag;
  }
  for (long i = 0; i < net.t.spheres; ++i) {
    out.force[i] += out.viscous_force[i];
    if (section[i] > 0.0) out.grain_pressure[i] /= section[i];
  }
}

}  // namespace

PoreFlow pore_flow(const std::vector<Sphere>& spheres,
                   const PoreFlowOptions& o) {
  validate(spheres, o);
  Network net = build_network(spheres, o);
  PoreFlow out;
  out.merged = net.merged;
  out.kind = net.kind;
  out.pore = net.pore;
  out.centre = net.t.orthocentre;
  for (long c = 0; c < static_cast<long>(net.kind.size()); ++c)
    out.pores += net.pore[c] == c && net.kind[c] != PoreKind::solid;
  solve_pressures(net, o, out);
  fluxes_and_forces(net, out);
  const Vec3 size = o.box.hi - o.box.lo;
  out.cross_section = size.x() * size.y();
  out.length = size.z();
  out.permeability = out.outflow * o.viscosity * out.length /
                     (out.cross_section * (o.inflow_pressure - o.outflow_pressure));
  return out;
}

}  // namespace fabric
