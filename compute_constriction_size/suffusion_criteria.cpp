#include "suffusion_criteria.h"

#include <algorithm>
#include <cmath>

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

KezdiResult kezdi(const ParticleSizeDistribution& psd) {
  KezdiResult r{0.0, 0.0};
  for (int f = 1; f <= 99; ++f) {
    const double F = f;
    double coarse15 = psd.diameter_at_percent(F + 0.15 * (100.0 - F));
    double fine85 = psd.diameter_at_percent(0.85 * F);
    double ratio = coarse15 / fine85;
    if (ratio > r.max_ratio) r = {ratio, F};
  }
  return r;
}

double kenney_lau_f_max(double cu) {
  if (!(cu > 0.0)) return 30.0;
  const double scale = std::pow(10.0, 2.0 - std::floor(std::log10(cu)));
  const double stated = std::round(cu * scale) / scale;  // 3 significant figures
  return stated > 3.0 ? 20.0 : 30.0;
}

KenneyLauResult kenney_lau(const ParticleSizeDistribution& psd) {
  const double fmax = kenney_lau_f_max(psd.uniformity_coefficient());
  KenneyLauResult r{INFINITY, 0.0, fmax};
  for (double F = 0.5; F <= fmax + 1e-9; F += 0.5) {
    double d = psd.diameter_at_percent(F);
    double H = psd.percent_passing(4.0 * d) - F;
    if (H / F < r.min_ratio) r = {H / F, F, fmax};
  }
  return r;
}

bool BurenkovaResult::stable() const {
  double l = std::log10(h2);
  return 0.76 * l + 1.0 < h1 && h1 < 1.86 * l + 1.0;
}

BurenkovaResult burenkova(const ParticleSizeDistribution& psd) {
  double d90 = psd.diameter_at_percent(90.0);
  return {d90 / psd.diameter_at_percent(60.0),
          d90 / psd.diameter_at_percent(15.0)};
}

WanFellResult wan_fell(const ParticleSizeDistribution& psd) {
  const BurenkovaResult b = burenkova(psd);
  const double l = std::log10(b.h2);
  auto logistic = [](double z) { return 1.0 / (1.0 + std::exp(-z)); };
  return {b.h1, b.h2, logistic(2.378 * l - 3.648 * b.h1 + 3.701),
          logistic(3.875 * l - 3.591 * b.h1 + 2.436)};
}

}  // namespace fabric
