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
// Cells hold singly linked lists threaded through one `next` array.
#ifndef FABRIC_SPHERE_GRID_H
#define FABRIC_SPHERE_GRID_H

#include <array>
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

  // Stores a sphere; returns its index (0, 1, 2, ... in insertion order).
  int insert(const Vec3& centre, double radius, int size_class);

  // True if a sphere at `centre` with `radius` overlaps a stored sphere by
  // more than `rel_tol` times the smaller of the two radii.
  bool overlaps(const Vec3& centre, double radius, double rel_tol) const;

  int size() const { return static_cast<int>(r_.size()); }
  Vec3 centre(int i) const { return Vec3(x_[i][0], x_[i][1], x_[i][2]); }
  double radius(int i) const { return r_[i]; }
  Sphere sphere(int i) const { return Sphere{centre(i), r_[i]}; }
  int levels() const { return static_cast<int>(level_.size()); }
  std::size_t memory_bytes() const;
  void reserve(std::size_t n);

 private:
  struct Level {
    double cell;       // edge length = largest diameter on the level
    double max_radius;
    int n[3];
    std::vector<int32_t> head;
    int count = 0;
  };
  int cell_coord(const Level& L, int axis, double v) const;

  Vec3 lo_, hi_;
  std::vector<Level> level_;
  std::vector<int> level_of_class_;
  std::vector<std::array<double, 3>> x_;
  std::vector<double> r_;
  std::vector<int32_t> next_;
};

}  // namespace fabric

#endif
