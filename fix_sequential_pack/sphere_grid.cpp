#include "sphere_grid.h"

#include <algorithm>
#include <cmath>

namespace fabric {

namespace {

// Bits of a 4 x 4 x 4 block (bit = x + 4 y + 16 z) by one coordinate:
// from[axis][a]: coordinate >= a; up_to[axis][b]: coordinate <= b.
struct AxisMasks {
  std::uint64_t from[3][4] = {}, up_to[3][4] = {};
  constexpr AxisMasks() {
    for (int axis = 0; axis < 3; ++axis)
      for (int a = 0; a < 4; ++a)
        for (int bit = 0; bit < 64; ++bit) {
          int v = (bit >> (2 * axis)) & 3;
          if (v >= a) from[axis][a] |= std::uint64_t{1} << bit;
          if (v <= a) up_to[axis][a] |= std::uint64_t{1} << bit;
        }
  }
};
constexpr AxisMasks kMask;

// Bits of block `blk` (along `axis`) whose coordinate is in [lo, hi]; the
// block must meet that range.
inline std::uint64_t axis_bits(int axis, int blk, int lo, int hi) {
  std::uint64_t m = ~std::uint64_t{0};
  if (blk == lo >> 2) m &= kMask.from[axis][lo & 3];
  if (blk == hi >> 2) m &= kMask.up_to[axis][hi & 3];
  return m;
}

// The same, for a range that the block may miss (then no bits).
inline std::uint64_t axis_bits_any(int axis, int blk, int lo, int hi) {
  return blk < lo >> 2 || blk > hi >> 2 ? 0 : axis_bits(axis, blk, lo, hi);
}

// Index of the lowest set bit of a non-zero word.
inline int lowest_bit(std::uint64_t bits) {
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_ctzll(bits);
#else
  int i = 0;
  while (!(bits & 1)) bits >>= 1, ++i;
  return i;
#endif
}

}  // namespace

SphereGrid::SphereGrid(const Vec3& lo, const Vec3& hi,
                       const std::vector<double>& class_radius,
                       std::size_t max_cells)
    : lo_(lo),
      hi_(hi),
      level_of_class_(class_radius.size(), 0),
      class_radius_(class_radius) {
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
    L.inv_cell = 1.0 / L.cell;
    size_t blocks = 1;
    for (int a = 0; a < 3; ++a) {
      L.n[a] = static_cast<int>(
          std::max(1.0, std::ceil((hi[a] - lo[a]) / L.cell)));
      L.nb[a] = (L.n[a] + 3) / 4;
      blocks *= static_cast<size_t>(L.nb[a]);
    }
    L.head.assign(64 * blocks, -1);
    L.occupied.assign(blocks, 0);
    for (int k : b) level_of_class_[k] = static_cast<int>(level_.size());
    level_.push_back(std::move(L));
  }
}

void SphereGrid::reserve(std::size_t n) {
  s_.reserve(n);
}

int SphereGrid::insert(const Vec3& c, int size_class) {
  Level& L = level_[level_of_class_[size_class]];
  int id = static_cast<int>(s_.size());
  int ix = cell_coord(L, 0, c[0]), iy = cell_coord(L, 1, c[1]),
      iz = cell_coord(L, 2, c[2]);
  size_t block =
      (static_cast<size_t>(iz >> 2) * L.nb[1] + (iy >> 2)) * L.nb[0] + (ix >> 2);
  int bit = (ix & 3) | (iy & 3) << 2 | (iz & 3) << 4;
  size_t cell = 64 * block + bit;
  s_.push_back(Entry{c[0], c[1], c[2], L.head[cell], size_class});
  L.head[cell] = id;
  L.occupied[block] |= std::uint64_t{1} << bit;
  ++L.count;
  return id;
}

SphereGrid::Box SphereGrid::box(const Level& L, const Vec3& c,
                                double reach) const {
  Box b;
  for (int a = 0; a < 3; ++a) {
    b.lo[a] = cell_coord(L, a, c[a] - reach);
    b.hi[a] = cell_coord(L, a, c[a] + reach);
  }
  return b;
}

