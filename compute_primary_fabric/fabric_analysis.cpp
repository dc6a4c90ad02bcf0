#include "fabric_analysis.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace fabric {

namespace {

constexpr double kDegree = static_cast<double>(EIGEN_PI) / 180.0;  // radians

[[noreturn]] void fail(const std::string& message) {
  throw std::invalid_argument("primary/fabric: " + message);
}

double ratio(double numerator, double denominator) {
  return denominator > 0.0 ? numerator / denominator : 0.0;
}

// A contact with a partner on another rank is seen there too (newton off):
// each rank contributes half of it to the per-contact sums.
double share(const ParticleContact& c) { return c.complete ? 1.0 : 0.5; }

void check_particle_index(int index, int particles, const char* what,
                          std::size_t contact) {
  if (index < 0 || index >= particles) {
    std::ostringstream m;
    m << what << " " << contact << " refers to particle " << index
      << ", the list has " << particles;
    fail(m.str());
  }
}

void check_vector(const Eigen::Vector3d& n, const char* what,
                  std::size_t contact) {
  if (!n.allFinite() || n.squaredNorm() == 0.0)
    fail(std::string(what) + " " + std::to_string(contact) +
         " has a zero or non-finite normal");
}

void check_force(double f, const char* what, std::size_t contact) {
  if (!std::isfinite(f))
    fail(std::string(what) + " " + std::to_string(contact) +
         " has a non-finite normal force");
}

void check_contacts(int particles, const std::vector<ParticleContact>& contacts,
                    const std::vector<WallContact>& walls,
                    const Options& options) {
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const ParticleContact& c = contacts[k];
    check_particle_index(c.i, particles, "particle contact", k);
    if (c.complete) {
      check_particle_index(c.j, particles, "particle contact", k);
      if (c.i == c.j)
        fail("particle contact " + std::to_string(k) +
             " joins particle " + std::to_string(c.i) + " to itself");
    }
    check_force(c.normal_force, "particle contact", k);
    check_vector(c.normal, "particle contact", k);
  }
  for (std::size_t k = 0; k < walls.size(); ++k) {
    check_particle_index(walls[k].i, particles, "wall contact", k);
    check_force(walls[k].normal_force, "wall contact", k);
    if (options.walls_in_fabric) check_vector(walls[k].normal, "wall contact", k);
  }
}

// See DirectionBin.
int direction_bin(const Eigen::Vector3d& unit_normal, int bins) {
  const double theta =
      std::acos(std::min(1.0, std::abs(unit_normal.z()))) / kDegree;
  return std::min(static_cast<int>(theta / (90.0 / bins)), bins - 1);
}

