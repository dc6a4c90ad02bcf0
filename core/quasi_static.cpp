#include "quasi_static.h"

#include <cmath>
#include <limits>

namespace fabric {

bool valid_local_damping(double alpha) { return alpha >= 0.0 && alpha < 1.0; }

double local_damping(double force, double velocity, double alpha) {
  if (velocity > 0.0) return force - alpha * std::fabs(force);
  if (velocity < 0.0) return force + alpha * std::fabs(force);
  return force;
}

void damp_locally(double *f, const double *v, double alpha) {
  for (int k = 0; k < 3; ++k) f[k] = local_damping(f[k], v[k], alpha);
}

void ForceBalance::add_grain(const double *resultant) {
  resultant_sum += std::sqrt(resultant[0] * resultant[0] +
                             resultant[1] * resultant[1] +
                             resultant[2] * resultant[2]);
  grains += 1.0;
}

void ForceBalance::add_contact(double magnitude) {
  contact_sum += std::fabs(magnitude);
  contacts += 1.0;
}

double ForceBalance::ratio() const {
  if (contacts == 0.0 || contact_sum == 0.0 || grains == 0.0)
    return std::numeric_limits<double>::infinity();
  return (resultant_sum / grains) / (contact_sum / contacts);
}

std::array<double, 4> ForceBalance::sums() const {
  return {resultant_sum, grains, contact_sum, contacts};
}

ForceBalance ForceBalance::from_sums(const std::array<double, 4> &s) {
  ForceBalance b;
  b.resultant_sum = s[0];
  b.grains = s[1];
  b.contact_sum = s[2];
  b.contacts = s[3];
  return b;
}

ForceBalance balance_of(int grains, const std::vector<PairForce> &contacts,
                        const std::vector<std::array<double, 3>> &external) {
  std::vector<std::array<double, 3>> resultant(grains, {0.0, 0.0, 0.0});
  std::vector<bool> touched(grains, false);
  ForceBalance b;
  for (const PairForce &c : contacts) {
    for (int k = 0; k < 3; ++k) {
      resultant[c.i][k] += c.force_on_i[k];
      if (c.j >= 0) resultant[c.j][k] -= c.force_on_i[k];
    }
    touched[c.i] = true;
    if (c.j >= 0) touched[c.j] = true;
    const auto &f = c.force_on_i;
    b.add_contact(std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]));
  }
  for (int g = 0; g < grains; ++g) {
    if (g < static_cast<int>(external.size()))
      for (int k = 0; k < 3; ++k) resultant[g][k] += external[g][k];
    if (touched[g]) b.add_grain(resultant[g].data());
  }
  return b;
}

}  // namespace fabric
