#include "regular_triangulation.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <Eigen/LU>
#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace fabric {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<
    long, K, CGAL::Regular_triangulation_vertex_base_3<K>>;
// Hidden points are counted, not kept: no memory per hidden sphere.
using Cb = CGAL::Triangulation_cell_base_with_info_3<
    long, K,
    CGAL::Regular_triangulation_cell_base_3<
        K, CGAL::Triangulation_cell_base_3<K>, CGAL::Discard_hidden_points>>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb>;
using RT = CGAL::Regular_triangulation_3<K, Tds>;
using CellHandle = RT::Cell_handle;

// How many box sizes the radius of a wall's sphere is: large enough that
// the sphere is the plane to 1e-5 box sizes across the box, small enough
// that its weight (R^2) keeps the constructions' rounding far below a grain.
constexpr double kWallRadiusInBoxSizes = 1e4;

RT::Weighted_point weighted(const Vec3& c, double r) {
  return RT::Weighted_point(K::Point_3(c.x(), c.y(), c.z()), r * r);
}

std::vector<std::pair<RT::Weighted_point, long>> points_of(
    const std::vector<Sphere>& spheres, const std::optional<Box>& walls) {
  std::vector<std::pair<RT::Weighted_point, long>> points;
  points.reserve(spheres.size() + 6);
  for (std::size_t i = 0; i < spheres.size(); ++i)
    points.emplace_back(weighted(spheres[i].centre, spheres[i].radius),
                        static_cast<long>(i));
  if (walls) {
    const Vec3 mid = 0.5 * (walls->lo + walls->hi);
    const double R = kWallRadiusInBoxSizes * (walls->hi - walls->lo).maxCoeff();
    for (int w = 0; w < 6; ++w) {
      const int a = wall_axis(w);
      Vec3 c = mid;
      c[a] = wall_side(w) ? walls->hi[a] + R : walls->lo[a] - R;
      points.emplace_back(weighted(c, R), static_cast<long>(spheres.size()) + w);
    }
  }
  return points;
}

// The orthocentre of a cell with wall vertices in the limit of planar walls:
// on every wall of the cell, at equal power from its spheres.
Vec3 orthocentre_at_walls(const std::array<long, 4>& v,
                          const std::vector<Sphere>& s, const Box& box) {
  const long n = static_cast<long>(s.size());
  Eigen::Matrix3d m;
  Vec3 rhs;
  int row = 0;
  long first = -1;
  Vec3 mean = Vec3::Zero();
  for (long id : v) {
    if (id >= n) {
      const int w = static_cast<int>(id - n), a = wall_axis(w);
      m.row(row) = Vec3::Unit(a).transpose();
      rhs[row++] = wall_side(w) ? box.hi[a] : box.lo[a];
    } else if (first < 0) {
      first = id;
    } else {
      const Sphere &p = s[first], &q = s[id];
      m.row(row) = 2.0 * (q.centre - p.centre).transpose();
      rhs[row++] = q.centre.squaredNorm() - p.centre.squaredNorm() -
                   q.radius * q.radius + p.radius * p.radius;
    }
    mean += id < n ? s[id].centre : Vec3(0.5 * (box.lo + box.hi));
  }
  Eigen::FullPivLU<Eigen::Matrix3d> lu(m);
  // Two opposite walls (a box one grain thin): no such point; the cell is
  // not a pore of the box and its centre is only a placeholder.
  return lu.isInvertible() ? Vec3(lu.solve(rhs)) : Vec3(mean / 4.0);
}