// Pruning::iterate, continuing from the `once` classification in `c`.
void prune_iteratively(const std::vector<ParticleContact>& contacts,
                       double threshold_force, const Options& options,
                       const PartnerExchange* exchange, Classification& c) {
  const int n = static_cast<int>(c.fraction.size());
  // Loaded particle-particle neighbours as a compressed adjacency list
  // (complete contacts); the incomplete ones are visited directly.
  std::vector<int> offset(n + 1, 0);
  std::vector<std::size_t> across;  // loaded incomplete contacts
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const ParticleContact& t = contacts[k];
    if (!is_loaded(t.normal_force, threshold_force)) continue;
    if (!t.complete) {
      across.push_back(k);
      continue;
    }
    ++offset[t.i + 1];
    ++offset[t.j + 1];
  }
  std::partial_sum(offset.begin(), offset.end(), offset.begin());
  std::vector<int> neighbour(offset[n]);
  std::vector<int> fill(offset.begin(), offset.end() - 1);
  for (const ParticleContact& t : contacts)
    if (t.complete && is_loaded(t.normal_force, threshold_force)) {
      neighbour[fill[t.i]++] = t.j;
      neighbour[fill[t.j]++] = t.i;
    }

  // Removing the particles found loose in one pass lowers the counts of their
  // primary neighbours; those that fall below min_contacts are the next
  // pass's loose particles. Layer by layer this is the synchronous recount of
  // compute rattlers/atom, at the cost of one visit per contact (plus one
  // visit per pass of each contact with a partner elsewhere).
  std::vector<int> remaining = c.loaded_contacts;
  std::vector<int> removed;
  for (int p = 0; p < n; ++p)
    if (c.fraction[p] == Fraction::loose) removed.push_back(p);
  std::vector<char> partner_loose, counted(contacts.size(), 0);
  while (true) {
    std::vector<int> newly_loose;
    auto lose_one = [&](int q) {
      if (c.fraction[q] == Fraction::primary &&
          --remaining[q] == options.min_contacts - 1)
        newly_loose.push_back(q);
    };
    for (int p : removed)
      for (int e = offset[p]; e < offset[p + 1]; ++e) lose_one(neighbour[e]);
    long long found = 0;
    if (exchange) {
      partner_loose.assign(contacts.size(), 0);
      exchange->partners_loose(c.fraction, partner_loose);
      if (partner_loose.size() != contacts.size())
        fail("the partner exchange returned " +
             std::to_string(partner_loose.size()) + " flags for " +
             std::to_string(contacts.size()) + " contacts");
      for (std::size_t k : across)
        if (partner_loose[k] && !counted[k]) {
          counted[k] = 1;
          lose_one(contacts[k].i);
        }
      found = exchange->global_sum(static_cast<long long>(newly_loose.size()));
    } else {
      found = static_cast<long long>(newly_loose.size());
    }
    if (found == 0) return;
    if (c.iterations == options.max_iterations) {
      c.converged = false;
      return;
    }
    for (int q : newly_loose) c.fraction[q] = Fraction::loose;
    ++c.iterations;
    removed.swap(newly_loose);
  }
}

}  // namespace

double normal_force(const Eigen::Vector3d& force_on_particle,
                    const Eigen::Vector3d& partner_to_particle) {
  const double length = partner_to_particle.norm();
  if (!(length > 0.0) || !std::isfinite(length))
    return std::numeric_limits<double>::quiet_NaN();
  return force_on_particle.dot(partner_to_particle) / length;
}

ParticleContact particle_contact(int i, int j,
                                 const Eigen::Vector3d& force_on_i,
                                 const Eigen::Vector3d& j_to_i, bool complete) {
  ParticleContact c;
  c.i = i;
  c.j = j;
  c.normal_force = normal_force(force_on_i, j_to_i);
  c.normal = -j_to_i;  // branch i -> j
  c.complete = complete;
  return c;
}

WallContact wall_contact(int i, const Eigen::Vector3d& force_on_i,
                         const Eigen::Vector3d& wall_to_i) {
  WallContact w;
  w.i = i;
  w.normal_force = normal_force(force_on_i, wall_to_i);
  w.normal = wall_to_i;
  return w;
}

double LoadThreshold::force(double mean_normal_force) const {
  return mode == Mode::absolute ? value
                                : std::max(0.0, value * mean_normal_force);
}

std::string to_string(LoadThreshold t) {
  std::ostringstream s;
  s << (t.mode == LoadThreshold::Mode::absolute ? "absolute " : "relative ")
    << t.value;
  return s.str();
}

std::string to_string(Pruning p) {
  return p == Pruning::once ? "once" : "iterate";
}

void validate(const Options& o) {
  if (!std::isfinite(o.threshold.value) || o.threshold.value < 0.0)
    fail("the load threshold must be a finite value >= 0, got " +
         to_string(o.threshold));
  if (o.min_contacts < 1)
    fail("min_contacts must be >= 1, got " + std::to_string(o.min_contacts));
  if (o.max_iterations < 1)
    fail("max_iterations must be >= 1, got " +
         std::to_string(o.max_iterations));
  if (o.direction_bins < 1)
    fail("direction_bins must be >= 1, got " +
         std::to_string(o.direction_bins));
  if (!(o.oz_tolerance >= 0.0 && o.oz_tolerance < 1.0))
    fail("oz_tolerance must lie in [0, 1), got " +
         std::to_string(o.oz_tolerance));
}

