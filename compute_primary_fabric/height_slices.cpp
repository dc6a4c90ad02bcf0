#include "height_slices.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fabric {

namespace {

[[noreturn]] void fail(const std::string& message) {
  throw std::invalid_argument("primary/fabric: " + message);
}

double ratio(double numerator, double denominator) {
  return denominator > 0.0 ? numerator / denominator : 0.0;
}

void check_index(int index, int particles, const char* what, std::size_t k) {
  if (index < 0 || index >= particles)
    fail(std::string(what) + " " + std::to_string(k) + " refers to particle " +
         std::to_string(index) + ", the list has " + std::to_string(particles));
}

}  // namespace

HeightExtent height_extent(const std::vector<Particle>& particles,
                           const std::vector<double>& z) {
  if (z.size() != particles.size())
    fail("got " + std::to_string(z.size()) + " heights for " +
         std::to_string(particles.size()) + " particles");
  HeightExtent e{std::numeric_limits<double>::infinity(),
                 -std::numeric_limits<double>::infinity()};
  for (std::size_t p = 0; p < particles.size(); ++p) {
    e.bottom = std::min(e.bottom, z[p] - particles[p].radius);
    e.top = std::max(e.top, z[p] + particles[p].radius);
  }
  return e;
}

HeightSlices::HeightSlices(HeightExtent extent, int count)
    : bottom_(extent.bottom), top_(extent.top), count_(count) {
  if (count < 1) fail("slices must be >= 1, got " + std::to_string(count));
  if (top_ >= bottom_ && !(std::isfinite(bottom_) && std::isfinite(top_))) {
    std::ostringstream m;
    m << "the grains' extent along z, " << bottom_ << " to " << top_
      << ", is not finite: no height slices";
    fail(m.str());
  }
}

double HeightSlices::lower(int k) const {
  if (empty()) return 0.0;
  return bottom_ + (top_ - bottom_) * k / count_;
}

double HeightSlices::upper(int k) const {
  if (empty()) return 0.0;
  return k + 1 == count_ ? top_ : bottom_ + (top_ - bottom_) * (k + 1) / count_;
}

int HeightSlices::of(double z) const {
  if (empty() || !(z >= bottom_ && z <= top_)) return -1;
  if (top_ == bottom_) return 0;
  const int k = static_cast<int>((z - bottom_) / (top_ - bottom_) * count_);
  // the bounds are those of lower()/upper(), whatever the rounding above
  int s = std::min(std::max(k, 0), count_ - 1);
  while (s > 0 && z < lower(s)) --s;
  while (s + 1 < count_ && z >= lower(s + 1)) ++s;
  return s;
}

SliceSums::SliceSums(int slices) : slices_(slices) {
  if (slices < 1) fail("slices must be >= 1, got " + std::to_string(slices));
  values_.assign(static_cast<std::size_t>(slices) * kPerSlice, 0.0);
}

int SliceSums::index(int k) const {
  if (k < 0 || k >= slices_)
    fail("slice " + std::to_string(k) + " is not in 0.." +
         std::to_string(slices_ - 1));
  return k * kPerSlice;
}

