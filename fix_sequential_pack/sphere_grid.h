// Overlap queries for polydisperse spheres in a box: a hierarchical grid.
//
// Plain C++, no LIGGGHTS include. One uniform grid sized by the largest
// sphere would put hundreds of fine spheres in a cell when sizes differ by a
// factor of 25; one sized by the finest would make a coarse query visit
// thousands of cells. So the size classes are grouped into levels whose radii
// differ by at most a factor of 2, and each level has its own dense grid
// with a cell edge of its largest diameter (the idea of Ogarko & Luding's
// hierarchical grid, also MercuryDPM's HGrid). A query visits, on each
// level, only the cells within (query radius + level's largest radius).
// Cells hold singly linked lists threaded through the sphere records, and
// are stored in blocks of 4 x 4 x 4 with one 64-bit word of occupancy bits
// per block, so a query skips empty cells without touching their list heads.
// Only the answer of a query is defined (is there an overlapping sphere?),
// not the order in which spheres are tested: queries test first where an
// overlap is most likely, and take hints from the caller.
#ifndef FABRIC_SPHERE_GRID_H
#define FABRIC_SPHERE_GRID_H

#include <algorithm>
#include <cstdint>
#include <vector>

#include "trilateration.h"

namespace fabric {

class SphereGrid {
 public:
  // `class_radius[k]`: radius of size class k (any order); spheres are
  // inserted with their class. `max_cells` caps the dense arrays of all
  // levels together (fine levels merge into coarser ones until it holds).
  SphereGrid(const Vec3& lo, const Vec3& hi,
             const std::vector<double>& class_radius, std::size_t max_cells);

  // Stores a sphere of class `size_class` (its radius is the class radius);
  // returns its index (0, 1, 2, ... in insertion order).
  int insert(const Vec3& centre, int size_class);

  // True if a sphere at `centre` with `radius` overlaps a stored sphere by
  // more than `rel_tol` times the smaller of the two radii.
  bool overlaps(const Vec3& centre, double radius, double rel_tol) const;
  // The same answer; first the stored spheres hint[0..n_hints) (-1: none)
  // are tested, then all within reach. On an overlap `found` is the sphere
  // found and `from_hint` tells whether it was one of the hints. A caller
  // whose queries come in runs at one place (one face, several sizes) finds
  // most overlaps with these few tests.
  bool overlaps(const Vec3& centre, double radius, double rel_tol,
                const int* hint, int n_hints, int& found,
                bool& from_hint) const {
    for (int i = 0; i < n_hints; ++i)
      if (hint[i] >= 0 && hint[i] < size() &&
          pair_overlaps(s_[hint[i]], centre[0], centre[1], centre[2], radius,
                        rel_tol)) {
        found = hint[i];
        from_hint = true;
        return true;
      }
    from_hint = false;
    return scan(centre, radius, rel_tol, found);
  }

  // Appends to `out` every stored sphere j whose gap to a sphere at `centre`
  // with `radius` is below `gap`: |centre - c_j| - radius - r_j < gap.
  void within_gap(const Vec3& centre, double radius, double gap,
                  std::vector<int>& out) const;
  int size() const { return static_cast<int>(s_.size()); }
  Vec3 centre(int i) const { return Vec3(s_[i].x, s_[i].y, s_[i].z); }
  double radius(int i) const { return class_radius_[s_[i].size_class]; }
  int sphere_class(int i) const { return s_[i].size_class; }
  Sphere sphere(int i) const { return Sphere{centre(i), radius(i)}; }
  int levels() const { return static_cast<int>(level_.size()); }
  std::size_t memory_bytes() const;
  void reserve(std::size_t n);

 private:
  // Cells are stored in blocks of 4 x 4 x 4 (bit / head index x + 4 y + 16 z
  // within the block): a block's 64 occupancy bits are one word, and its 64
  // list heads lie together. A query masks each block's word with its box
  // and visits only the occupied cells inside. (The cell count is rounded
  // up to whole blocks after the cap of the constructor is applied.)
  struct Level {
    double cell;       // edge length = largest diameter on the level
    double inv_cell;   // 1 / cell
    double max_radius;
    int n[3];          // cells per axis
    int nb[3];         // blocks per axis
    std::vector<int32_t> head;            // per cell, block-major
    std::vector<std::uint64_t> occupied;  // per block: bit = head != -1
    int count = 0;
  };
  // A stored sphere: centre, class and the next sphere in its cell in one
  // aligned 32-byte record, so a pair test touches one cache line.
  struct alignas(32) Entry {
    double x, y, z;
    int32_t next;
    int32_t size_class;
  };
  // Cell index along `axis` of coordinate `v`, clamped to the grid. Any
  // mapping that does not decrease with `v` keeps queries exact, since
  // insert and query share it; this one multiplies instead of dividing.
  int cell_coord(const Level& L, int axis, double v) const {
    double t = (v - lo_[axis]) * L.inv_cell;
    if (!(t > 0.0)) return 0;
    if (t >= static_cast<double>(L.n[axis] - 1)) return L.n[axis] - 1;
    return static_cast<int>(t);
  }
  bool pair_overlaps(const Entry& e, double cx, double cy, double cz,
                     double radius, double rel_tol) const {
    const double r = class_radius_[e.size_class];
    double dx = cx - e.x, dy = cy - e.y, dz = cz - e.z;
    double contact = radius + r - rel_tol * std::min(radius, r);
    return dx * dx + dy * dy + dz * dz < contact * contact;
  }
  struct Box {
    int lo[3], hi[3];  // cell coordinates, inclusive
  };
  Box box(const Level& L, const Vec3& c, double reach) const;
  // Tests the spheres in the cells of `b` (less those of `skip`, if given).
  bool scan_box(const Level& L, const Box& b, const Box* skip, const Vec3& c,
                double radius, double rel_tol, int& found) const;
  bool scan(const Vec3& centre, double radius, double rel_tol,
            int& found) const;

  Vec3 lo_, hi_;
  std::vector<Level> level_;
  std::vector<int> level_of_class_;
  std::vector<double> class_radius_;
  std::vector<Entry> s_;
};

}  // namespace fabric

#endif
