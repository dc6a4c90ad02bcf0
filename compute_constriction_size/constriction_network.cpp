#include "constriction_network.h"

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "regular_triangulation.h"
#include "union_find.h"

namespace fabric {
namespace {

// The pores: sets of tetrahedra.
using Pores = UnionFind;

void validate(const std::vector<Sphere>& spheres,
              const ConstrictionOptions& o) {
  if (spheres.size() < 4)
    throw std::invalid_argument(
        "the group has " + std::to_string(spheres.size()) +
        " grains; a constriction network needs at least 4");
  for (const Sphere& s : spheres)
    if (!s.centre.allFinite() || !(s.radius > 0.0) || !std::isfinite(s.radius))
      throw std::invalid_argument(
          "a grain has a non-finite position or a radius " +
          std::to_string(s.radius) + " that is not positive and finite");
  if (!(o.coincident_tolerance >= 0.0 && o.coincident_tolerance < 1.0))
    throw std::invalid_argument("the coincidence tolerance " +
                                std::to_string(o.coincident_tolerance) +
                                " must lie in [0, 1)");
  if (!std::isfinite(o.wall_margin))
    throw std::invalid_argument("the wall margin must be finite");
  if (o.container && !((o.container->hi - o.container->lo).array() > 0).all())
    throw std::invalid_argument("the container box is empty");
}

bool near_wall(const Vec3& p, const Box& b, double m, bool sides_only) {
  for (int a = 0; a < (sides_only ? 2 : 3); ++a)
    if (p[a] < b.lo[a] + m || p[a] > b.hi[a] - m) return true;
  return false;
}

// One face between two tetrahedra: its three spheres and the two cells.
struct Face {
  std::array<long, 3> sphere;
  long cell_a, cell_b;
};

template <class F>
void for_each_inner_face(const RegularTriangulation& t, F&& f) {
  for (const RegularTriangulation::Face& tf : t.faces) {
    // on the convex hull: no pore pair
    if (tf.across < 0) continue;
    Face face;
    face.sphere = tf.vertex;
    std::sort(face.sphere.begin(), face.sphere.end());
    face.cell_a = std::min(tf.cell, tf.across);
    face.cell_b = std::max(tf.cell, tf.across);
    f(face);
  }
}

void merge_pores(const RegularTriangulation& t, const std::vector<Sphere>& s,
                 const ConstrictionOptions& o, Pores& pores) {
  std::vector<std::optional<Sphere>> inscribed;
  if (o.merging == PoreMerging::overlap) {
    inscribed.reserve(t.cell.size());
    for (const auto& c : t.cell)
      inscribed.push_back(
          inscribed_pore_sphere({s[c[0]], s[c[1]], s[c[2]], s[c[3]]}));
  }
  for_each_inner_face(t, [&](const Face& f) {
    bool join = same_pore(t, f.cell_a, f.cell_b, f.sphere, s,
                          o.coincident_tolerance);
    if (!join && !inscribed.empty()) {
      const auto& p = inscribed[f.cell_a];
      const auto& q = inscribed[f.cell_b];
      join = p && q && (p->centre - q->centre).norm() < p->radius + q->radius;
    }
    if (join) pores.join(f.cell_a, f.cell_b);
  });
}

// Openings between two pores made of several faces: coplanar faces are one
// opening, represented by the largest circle.
struct Opening {
  Vec3 point, normal;
  std::optional<ConstrictionDisc> disc;
};

void add_to_openings(std::vector<Opening>& list, const Vec3& centroid,
                     const Vec3& normal, double scale,
                     const std::optional<ConstrictionDisc>& disc) {
  for (Opening& o : list) {
    if (std::abs(o.normal.dot(normal)) < 1.0 - 1e-9) continue;
    if (std::abs((centroid - o.point).dot(o.normal)) > 1e-9 * scale) continue;
    if (disc && (!o.disc || disc->radius > o.disc->radius)) o.disc = disc;
    return;
  }
  list.push_back({centroid, normal, disc});
}

// Largest bottleneck of a path from a floor pore to a lid pore: edges in
// decreasing diameter join pores until floor and lid are connected.
double percolation(long npores, std::vector<std::pair<double, std::pair<long, long>>> edges,
                   const std::vector<char>& floor, const std::vector<char>& lid) {
  Pores uf(npores + 2);  // npores: the floor, npores + 1: the lid
  for (long p = 0; p < npores; ++p) {
    if (floor[p]) uf.join(p, npores);
    if (lid[p]) uf.join(p, npores + 1);
  }
  if (uf.find(npores) == uf.find(npores + 1)) return INFINITY;
  std::sort(edges.begin(), edges.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  for (const auto& e : edges) {
    uf.join(e.second.first, e.second.second);
    if (uf.find(npores) == uf.find(npores + 1)) return e.first;
  }
  return 0.0;
}

// The pores behind the convex hull's bottom (outward normal within 45
// degrees of -z) and top faces: where a path from the floor to the lid
// starts and ends.
void mark_floor_and_lid(const RegularTriangulation& t,
                        const std::vector<Sphere>& s,
                        const std::vector<long>& pore_of,
                        std::vector<char>& floor, std::vector<char>& lid) {
  for (const RegularTriangulation::Face& f : t.faces) {
    if (f.across >= 0) continue;
    const Vec3 p[3] = {s[f.vertex[0]].centre, s[f.vertex[1]].centre,
                       s[f.vertex[2]].centre};
    Vec3 n = (p[1] - p[0]).cross(p[2] - p[0]);
    if (n.dot(s[f.opposite].centre - p[0]) > 0.0) n = -n;
    double nz = n.z() / n.norm();
    if (nz < -std::sqrt(0.5)) floor[pore_of[f.cell]] = 1;
    if (nz > std::sqrt(0.5)) lid[pore_of[f.cell]] = 1;
  }
}

struct FaceResult {
  Vec3 centroid, normal;
  double scale;
  std::optional<ConstrictionDisc> disc;
  bool degenerate;
};

// Largest empty circle centred on the segment a-b of the face plane (2-D
// frame coordinates), beside the discs a, b and c: where the gaps to two of
// them are equal along the segment. Radius 0 if none is positive.
double edge_circle(const Eigen::Vector2d& a, double ra, const Eigen::Vector2d& b,
                   double rb, const Eigen::Vector2d& c, double rc,
                   Eigen::Vector2d& centre) {
  const Eigen::Vector2d e = b - a;
  const double d = e.norm();
  auto gap = [&](double t) {  // t: distance from a along the segment
    Eigen::Vector2d p = a + t / d * e;
    return std::min({t - ra, d - t - rb, (p - c).norm() - rc});
  };
  std::vector<double> ts = {(d + ra - rb) / 2.0};  // equal gaps to a and b
  // Equal gaps to a (or b) and c: t + delta = |p - c| is linear in t.
  for (int end = 0; end < 2; ++end) {
    const Eigen::Vector2d& o = end ? b : a;
    const double ro = end ? rb : ra;
    Eigen::Vector2d u = (end ? -e : e) / d, w = c - o;
    double xk = w.dot(u), delta = rc - ro;
    double den = 2.0 * (delta + xk);
    if (den == 0.0) continue;
    double t = (w.squaredNorm() - delta * delta) / den;
    if (t + delta >= 0.0) ts.push_back(end ? d - t : t);
  }
  double best = 0.0;
  for (double t : ts) {
    if (!(t >= 0.0 && t <= d)) continue;
    double g = gap(t);
    if (g > best) best = g, centre = a + t / d * e;
  }
  return best;
}

FaceResult solve_face(const Face& f, const std::vector<Sphere>& s) {
  const Sphere& a = s[f.sphere[0]];
  const Sphere& b = s[f.sphere[1]];
  const Sphere& c = s[f.sphere[2]];
  FaceResult r{(a.centre + b.centre + c.centre) / 3.0, Vec3::Zero(),
               std::max({a.radius, b.radius, c.radius}), std::nullopt, false};
  auto frame = face_frame(a.centre, b.centre, c.centre);
  if (!frame) {
    r.degenerate = true;
    return r;
  }
  r.normal = frame->normal;
  if (auto k = constriction(*frame, a.radius, b.radius, c.radius)) {
    r.disc = ConstrictionDisc{k->centre, frame->normal, k->radius, false,
                              r.centroid};
    return r;
  }
  // Eq. (2) has no circle inside the triangle: the narrowest passage of the
  // face then lies on one of its edges.
  const Eigen::Vector2d p[3] = {{0.0, 0.0}, {frame->x2, 0.0},
                                {frame->x3, frame->y3}};
  const double rr[3] = {a.radius, b.radius, c.radius};
  double best = 0.0;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (int i = 0; i < 3; ++i) {
    int j = (i + 1) % 3, k = (i + 2) % 3;
    Eigen::Vector2d q = Eigen::Vector2d::Zero();
    double g = edge_circle(p[i], rr[i], p[j], rr[j], p[k], rr[k], q);
    if (g > best) best = g, centre = q;
  }
  if (best > 0.0)
    r.disc = ConstrictionDisc{frame->to_global(centre.x(), centre.y(), 0.0),
                              frame->normal, best, true, r.centroid};
  return r;
}

}  // namespace

std::optional<Sphere> inscribed_pore_sphere(const std::array<Sphere, 4>& s) {
  // |x - c_i|^2 = (r_i + rho)^2; lines i minus line 0 are linear in x, rho.
  Eigen::Matrix3d m;
  Vec3 rhs, g;
  const Vec3& c0 = s[0].centre;
  const double r0 = s[0].radius;
  for (int i = 1; i < 4; ++i) {
    const Vec3& ci = s[i].centre;
    const double ri = s[i].radius;
    m.row(i - 1) = 2.0 * (ci - c0).transpose();
    rhs[i - 1] = ci.squaredNorm() - c0.squaredNorm() - ri * ri + r0 * r0;
    g[i - 1] = -2.0 * (ri - r0);
  }
  Eigen::FullPivLU<Eigen::Matrix3d> lu(m);
  if (!lu.isInvertible()) return std::nullopt;
  Vec3 u = lu.solve(rhs), v = lu.solve(g);  // x = u + rho v
  Vec3 w = u - c0;
  double A = v.squaredNorm() - 1.0, B = 2.0 * (w.dot(v) - r0),
         C = w.squaredNorm() - r0 * r0;
  double rho = -1.0;
  if (std::abs(A) < 1e-14) {
    if (B != 0.0) rho = -C / B;
  } else {
    double disc = B * B - 4.0 * A * C;
    if (disc < 0.0) return std::nullopt;
    double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
    double roots[2] = {q / A, q != 0.0 ? C / q : -1.0};
    for (double x : roots)
      if (x > 0.0 && (rho < 0.0 || x < rho)) rho = x;
  }
  if (!(rho > 0.0) || !std::isfinite(rho)) return std::nullopt;
  return Sphere{u + rho * v, rho};
}

namespace {

// The container (given, or the spheres' bounding box) and the wall margin
// (given, or one coarsest diameter).
void set_container(const std::vector<Sphere>& spheres,
                   const ConstrictionOptions& o, ConstrictionNetwork& net) {
  Box bb{spheres[0].centre, spheres[0].centre};
  double dmax = 0.0;
  for (const Sphere& s : spheres) {
    Vec3 r = Vec3::Constant(s.radius);
    bb.lo = bb.lo.cwiseMin(s.centre - r);
    bb.hi = bb.hi.cwiseMax(s.centre + r);
    dmax = std::max(dmax, 2.0 * s.radius);
  }
  net.container = o.container ? *o.container : bb;
  net.wall_margin = o.wall_margin >= 0.0 ? o.wall_margin : dmax;
}

}  // namespace

ConstrictionNetwork constriction_network(const std::vector<Sphere>& spheres,
                                         const ConstrictionOptions& o) {
  validate(spheres, o);
  ConstrictionNetwork net;
  net.spheres = static_cast<long>(spheres.size());
  set_container(spheres, o, net);
  const RegularTriangulation t = regular_triangulation(spheres);
  net.hidden = t.hidden;
  net.cells = static_cast<long>(t.cell.size());
  Pores pores(net.cells);
  merge_pores(t, spheres, o, pores);
  // Pore numbers 0..npores-1 in the order of their first cell.
  std::vector<long> pore_of(net.cells, -1), root_number(net.cells, -1);
  for (long c = 0; c < net.cells; ++c) {
    long r = pores.find(c);
    if (root_number[r] < 0) root_number[r] = net.pores++;
    pore_of[c] = root_number[r];
  }
  std::vector<long> cells_in_pore(net.pores, 0);
  for (long c = 0; c < net.cells; ++c) ++cells_in_pore[pore_of[c]];
  std::vector<char> floor(net.pores, 0), lid(net.pores, 0);
  mark_floor_and_lid(t, spheres, pore_of, floor, lid);
  const Box& box = net.container;
  const double m = net.wall_margin;
  std::vector<std::pair<double, std::pair<long, long>>> edges;
  std::map<std::pair<long, long>, std::vector<Opening>> shared;
  for_each_inner_face(t, [&](const Face& f) {
    long pa = pore_of[f.cell_a], pb = pore_of[f.cell_b];
    if (pa == pb) return;
    FaceResult r = solve_face(f, spheres);
    if (!near_wall(r.centroid, box, m, true))
      edges.push_back({r.disc ? 2.0 * r.disc->radius : 0.0, {pa, pb}});
    if (near_wall(r.centroid, box, m, false)) {
      ++net.wall_excluded;
    } else if (cells_in_pore[pa] > 1 || cells_in_pore[pb] > 1) {
      add_to_openings(shared[{std::min(pa, pb), std::max(pa, pb)}],
                      r.centroid, r.normal, r.scale, r.disc);
    } else if (r.disc) {
      net.discs.push_back(*r.disc);
      net.on_edge += r.disc->on_edge;
    } else {
      ++net.unsolved;
    }
  });
  for (const auto& kv : shared)
    for (const Opening& op : kv.second) {
      if (op.disc) {
        net.discs.push_back(*op.disc);
        net.on_edge += op.disc->on_edge;
      } else {
        ++net.unsolved;
      }
    }
  // The discs in an order of their own, not CGAL's (which follows memory
  // addresses): two faces sharing an edge can give the same circle on it, so
  // the normal breaks the tie.
  std::sort(net.discs.begin(), net.discs.end(),
            [](const ConstrictionDisc& a, const ConstrictionDisc& b) {
              for (int k = 0; k < 3; ++k)
                if (a.centre[k] != b.centre[k]) return a.centre[k] < b.centre[k];
              if (a.radius != b.radius) return a.radius < b.radius;
              for (int k = 0; k < 3; ++k)
                if (a.normal[k] != b.normal[k]) return a.normal[k] < b.normal[k];
              return false;
            });
  double perc = percolation(net.pores, std::move(edges), floor, lid);
  net.percolation_diameter = std::isfinite(perc) ? perc : 0.0;
  return net;
}

std::vector<double> csd_percentiles(const std::vector<ConstrictionDisc>& discs,
                                    const std::vector<double>& percents,
                                    CsdWeight weight) {
  std::vector<CsdPoint> c = cumulative_csd(discs);
  std::vector<double> out;
  for (double p : percents) {
    if (c.empty()) {
      out.push_back(NAN);
      continue;
    }
    if (weight == CsdWeight::number) {  // order statistics, linear between them
      double pos = p / 100.0 * (c.size() - 1);
      std::size_t i = static_cast<std::size_t>(std::floor(pos));
      if (i + 1 >= c.size()) {
        out.push_back(c.back().diameter);
        continue;
      }
      double t = pos - i;
      out.push_back(c[i].diameter + t * (c[i + 1].diameter - c[i].diameter));
      continue;
    }
    // Weighted: the smallest diameter at which the cumulative share reaches p.
    const auto share = [weight](const CsdPoint& q) {
      return weight == CsdWeight::area ? q.percent_area : q.percent_cubic;
    };
    std::size_t i = 0;
    while (i + 1 < c.size() && share(c[i]) < p) ++i;
    out.push_back(c[i].diameter);
  }
  return out;
}

std::vector<double> csd_percentiles(const std::vector<ConstrictionDisc>& discs,
                                    const std::vector<double>& percents,
                                    bool cubic_weight) {
  return csd_percentiles(discs, percents,
                         cubic_weight ? CsdWeight::cubic : CsdWeight::number);
}

std::vector<CsdPoint> cumulative_csd(const std::vector<ConstrictionDisc>& discs) {
  std::vector<double> d;
  d.reserve(discs.size());
  for (const auto& k : discs) d.push_back(2.0 * k.radius);
  std::sort(d.begin(), d.end());
  double total = 0.0, total_area = 0.0;
  for (double x : d) {
    total += x * x * x;
    total_area += x * x;
  }
  std::vector<CsdPoint> out;
  out.reserve(d.size());
  double cum = 0.0, cum_area = 0.0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    cum += d[i] * d[i] * d[i];
    cum_area += d[i] * d[i];
    out.push_back({d[i], 100.0 * (i + 1) / d.size(), 100.0 * cum / total,
                   100.0 * cum_area / total_area});
  }
  return out;
}

}  // namespace fabric