SliceSums accumulate_slices(const std::vector<Particle>& particles,
                            const std::vector<double>& z,
                            const std::vector<ParticleContact>& contacts,
                            const std::vector<WallContact>& walls,
                            const Classification& classification,
                            double threshold_force, const HeightSlices& slices,
                            const Options& options) {
  validate(options);
  const int n = static_cast<int>(particles.size());
  if (z.size() != particles.size())
    fail("got " + std::to_string(z.size()) + " heights for " +
         std::to_string(n) + " particles");
  if (classification.fraction.size() != particles.size() ||
      classification.loaded_contacts.size() != particles.size())
    fail("the classification does not belong to these particles");

  using S = SliceSums::Sum;
  SliceSums sums(slices.count());
  std::vector<int> slice_of(n);
  for (int p = 0; p < n; ++p) {
    const int k = slices.of(z[p]);
    slice_of[p] = k;
    if (!std::isfinite(z[p])) continue;  // a broken state: in no slice
    if (k < 0) {
      std::ostringstream m;
      m << "particle " << particles[p].id << " at height " << z[p]
        << " lies outside the height slices";
      fail(m.str());
    }
    const bool primary = classification.fraction[p] == Fraction::primary;
    sums.at(k, S::particles) += 1.0;
    sums.at(k, S::mass) += particles[p].mass;
    sums.at(k, S::loaded_contacts) += classification.loaded_contacts[p];
    if (primary)
      sums.at(k, S::primary_mass) += particles[p].mass;
    else
      sums.at(k, S::loose_particles) += 1.0;
  }

  auto add = [&](int k, double weight, double force,
                 const Eigen::Vector3d& normal) {
    const Eigen::Vector3d u = normal.normalized();
    const Eigen::Matrix3d dyad = u * u.transpose();
    sums.at(k, S::fabric_contacts) += weight;
    sums.at(k, S::fabric_normal_force) += weight * force;
    sums.normal_dyads(k) += weight * dyad;
    sums.force_dyads(k) += weight * force * dyad;
  };
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const ParticleContact& k = contacts[c];
    check_index(k.i, n, "particle contact", c);
    if (k.complete) check_index(k.j, n, "particle contact", c);
    if (!std::isfinite(k.normal_force) || !k.normal.allFinite() ||
        k.normal.squaredNorm() == 0.0)
      fail("particle contact " + std::to_string(c) +
           " has a non-finite force or a zero or non-finite normal");
    if (!is_loaded(k.normal_force, threshold_force)) continue;
    // half for each end; the other rank adds the partner's half
    if (slice_of[k.i] >= 0) add(slice_of[k.i], 0.5, k.normal_force, k.normal);
    if (k.complete && slice_of[k.j] >= 0)
      add(slice_of[k.j], 0.5, k.normal_force, k.normal);
  }
  if (options.walls_in_fabric)
    for (std::size_t c = 0; c < walls.size(); ++c) {
      const WallContact& w = walls[c];
      check_index(w.i, n, "wall contact", c);
      if (!std::isfinite(w.normal_force) || !w.normal.allFinite() ||
          w.normal.squaredNorm() == 0.0)
        fail("wall contact " + std::to_string(c) +
             " has a non-finite force or a zero or non-finite normal");
      if (is_loaded(w.normal_force, threshold_force) && slice_of[w.i] >= 0)
        add(slice_of[w.i], 1.0, w.normal_force, w.normal);
    }
  return sums;
}

std::vector<SliceSummary> finalise_slices(const SliceSums& sums,
                                          const HeightSlices& slices) {
  if (sums.slices() != slices.count())
    fail("sums of " + std::to_string(sums.slices()) + " slices for " +
         std::to_string(slices.count()) + " slices");
  using S = SliceSums::Sum;
  double mass = 0.0;
  for (int k = 0; k < sums.slices(); ++k) mass += sums.at(k, S::mass);
  std::vector<SliceSummary> rows(sums.slices());
  for (int k = 0; k < sums.slices(); ++k) {
    SliceSummary& r = rows[k];
    const double n = sums.at(k, S::particles);
    const double m = sums.at(k, S::mass);
    r.lower = slices.lower(k);
    r.upper = slices.upper(k);
    r.particles = n;
    r.mass_percent = 100.0 * ratio(m, mass);
    r.primary_percent = 100.0 * ratio(sums.at(k, S::primary_mass), m);
    r.loose_percent_by_number = 100.0 * ratio(sums.at(k, S::loose_particles), n);
    r.coordination = ratio(sums.at(k, S::loaded_contacts), n);
    r.fabric_contacts = sums.at(k, S::fabric_contacts);
    if (r.fabric_contacts > 0.0)
      r.fabric_tensor = sums.normal_dyads(k) / r.fabric_contacts;
    if (sums.at(k, S::fabric_normal_force) > 0.0)
      r.force_fabric_tensor =
          sums.force_dyads(k) / sums.at(k, S::fabric_normal_force);
    r.fabric_anisotropy = fabric_anisotropy(r.fabric_tensor);
    r.force_anisotropy = force_anisotropy(r.fabric_tensor, r.force_fabric_tensor);
  }
  return rows;
}

}  // namespace fabric
