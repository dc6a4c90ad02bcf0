// The split of the placed spheres' volume over the grid cells of the vacancy
// choice (Packer::choose_vacancies): which cells each sphere's volume lies in,
// and how much of it in each.
#ifndef FABRIC_CELL_SHARES_H
#define FABRIC_CELL_SHARES_H

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "geometry.h"
#include "sphere_grid.h"

namespace fabric {
namespace detail {

// The cells of the vacancy choice (about a coarsest diameter each) and the
// share of each placed sphere's volume in each cell it meets: a sphere wider
// than an eighth of a cell is split over the cells it meets by a lattice
// quadrature; a smaller one counts in the cell of its centre.
struct CellShares {
  int n[3];
  Vec3 lo, cell_size;
  int cells = 0;
  double split_radius = 0.0;
  std::vector<std::uint32_t> begin;          // per sphere, into part
  std::vector<std::pair<int, double>> part;  // (cell, share of the volume)
  int cell_at(const Vec3& q) const {
    int idx[3];
    for (int a = 0; a < 3; ++a)
      idx[a] = std::clamp(static_cast<int>((q[a] - lo[a]) / cell_size[a]), 0,
                          n[a] - 1);
    return (idx[2] * n[1] + idx[1]) * n[0] + idx[0];
  }
  int home(int i) const { return part[begin[i]].first; }
};

// The cells of the box [lo, hi], each about dmax wide, and the shares of
// every sphere of the grid in them.
CellShares split_over_cells(const SphereGrid& grid, const Vec3& lo,
                            const Vec3& hi, double dmax);

}  // namespace detail
}  // namespace fabric

#endif
