#include "suffusion_criteria.h"

namespace fabric {

double mass_percent_finer(const std::vector<double>& d,
                          const std::vector<double>& m, double opening) {
  double total = 0.0, finer = 0.0;
  for (std::size_t i = 0; i < d.size() && i < m.size(); ++i) {
    total += m[i];
    if (d[i] < opening) finer += m[i];
  }
  return total > 0.0 ? 100.0 * finer / total : 0.0;
}

}  // namespace fabric