bool SphereGrid::scan_box(const Level& L, const Box& b, const Box* skip,
                          const Vec3& c, double radius, double rel_tol,
                          int& found) const {
  const double cx = c[0], cy = c[1], cz = c[2];
  const std::uint64_t* occ = L.occupied.data();
  const int32_t* head = L.head.data();
  const int bx0 = b.lo[0] >> 2, bx1 = b.hi[0] >> 2;
  for (int bz = b.lo[2] >> 2; bz <= b.hi[2] >> 2; ++bz) {
    std::uint64_t mz = axis_bits(2, bz, b.lo[2], b.hi[2]);
    std::uint64_t sz =
        skip ? axis_bits_any(2, bz, skip->lo[2], skip->hi[2]) : 0;
    for (int by = b.lo[1] >> 2; by <= b.hi[1] >> 2; ++by) {
      std::uint64_t myz = mz & axis_bits(1, by, b.lo[1], b.hi[1]);
      std::uint64_t syz =
          sz ? sz & axis_bits_any(1, by, skip->lo[1], skip->hi[1]) : 0;
      size_t row = (static_cast<size_t>(bz) * L.nb[1] + by) * L.nb[0];
      for (int bx = bx0; bx <= bx1; ++bx) {
        std::uint64_t bits = occ[row + bx] & myz;
        if (!bits) continue;
        bits &= axis_bits(0, bx, b.lo[0], b.hi[0]);
        if (syz)
          bits &= ~(syz & axis_bits_any(0, bx, skip->lo[0], skip->hi[0]));
        const int32_t* h = head + 64 * (row + bx);
        while (bits) {
          int bit = lowest_bit(bits);
          bits &= bits - 1;
          for (int j = h[bit]; j >= 0;) {
            const Entry& e = s_[j];
            if (pair_overlaps(e, cx, cy, cz, radius, rel_tol)) {
              found = j;
              return true;
            }
            j = e.next;
          }
        }
      }
    }
  }
  return false;
}

// Every stored sphere that overlaps lies within (radius + level's largest
// radius) of the centre on each axis, so in the cells visited; the answer is
// "any pair overlaps", whatever order the pairs are tested in. The order is
// chosen to find an overlap early: first, on every level, the cells within
// `radius` of the centre (where an overlapping sphere most often is), then
// the rest of each level's range.
bool SphereGrid::scan(const Vec3& c, double radius, double rel_tol,
                      int& found) const {
  constexpr size_t kKept = 16;  // inner boxes kept for the second pass
  Box inner[kKept];
  // The first pass starts on the level of the query's own size, where an
  // overlapping sphere is found most often, then goes to coarser levels and
  // last to finer ones.
  size_t own = 0;
  while (own + 1 < level_.size() && level_[own + 1].max_radius >= radius)
    ++own;
  for (size_t i = 0; i < level_.size(); ++i) {
    size_t l = i <= own ? own - i : i;
    const Level& L = level_[l];
    if (L.count == 0) continue;
    Box b = box(L, c, radius);
    if (l < kKept) inner[l] = b;
    if (scan_box(L, b, nullptr, c, radius, rel_tol, found)) return true;
  }
  for (size_t l = 0; l < level_.size(); ++l) {
    const Level& L = level_[l];
    if (L.count == 0) continue;
    Box in = l < kKept ? inner[l] : box(L, c, radius);
    if (scan_box(L, box(L, c, radius + L.max_radius), &in, c, radius,
                 rel_tol, found))
      return true;
  }
  return false;
}

void SphereGrid::within_gap(const Vec3& c, double radius, double gap,
                            std::vector<int>& out) const {
  for (const Level& L : level_) {
    if (L.count == 0) continue;
    Box b = box(L, c, radius + L.max_radius + gap);
    for (int bz = b.lo[2] >> 2; bz <= b.hi[2] >> 2; ++bz) {
      std::uint64_t mz = axis_bits(2, bz, b.lo[2], b.hi[2]);
      for (int by = b.lo[1] >> 2; by <= b.hi[1] >> 2; ++by) {
        std::uint64_t myz = mz & axis_bits(1, by, b.lo[1], b.hi[1]);
        size_t row = (static_cast<size_t>(bz) * L.nb[1] + by) * L.nb[0];
        for (int bx = b.lo[0] >> 2; bx <= b.hi[0] >> 2; ++bx) {
          std::uint64_t bits = L.occupied[row + bx] & myz &
                               axis_bits(0, bx, b.lo[0], b.hi[0]);
          const int32_t* h = L.head.data() + 64 * (row + bx);
          while (bits) {
            int bit = lowest_bit(bits);
            bits &= bits - 1;
            for (int j = h[bit]; j >= 0; j = s_[j].next) {
              const Entry& e = s_[j];
              double reach = radius + class_radius_[e.size_class] + gap;
              double dx = c[0] - e.x, dy = c[1] - e.y, dz = c[2] - e.z;
              if (dx * dx + dy * dy + dz * dz < reach * reach) out.push_back(j);
            }
          }
        }
      }
    }
  }
}

bool SphereGrid::overlaps(const Vec3& c, double radius, double rel_tol) const {
  int found;
  return scan(c, radius, rel_tol, found);
}

std::size_t SphereGrid::memory_bytes() const {
  std::size_t b = s_.capacity() * sizeof(Entry) +
                  class_radius_.capacity() * sizeof(double);
  for (const Level& L : level_)
    b += L.head.capacity() * sizeof(int32_t) +
         L.occupied.capacity() * sizeof(std::uint64_t);
  return b;
}

}  // namespace fabric
