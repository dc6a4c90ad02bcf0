#include "sphere_grid.h"

#include <algorithm>
#include <cmath>

namespace fabric {

SphereGrid::SphereGrid(const Vec3& lo, const Vec3& hi,
                       const std::vector<double>& class_radius,
                       std::size_t max_cells)
    : lo_(lo), hi_(hi), level_of_class_(class_radius.size(), 0) {
  // Group the classes, largest first, into bands of radius ratio <= 2.
  std::vector<int> order(class_radius.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return class_radius[a] > class_radius[b];
  });
  std::vector<std::vector<int>> bands;
  for (int k : order) {
    if (bands.empty() || class_radius[k] <= 0.5 * class_radius[bands.back()[0]])
      bands.push_back({k});
    else
      bands.back().push_back(k);
  }
  auto cells_of = [&](double cell) {
    double total = 1.0;
    for (int a = 0; a < 3; ++a)
      total *= std::max(1.0, std::ceil((hi[a] - lo[a]) / cell));
    return total;
  };
  // Merge the finest band into the next coarser one until the cap holds.
  for (;;) {
    double total = 0.0;
    for (auto& b : bands) total += cells_of(2.0 * class_radius[b[0]]);
    if (total <= static_cast<double>(max_cells) || bands.size() == 1) break;
    auto fine = bands.back();
    bands.pop_back();
    bands.back().insert(bands.back().end(), fine.begin(), fine.end());
  }
  // A single band may still be too fine: coarsen its cell to honour the cap.
  for (auto& b : bands) {
    Level L;
    L.max_radius = class_radius[b[0]];
    L.cell = 2.0 * L.max_radius;
    while (cells_of(L.cell) > static_cast<double>(max_cells)) L.cell *= 1.25;
    for (int a = 0; a < 3; ++a)
      L.n[a] = static_cast<int>(
          std::max(1.0, std::ceil((hi[a] - lo[a]) / L.cell)));
    L.head.assign(static_cast<size_t>(L.n[0]) * L.n[1] * L.n[2], -1);
    for (int k : b) level_of_class_[k] = static_cast<int>(level_.size());
    level_.push_back(std::move(L));
  }
}

void SphereGrid::reserve(std::size_t n) {
  x_.reserve(n);
  r_.reserve(n);
  next_.reserve(n);
}

int SphereGrid::cell_coord(const Level& L, int axis, double v) const {
  int c = static_cast<int>(std::floor((v - lo_[axis]) / L.cell));
  return std::min(std::max(c, 0), L.n[axis] - 1);
}

int SphereGrid::insert(const Vec3& c, double radius, int size_class) {
  Level& L = level_[level_of_class_[size_class]];
  int id = static_cast<int>(r_.size());
  x_.push_back({c[0], c[1], c[2]});
  r_.push_back(radius);
  size_t cell = (static_cast<size_t>(cell_coord(L, 2, c[2])) * L.n[1] +
                 cell_coord(L, 1, c[1])) * L.n[0] + cell_coord(L, 0, c[0]);
  next_.push_back(L.head[cell]);
  L.head[cell] = id;
  ++L.count;
  return id;
}

bool SphereGrid::overlaps(const Vec3& c, double radius, double rel_tol) const {
  for (const Level& L : level_) {
    if (L.count == 0) continue;
    double reach = radius + L.max_radius;
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = cell_coord(L, a, c[a] - reach);
      hi[a] = cell_coord(L, a, c[a] + reach);
    }
    for (int iz = lo[2]; iz <= hi[2]; ++iz)
      for (int iy = lo[1]; iy <= hi[1]; ++iy) {
        size_t row = (static_cast<size_t>(iz) * L.n[1] + iy) * L.n[0];
        for (int ix = lo[0]; ix <= hi[0]; ++ix)
          for (int j = L.head[row + ix]; j >= 0; j = next_[j]) {
            double dx = c[0] - x_[j][0], dy = c[1] - x_[j][1],
                   dz = c[2] - x_[j][2];
            double contact = radius + r_[j] -
                             rel_tol * std::min(radius, r_[j]);
            if (dx * dx + dy * dy + dz * dz < contact * contact) return true;
          }
      }
  }
  return false;
}

std::size_t SphereGrid::memory_bytes() const {
  std::size_t b = x_.capacity() * sizeof(x_[0]) + r_.capacity() * sizeof(double) +
                  next_.capacity() * sizeof(int32_t);
  for (const Level& L : level_) b += L.head.capacity() * sizeof(int32_t);
  return b;
}

}  // namespace fabric