namespace {
// sign(a_zz) sqrt(2/3 a:a) of a = (15/2) D, D deviatoric
double anisotropy_scalar(const Eigen::Matrix3d& D) {
  const Eigen::Matrix3d a = 7.5 * D;
  const double size = std::sqrt(2.0 / 3.0 * a.cwiseProduct(a).sum());
  return a(2, 2) < 0.0 ? -size : size;
}
Eigen::Matrix3d deviator(const Eigen::Matrix3d& T) {
  return T - T.trace() / 3.0 * Eigen::Matrix3d::Identity();
}
}  // namespace

double fabric_anisotropy(const Eigen::Matrix3d& F) {
  if (F.trace() == 0.0) return 0.0;  // no contacts
  return anisotropy_scalar(deviator(F));
}

double force_anisotropy(const Eigen::Matrix3d& F, const Eigen::Matrix3d& Phi) {
  if (F.trace() == 0.0 || Phi.trace() == 0.0) return 0.0;
  return anisotropy_scalar(deviator(Phi) - deviator(F));
}

double NormalForceSums::mean() const { return ratio(values[1], values[0]); }

NormalForceSums normal_force_sums(const std::vector<ParticleContact>& contacts,
                                  const std::vector<WallContact>& walls) {
  NormalForceSums s;
  for (const ParticleContact& c : contacts) {
    s.values[0] += share(c);
    s.values[1] += share(c) * c.normal_force;
  }
  for (const WallContact& w : walls) {
    s.values[0] += 1.0;
    s.values[1] += w.normal_force;
  }
  return s;
}

Classification classify(int particles,
                        const std::vector<ParticleContact>& contacts,
                        const std::vector<WallContact>& walls,
                        double threshold_force, const Options& options,
                        const PartnerExchange* exchange) {
  validate(options);
  check_contacts(particles, contacts, walls, options);
  if (exchange && (!exchange->partners_loose || !exchange->global_sum))
    fail("a partner exchange needs both of its functions");
  if (options.pruning == Pruning::iterate && !exchange &&
      std::any_of(contacts.begin(), contacts.end(),
                  [](const ParticleContact& c) { return !c.complete; }))
    fail("pruning iterate needs the complete contact list (a contact with a "
         "particle of another rank cannot be recounted here)");

  Classification c;
  c.loaded_contacts.assign(particles, 0);
  for (const ParticleContact& k : contacts)
    if (is_loaded(k.normal_force, threshold_force)) {
      ++c.loaded_contacts[k.i];
      if (k.complete) ++c.loaded_contacts[k.j];
    }
  for (const WallContact& w : walls)
    if (is_loaded(w.normal_force, threshold_force)) ++c.loaded_contacts[w.i];

  // Section 3.1: a particle with fewer than three contacts is loose.
  c.fraction.resize(particles);
  std::transform(c.loaded_contacts.begin(), c.loaded_contacts.end(),
                 c.fraction.begin(), [&](int n) {
                   return n >= options.min_contacts ? Fraction::primary
                                                    : Fraction::loose;
                 });
  if (options.pruning == Pruning::iterate)
    prune_iteratively(contacts, threshold_force, options, exchange, c);
  return c;
}

FabricSums::FabricSums(int intervals, int direction_bins)
    : intervals_(intervals), bins_(direction_bins) {
  if (intervals < 0 || direction_bins < 1)
    fail("sums need >= 0 intervals and >= 1 direction bin");
  values_.assign(kContacts + kDyads + intervals * kIntervalSums +
                     direction_bins * kDirectionSums,
                 0.0);
}

int FabricSums::index(int k, Interval s) const {
  return kContacts + kDyads + k * kIntervalSums + static_cast<int>(s);
}

int FabricSums::index(int b, Direction s) const {
  return kContacts + kDyads + intervals_ * kIntervalSums + b * kDirectionSums +
         static_cast<int>(s);
}

FabricSums& FabricSums::operator+=(const FabricSums& other) {
  if (other.intervals_ != intervals_ || other.bins_ != bins_)
    fail("cannot add sums of different intervals or direction bins");
  std::transform(values_.begin(), values_.end(), other.values_.begin(),
                 values_.begin(), std::plus<>());
  return *this;
}

