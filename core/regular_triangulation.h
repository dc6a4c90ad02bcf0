// The regular (power-weighted) Delaunay triangulation of a packing of
// spheres: the one triangulation of the project, shared by the
// constrictions (compute constriction/size, constriction_network.h) and the
// pore-scale flow (pore_flow.h).
//
// Plain C++ on CGAL (compiled apart, see CMakeLists.txt), no LIGGGHTS
// include: the spheres are inserted into CGAL's Regular_triangulation_3 as
// weighted points (centre, r^2) and the result is handed out as plain
// arrays, so that the code that reads it needs no CGAL header. Each
// tetrahedron (cell) is a pore; its weighted circumcentre (orthocentre) is
// the vertex of the power diagram that the pore finite-volume method takes as
// the pore's centre (Chareyre et al. 2012).
//
// With walls, the six faces of a box are inserted as six more vertices, as
// YADE's FlowEngine does: each a sphere so large (radius 1e4 box sizes)
// that it is a plane where the packing is. The cells then fill the box up to
// its walls; a cell with a wall vertex has its orthocentre on that wall (the
// power distance to a plane-like sphere is 2R times the distance to the
// plane, so any finite power is met on the plane as R grows), and it is
// placed there exactly rather than computed from the large sphere.
#ifndef FABRIC_REGULAR_TRIANGULATION_H
#define FABRIC_REGULAR_TRIANGULATION_H

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include "box.h"
#include "geometry.h"

namespace fabric {

struct RegularTriangulation {
  long spheres = 0;  // vertices 0 .. spheres-1 are the input spheres
  long hidden = 0;   // spheres the triangulation hides (inside others' power)
  // Walls: vertex spheres + w for w = 0..5, the box faces x lo, x hi, y lo,
  // y hi, z lo, z hi.
  std::optional<Box> walls;
  // Per cell, in CGAL's order of its finite cells: its four vertices in
  // increasing order, the cell across the face opposite each (-1: outside
  // the convex hull) and its orthocentre.
  std::vector<std::array<long, 4>> cell;
  std::vector<std::array<long, 4>> neighbour;
  std::vector<Vec3> orthocentre;
  // Every triangular face once, in CGAL's order of its finite facets. `cell`
  // is a finite cell of the face, `vertex` its three vertices in that cell's
  // order, `opposite` the cell's fourth vertex; `across` the cell on the
  // other side (-1: the face is on the convex hull).
  struct Face {
    long cell, across, opposite;
    std::array<long, 3> vertex;
  };
  std::vector<Face> faces;

  bool is_wall(long v) const { return v >= spheres; }
  int wall_of(long v) const { return static_cast<int>(v - spheres); }
};

// The axis (0 x, 1 y, 2 z) and side (0 lo, 1 hi) of wall w.
inline int wall_axis(int w) { return w / 2; }
inline int wall_side(int w) { return w % 2; }

// Whether two cells across a face (its three vertices) are one pore: their
// orthocentres coincide within `tolerance` times the largest radius of the
// face's spheres. Lattices split one pore into several such cells (FCC's
// octahedron, the cube of simple cubic); the constrictions and the pore
// flow both join them.
inline bool same_pore(const RegularTriangulation& t, long cell_a, long cell_b,
                      const std::array<long, 3>& face,
                      const std::vector<Sphere>& spheres, double tolerance) {
  double scale = 0.0;
  for (long v : face)
    if (!t.is_wall(v)) scale = std::max(scale, spheres[v].radius);
  return (t.orthocentre[cell_a] - t.orthocentre[cell_b]).norm() <=
         tolerance * scale;
}

// Throws std::invalid_argument when the visible centres are coplanar (or
// fewer than 4): no cells. Spheres are assumed valid (finite, r > 0).
RegularTriangulation regular_triangulation(const std::vector<Sphere>& spheres,
                                           const std::optional<Box>& walls = {});

}  // namespace fabric

#endif
