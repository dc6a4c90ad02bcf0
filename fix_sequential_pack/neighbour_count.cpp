#include "neighbour_count.h"

#include <algorithm>
#include <cstddef>

#include "sphere_grid.h"

namespace fabric {

bool neighbours_surely_fit(const std::vector<double>& radius, double skin,
                           double cdf, long long one) {
  if (radius.size() < 2) return true;
  const auto [rmin, rmax] = std::minmax_element(radius.begin(), radius.end());
  const double reach_max = 2.0 * *rmax * cdf + *rmax + skin;
  return std::pow(reach_max / *rmin, 3) <= one;
}

NeighbourCount count_neighbours(const PackingResult& res,
                                const std::vector<double>& class_diameter,
                                const Box& container, double skin, double cdf,
                                long long keep) {
  NeighbourCount out;
  const long long n = res.placed();
  if (n < 2) return out;
  const double rmax = *std::max_element(res.radius.begin(), res.radius.end());
  std::vector<double> class_radius(class_diameter.size());
  for (std::size_t k = 0; k < class_radius.size(); ++k)
    class_radius[k] = 0.5 * class_diameter[k];
  SphereGrid grid(container.lo, container.hi, class_radius,
                  std::max<std::size_t>(1u << 16, res.centre.size()));
  for (long long i = 0; i < n; ++i) grid.insert(res.centre[i], res.size_class[i]);
  std::vector<int> near;
  std::vector<double> gap;  // per neighbour: the skin that lists it
  for (long long i = 0; i < n; ++i) {
    const double ri = res.radius[i];
    if (ri < 0.5 * rmax) continue;
    near.clear();
    gap.clear();
    grid.within_gap(res.centre[i], ri,
                    skin + (cdf - 1.0) * (ri + rmax) + 1e-12 * rmax, near);
    for (int j : near) {
      if (j == i) continue;
      const Vec3 d = grid.centre(j) - res.centre[i];
      gap.push_back(std::sqrt(d.dot(d)) - (ri + grid.radius(j)) * cdf);
    }
    long long count = 0;
    for (double g : gap) count += g <= skin;
    if (count > out.most) out.most = count, out.diameter = 2.0 * ri;
    if (static_cast<long long>(gap.size()) > keep) {
      std::nth_element(gap.begin(), gap.begin() + keep, gap.end());
      out.skin_for_keep = std::min(out.skin_for_keep, gap[keep]);
    }
  }
  return out;
}

}  // namespace fabric