FabricSums accumulate(const std::vector<Particle>& particles,
                      const std::vector<ParticleContact>& contacts,
                      const std::vector<WallContact>& walls,
                      const Classification& classification,
                      double threshold_force, int intervals,
                      const Options& options) {
  validate(options);
  const int n = static_cast<int>(particles.size());
  check_contacts(n, contacts, walls, options);
  if (classification.fraction.size() != particles.size() ||
      classification.loaded_contacts.size() != particles.size())
    fail("the classification does not belong to these particles");

  FabricSums sums(intervals, options.direction_bins);
  using I = FabricSums::Interval;
  for (int p = 0; p < n; ++p) {
    const Particle& a = particles[p];
    if (a.interval < 0 || a.interval >= intervals)
      fail("particle " + std::to_string(a.id) + " is in size interval " +
           std::to_string(a.interval) + ", not in 0.." +
           std::to_string(intervals - 1));
    const bool primary = classification.fraction[p] == Fraction::primary;
    const double contacts_of_p = classification.loaded_contacts[p];
    sums.at(a.interval, I::particles) += 1.0;
    sums.at(a.interval, I::diameter) += 2.0 * a.radius;
    sums.at(a.interval, I::loaded_contacts) += contacts_of_p;
    if (primary) {
      sums.at(a.interval, I::primary_particles) += 1.0;
      sums.at(a.interval, I::primary_mass) += a.mass;
      sums.at(a.interval, I::primary_loaded_contacts) += contacts_of_p;
    } else {
      sums.at(a.interval, I::loose_mass) += a.mass;
    }
  }

  using C = FabricSums::Contact;
  using D = FabricSums::Direction;
  // Figs. 15-16 and the fabric tensor F = sum n n^T / N_c.
  auto add_to_fabric = [&](double weight, double force,
                           const Eigen::Vector3d& normal) {
    const Eigen::Vector3d u = normal.normalized();
    const Eigen::Matrix3d dyad = u * u.transpose();
    sums[C::fabric_contacts] += weight;
    sums[C::fabric_normal_force] += weight * force;
    sums.normal_dyads() += weight * dyad;
    sums.force_dyads() += weight * force * dyad;
    const int b = direction_bin(u, options.direction_bins);
    sums.at(b, D::contacts) += weight;
    sums.at(b, D::normal_force) += weight * force;
  };

  for (const ParticleContact& c : contacts) {
    const double w = share(c);
    sums[C::contacts] += w;
    sums[C::normal_force] += w * c.normal_force;
    if (!is_loaded(c.normal_force, threshold_force)) continue;
    sums[C::loaded_particle_contacts] += w;
    sums[C::loaded_normal_force] += w * c.normal_force;
    // Fig. 14 averages per particle end: each end adds the whole force.
    sums.at(particles[c.i].interval, I::loaded_normal_force) += c.normal_force;
    if (c.complete)
      sums.at(particles[c.j].interval, I::loaded_normal_force) += c.normal_force;
    add_to_fabric(w, c.normal_force, c.normal);
  }
  for (const WallContact& c : walls) {
    sums[C::contacts] += 1.0;
    sums[C::normal_force] += c.normal_force;
    if (!is_loaded(c.normal_force, threshold_force)) continue;
    sums[C::loaded_wall_contacts] += 1.0;
    sums[C::loaded_normal_force] += c.normal_force;
    sums.at(particles[c.i].interval, I::loaded_normal_force) += c.normal_force;
    if (options.walls_in_fabric) add_to_fabric(1.0, c.normal_force, c.normal);
  }
  return sums;
}