// Cells numbered in the order of their sorted vertex indices, faces in the
// order of (cell, opposite vertex): every value computed from a cell takes
// its spheres in the order of their index, and every loop over cells or
// faces runs in an order that depends on the spheres alone, not on CGAL's
// (which follows memory addresses), so a solve over them rounds alike in
// every run and on every rank.
void index_cells(RT& rt, const std::vector<Sphere>& spheres,
                 RegularTriangulation& t) {
  const long n = static_cast<long>(spheres.size());
  std::vector<std::array<long, 4>> ids_of;
  ids_of.reserve(rt.number_of_finite_cells());
  for (auto c = rt.finite_cells_begin(); c != rt.finite_cells_end(); ++c) {
    c->info() = static_cast<long>(ids_of.size());
    std::array<long, 4> ids;
    for (int k = 0; k < 4; ++k) ids[k] = c->vertex(k)->info();
    std::sort(ids.begin(), ids.end());
    ids_of.push_back(ids);
  }
  std::vector<long> order(ids_of.size()), rank(ids_of.size());
  std::iota(order.begin(), order.end(), 0L);
  std::sort(order.begin(), order.end(),
            [&](long a, long b) { return ids_of[a] < ids_of[b]; });
  for (long k = 0; k < static_cast<long>(order.size()); ++k) rank[order[k]] = k;
  std::vector<CellHandle> handle(ids_of.size());
  for (auto c = rt.finite_cells_begin(); c != rt.finite_cells_end(); ++c) {
    c->info() = rank[c->info()];
    handle[c->info()] = c;
  }
  auto centre = rt.geom_traits().construct_weighted_circumcenter_3_object();
  t.cell.reserve(handle.size());
  for (const CellHandle& c : handle) {
    RT::Vertex_handle v[4];
    for (int k = 0; k < 4; ++k) v[k] = c->vertex(k);
    std::sort(v, v + 4, [](const auto& a, const auto& b) {
      return a->info() < b->info();
    });
    std::array<long, 4> ids;
    for (int k = 0; k < 4; ++k) ids[k] = v[k]->info();
    t.cell.push_back(ids);
    if (ids[3] >= n) {
      t.orthocentre.push_back(orthocentre_at_walls(ids, spheres, *t.walls));
    } else {
      const auto p = centre(v[0]->point(), v[1]->point(), v[2]->point(),
                            v[3]->point());
      t.orthocentre.emplace_back(p.x(), p.y(), p.z());
    }
  }
  t.neighbour.assign(t.cell.size(), {-1, -1, -1, -1});
  for (const CellHandle& c : handle) {
    const auto& ids = t.cell[c->info()];
    for (int k = 0; k < 4; ++k) {
      CellHandle nb = c->neighbor(k);
      if (rt.is_infinite(nb)) continue;
      int pos = static_cast<int>(
          std::find(ids.begin(), ids.end(), c->vertex(k)->info()) - ids.begin());
      t.neighbour[c->info()][pos] = nb->info();
    }
  }
}

void index_faces(RT& rt, RegularTriangulation& t) {
  t.faces.reserve(rt.number_of_finite_facets());
  for (auto it = rt.finite_facets_begin(); it != rt.finite_facets_end(); ++it) {
    CellHandle c = it->first, n = c->neighbor(it->second);
    int i = it->second;
    if (rt.is_infinite(c)) {  // a hull face seen from outside: take the cell
      i = n->index(c);
      std::swap(c, n);
    }
    RegularTriangulation::Face f;
    f.cell = c->info();
    f.across = rt.is_infinite(n) ? -1 : n->info();
    f.opposite = c->vertex(i)->info();
    for (int k = 0, j = 0; k < 4; ++k)
      if (k != i) f.vertex[j++] = c->vertex(k)->info();
    t.faces.push_back(f);
  }
  std::sort(t.faces.begin(), t.faces.end(), [](const auto& a, const auto& b) {
    return std::tie(a.cell, a.opposite) < std::tie(b.cell, b.opposite);
  });
}

}  // namespace

RegularTriangulation regular_triangulation(const std::vector<Sphere>& spheres,
                                           const std::optional<Box>& walls) {
  RegularTriangulation t;
  t.spheres = static_cast<long>(spheres.size());
  t.walls = walls;
  auto points = points_of(spheres, walls);
  RT rt;
  rt.insert(points.begin(), points.end());
  t.hidden = static_cast<long>(points.size()) -
             static_cast<long>(rt.number_of_vertices());
  if (rt.dimension() < 3)
    throw std::invalid_argument(
        "the grains' centres are coplanar (or fewer than 4 are visible to the "
        "regular triangulation): no pores");
  index_cells(rt, spheres, t);
  index_faces(rt, t);
  return t;
}

}  // namespace fabric
