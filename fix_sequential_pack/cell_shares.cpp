// The split of the placed spheres' volume over the cells of the vacancy
// choice (see cell_shares.h).
#include "cell_shares.h"

#include <cmath>

namespace fabric {
namespace detail {

namespace {

// Quadrature points of the unit ball: the centres of an 8^3 lattice on
// [-1, 1]^3 that lie inside it.
const std::vector<Vec3>& unit_ball_points() {
  static const std::vector<Vec3> ball = [] {
    std::vector<Vec3> p;
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j)
        for (int k = 0; k < 8; ++k) {
          Vec3 q((i + 0.5) / 4.0 - 1.0, (j + 0.5) / 4.0 - 1.0,
                 (k + 0.5) / 4.0 - 1.0);
          if (q.squaredNorm() <= 1.0) p.push_back(q);
        }
    return p;
  }();
  return ball;
}

}  // namespace

CellShares split_over_cells(const SphereGrid& grid, const Vec3& lo,
                            const Vec3& hi, double dmax) {
  CellShares cs;
  cs.lo = lo;
  const Vec3 ext = hi - lo;
  for (int a = 0; a < 3; ++a) {
    cs.n[a] = std::max(1, static_cast<int>(std::lround(ext[a] / dmax)));
    cs.cell_size[a] = ext[a] / cs.n[a];
  }
  cs.cells = cs.n[0] * cs.n[1] * cs.n[2];
  cs.split_radius = 0.125 * cs.cell_size.minCoeff();
  const std::vector<Vec3>& ball = unit_ball_points();
  std::vector<int> count_in(cs.cells), touched;
  cs.begin.assign(grid.size() + 1, 0);
  for (int i = 0; i < grid.size(); ++i) {
    cs.begin[i] = static_cast<std::uint32_t>(cs.part.size());
    const Vec3 c = grid.centre(i);
    const double r = grid.radius(i);
    bool within = true;  // does the sphere lie in the cell of its centre?
    for (int a = 0; a < 3 && within; ++a) {
      double cl = lo[a] + std::floor((c[a] - lo[a]) / cs.cell_size[a]) *
                              cs.cell_size[a];
      within = c[a] - r >= cl && c[a] + r <= cl + cs.cell_size[a];
    }
    if (within || r < cs.split_radius) {
      cs.part.push_back({cs.cell_at(c), 1.0});
      continue;
    }
    std::fill(count_in.begin(), count_in.end(), 0);
    touched.clear();
    for (const Vec3& q : ball) {
      int cq = cs.cell_at(c + r * q);
      if (count_in[cq]++ == 0) touched.push_back(cq);
    }
    for (int cq : touched)
      cs.part.push_back({cq, static_cast<double>(count_in[cq]) / ball.size()});
  }
  cs.begin[grid.size()] = static_cast<std::uint32_t>(cs.part.size());
  return cs;
}

}  // namespace detail
}  // namespace fabric