namespace {

void check_interval_diameters(const std::vector<double>& interval_diameters,
                              int intervals) {
  if (interval_diameters.empty()) return;
  if (static_cast<int>(interval_diameters.size()) != intervals)
    fail("got " + std::to_string(interval_diameters.size()) +
         " interval diameters for " + std::to_string(intervals) + " intervals");
  // The overlapping zone is found by interval order, which must be size order.
  if (!std::is_sorted(interval_diameters.begin(), interval_diameters.end()))
    fail("interval diameters must be given finest first");
}

// The counts, mass shares and coordination numbers of the whole specimen
// (Figs. 11-12); returns the total mass, which the interval rows divide by.
double summarise_particles(const FabricSums& sums, FabricSummary& s) {
  using I = FabricSums::Interval;
  double primary_particles = 0, primary_mass = 0, mass = 0;
  double loaded_contacts_on_particles = 0, loaded_contacts_on_primary = 0;
  for (int k = 0; k < sums.intervals(); ++k) {
    s.particles += sums.at(k, I::particles);
    primary_particles += sums.at(k, I::primary_particles);
    primary_mass += sums.at(k, I::primary_mass);
    mass += sums.at(k, I::primary_mass) + sums.at(k, I::loose_mass);
    loaded_contacts_on_particles += sums.at(k, I::loaded_contacts);
    loaded_contacts_on_primary += sums.at(k, I::primary_loaded_contacts);
  }
  s.loose_particles = s.particles - primary_particles;
  s.loose_percent_by_number = 100.0 * ratio(s.loose_particles, s.particles);
  s.primary_percent_by_mass = 100.0 * ratio(primary_mass, mass);
  s.coordination = ratio(loaded_contacts_on_particles, s.particles);
  s.primary_coordination =
      ratio(loaded_contacts_on_primary, primary_particles);
  return mass;
}

// The contact counts, mean forces, fabric tensors and their anisotropies.
void summarise_contacts(const FabricSums& sums, FabricSummary& s) {
  using C = FabricSums::Contact;
  s.contacts = sums[C::contacts];
  s.loaded_particle_contacts = sums[C::loaded_particle_contacts];
  s.loaded_wall_contacts = sums[C::loaded_wall_contacts];
  s.loaded_contacts = s.loaded_particle_contacts + s.loaded_wall_contacts;
  s.mean_normal_force = ratio(sums[C::normal_force], s.contacts);
  s.mean_loaded_normal_force =
      ratio(sums[C::loaded_normal_force], s.loaded_contacts);
  if (sums[C::fabric_contacts] > 0.0)
    s.fabric_tensor = sums.normal_dyads() / sums[C::fabric_contacts];
  if (sums[C::fabric_normal_force] > 0.0)
    s.force_fabric_tensor = sums.force_dyads() / sums[C::fabric_normal_force];
  s.fabric_anisotropy = fabric_anisotropy(s.fabric_tensor);
  s.force_anisotropy = force_anisotropy(s.fabric_tensor, s.force_fabric_tensor);
}

// Interval k's row (Figs. 13-14, 17-19), with the caller's diameter if given.
IntervalSummary summarise_interval(const FabricSums& sums, int k,
                                   const std::vector<double>& interval_diameters,
                                   double mass) {
  using I = FabricSums::Interval;
  IntervalSummary row;
  const double n = sums.at(k, I::particles);
  const double pm = sums.at(k, I::primary_mass);
  const double lm = sums.at(k, I::loose_mass);
  row.particles = n;
  row.measured_diameter = ratio(sums.at(k, I::diameter), n);
  row.diameter =
      interval_diameters.empty() ? row.measured_diameter : interval_diameters[k];
  row.mass_percent = 100.0 * ratio(pm + lm, mass);
  row.primary_mass_percent = 100.0 * ratio(pm, mass);
  row.loose_mass_percent = 100.0 * ratio(lm, mass);
  row.primary_percent_of_interval = 100.0 * ratio(pm, pm + lm);
  row.loaded_contacts_per_particle = ratio(sums.at(k, I::loaded_contacts), n);
  row.normal_force_per_loaded_contact = ratio(
      sums.at(k, I::loaded_normal_force), sums.at(k, I::loaded_contacts));
  return row;
}

// Finds the bounds of both overlapping zones (see OverlappingZone).
void find_zone_bounds(const FabricSums& sums, double oz_tolerance,
                      OverlappingZone& oz, OverlappingZone& tz) {
  using I = FabricSums::Interval;
  for (int k = 0; k < sums.intervals(); ++k) {
    const double n = sums.at(k, I::particles);
    const double pm = sums.at(k, I::primary_mass);
    const double lm = sums.at(k, I::loose_mass);
    // Particle counts, not masses, decide the bounds: they are exact integers.
    if (sums.at(k, I::primary_particles) > 0.0 && oz.lower_interval < 0)
      oz.lower_interval = k;
    if (n - sums.at(k, I::primary_particles) > 0.0) oz.upper_interval = k;
    // the tolerant zone: by mass share, and only above the tolerance (at
    // t = 0 the same as the counts above: a mass is positive with a grain)
    if (pm > oz_tolerance * (pm + lm) && pm > 0.0 && tz.lower_interval < 0)
      tz.lower_interval = k;
    if (lm > oz_tolerance * (pm + lm) && lm > 0.0) tz.upper_interval = k;
  }
}

// r1, r2 and the mass of a zone whose bounds are known.
void measure_zone(const std::vector<IntervalSummary>& intervals,
                  OverlappingZone& z) {
  if (z.lower_interval >= 0) z.r1 = intervals[z.lower_interval].diameter;
  if (z.upper_interval >= 0) z.r2 = intervals[z.upper_interval].diameter;
  if (z.lower_interval >= 0 && z.upper_interval >= z.lower_interval)
    for (int k = z.lower_interval; k <= z.upper_interval; ++k)
      z.mass_percent += intervals[k].mass_percent;
}

std::vector<DirectionBin> summarise_directions(const FabricSums& sums) {
  using C = FabricSums::Contact;
  using D = FabricSums::Direction;
  const int bins = sums.direction_bins();
  std::vector<DirectionBin> directions(bins);
  for (int b = 0; b < bins; ++b) {
    DirectionBin& d = directions[b];
    d.theta_lo = 90.0 * b / bins;
    d.theta_hi = 90.0 * (b + 1) / bins;
    d.contacts = sums.at(b, D::contacts);
    d.contact_fraction = ratio(d.contacts, sums[C::fabric_contacts]);
    const double solid_angle_share =
        std::cos(d.theta_lo * kDegree) - std::cos(d.theta_hi * kDegree);
    d.density_vs_isotropic = ratio(d.contact_fraction, solid_angle_share);
    d.mean_normal_force = ratio(sums.at(b, D::normal_force), d.contacts);
  }
  return directions;
}

}  // namespace

FabricSummary finalise(const FabricSums& sums,
                       const std::vector<double>& interval_diameters,
                       double oz_tolerance) {
  if (!(oz_tolerance >= 0.0 && oz_tolerance < 1.0))
    fail("oz_tolerance must lie in [0, 1), got " + std::to_string(oz_tolerance));
  const int m = sums.intervals();
  check_interval_diameters(interval_diameters, m);

  FabricSummary s;
  const double mass = summarise_particles(sums, s);
  summarise_contacts(sums, s);
  s.intervals.resize(m);
  for (int k = 0; k < m; ++k)
    s.intervals[k] = summarise_interval(sums, k, interval_diameters, mass);
  find_zone_bounds(sums, oz_tolerance, s.overlapping_zone,
                   s.overlapping_zone_tolerant);
  measure_zone(s.intervals, s.overlapping_zone);
  measure_zone(s.intervals, s.overlapping_zone_tolerant);
  s.directions = summarise_directions(sums);
  return s;
}

Analysis analyse(const std::vector<Particle>& particles,
                 const std::vector<ParticleContact>& contacts,
                 const std::vector<WallContact>& walls, int intervals,
                 const Options& options,
                 const std::vector<double>& interval_diameters) {
  validate(options);
  Analysis a;
  a.threshold_force =
      options.threshold.force(normal_force_sums(contacts, walls).mean());
  a.classification = classify(static_cast<int>(particles.size()), contacts,
                              walls, a.threshold_force, options);
  a.sums = accumulate(particles, contacts, walls, a.classification,
                      a.threshold_force, intervals, options);
  a.summary = finalise(a.sums, interval_diameters, options.oz_tolerance);
  return a;
}

}  // namespace fabric
