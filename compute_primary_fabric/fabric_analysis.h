// Primary fabric analysis of a compacted granular specimen (paper, sections
// 2.4 and 3): which particles carry the load, how the load is spread over the
// size intervals, and how the loaded contacts are oriented.
//
// Plain C++ with Eigen, no LIGGGHTS include. The analysis runs in three steps
// so that an MPI adapter can feed each rank's own particles and contacts and
// reduce plain arrays of doubles with MPI_SUM in between:
//
//   NormalForceSums s = normal_force_sums(contacts, walls);   // rank-local
//   MPI_Allreduce(s.values)                                   // 2 doubles
//   double threshold = options.threshold.force(s.mean());
//   Classification c = classify(particles.size(), contacts, walls,
//                               threshold, options);          // rank-local*
//   FabricSums sums = accumulate(particles, contacts, walls, c, threshold,
//                                intervals, options);         // rank-local
//   MPI_Allreduce(sums.data(), sums.size())                   // one call
//   FabricSummary summary = finalise(sums, interval_diameters);
//
// (*) `once` pruning is rank-local; `iterate` passes the partners' classes
// between the ranks through a PartnerExchange (forward communication and a
// sum over the ranks in the adapter); the loop itself is classify()'s.
// analyse() runs the three steps on one complete data set.
//
// Contacts across ranks follow LIGGGHTS' `newton off` convention: a contact
// whose partner is a ghost is listed on both ranks, each time with its own
// particle as `i` and `complete = false`. It then counts for particle i only
// and enters the per-contact sums with weight 1/2, so the two halves add up
// to one contact after the reduction.
#ifndef FABRIC_FABRIC_ANALYSIS_H
#define FABRIC_FABRIC_ANALYSIS_H

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "min_contacts.h"

namespace fabric {

struct Particle {
  long long id = 0;     // atom tag; only named in error messages
  double radius = 0.0;
  double mass = 0.0;
  int interval = 0;     // size interval, 0 = finest (the paper's 20 intervals)
};

// Normal forces are signed, compressive positive: an attractive force (a
// damping artefact at the end of a collision) is never a loaded contact.
// Build contacts with particle_contact() and wall_contact() below, which take
// the normal force from normal_force(): one definition for both kinds.
struct ParticleContact {
  int i = -1;
  int j = -1;               // ignored when !complete (partner on another rank)
  double normal_force = 0.0;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // branch direction i->j;
                            // its sign is irrelevant, it is normalised here
  bool complete = true;     // both particles are in this particle list
};

struct WallContact {
  int i = -1;
  double normal_force = 0.0;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // the contact normal
                            // (wall to particle); its sign is irrelevant
};

// THE normal force of a contact, particle or wall: the force on the particle
// projected onto the unit contact normal that points from the partner (the
// other particle's centre, the wall's contact point) to the particle,
//   f_n = F . n / |n|,
// positive when the contact pushes the particle away (compression). A
// tangential force, however large, adds nothing. A zero or non-finite
// normal gives NaN, which classify() rejects.
double normal_force(const Eigen::Vector3d& force_on_particle,
                    const Eigen::Vector3d& partner_to_particle);

// A contact of particle i with particle j (j: index in the particle list;
// ignored when !complete), from the force on i and the vector from j's
// centre to i's centre.
ParticleContact particle_contact(int i, int j,
                                 const Eigen::Vector3d& force_on_i,
                                 const Eigen::Vector3d& j_to_i, bool complete);
// A contact of particle i with a wall, from the force on i and the vector
// from the wall's contact point to i's centre.
WallContact wall_contact(int i, const Eigen::Vector3d& force_on_i,
                         const Eigen::Vector3d& wall_to_i);

// Whether a contact that LIGGGHTS reports is a contact here: the particle
// overlaps its partner, i.e. the distance from the partner (the other
// particle's centre, the wall's contact point) to the particle's centre is
// strictly below the contact distance (r_i + r_j, or r_i for a wall). The pair
// style already applies this test (rsq < radsum^2); LIGGGHTS' wall fixes also
// report a particle that exactly touches a wall (zero overlap, zero force), as
// a packing leaves its grains against the container, so the adapter asks this
// of every wall contact: one contact definition for particles and walls.
inline bool overlaps(double centre_distance, double contact_distance) {
  return centre_distance < contact_distance;
}

// The load threshold of a loaded contact.
//   absolute F: F in force units.
//   relative f: f times the mean normal force of all contacts (particle and
//               wall), so it follows the applied stress and the unit system.
// Default relative 1e-3. The paper counts every contact that carries force
// (`relative 0` is that literal rule). After compaction under zero gravity the
// loose particles still graze their neighbours with overlaps left over from
// their last rebound; those forces are orders of magnitude below the mean and
// would decide a particle's class by numerical residue. A contact below a
// thousandth of the mean force transfers no noticeable stress, so the default
// removes the residue without touching the force chains; being relative, it
// needs no change with the lid stress or the units.
struct LoadThreshold {
  enum class Mode { absolute, relative };
  Mode mode = Mode::relative;
  double value = 1e-3;

  static LoadThreshold absolute(double force) { return {Mode::absolute, force}; }
  static LoadThreshold relative(double fraction) { return {Mode::relative, fraction}; }
  // The threshold force; never negative, so a loaded contact always pushes.
  double force(double mean_normal_force) const;
};
std::string to_string(LoadThreshold t);  // "absolute 5" / "relative 0.001"

// THE definition of a loaded contact, for particle and wall contacts alike:
// its normal force (see normal_force()) strictly above the threshold force;
// a contact exactly at the threshold is not loaded.
inline bool is_loaded(double normal_force, double threshold_force) {
  return normal_force > threshold_force;
}
inline bool is_loaded(const Eigen::Vector3d& force_on_particle,
                      const Eigen::Vector3d& partner_to_particle,
                      double threshold_force) {
  return is_loaded(normal_force(force_on_particle, partner_to_particle),
                   threshold_force);
}

// once:    the paper's rule, one count of loaded contacts per particle.
// iterate: loose particles are removed and their neighbours recounted until
//          nothing changes (as LAMMPS' compute rattlers/atom): what remains is
//          a network in which every particle has min_contacts loaded contacts
//          with other remaining particles or walls.
enum class Pruning { once, iterate };
std::string to_string(Pruning p);

struct Options {
  LoadThreshold threshold;
  int min_contacts = kMinContacts;  // fewer loaded contacts: loose (3.1)
  Pruning pruning = Pruning::once;
  int max_iterations = 1000;     // iterate only: recount passes at most
  int direction_bins = 9;        // polar-angle bins of 90/M degrees
  bool walls_in_fabric = false;  // wall normals are the box axes; they say
                                 // nothing about the soil's own fabric
  double oz_tolerance = 0.1;     // the tolerant overlapping zone: a class
                                 // counts in an interval above this share
                                 // of the interval's mass (0 <= t < 1)
};
// Throws std::invalid_argument naming the bad value.
void validate(const Options& options);

// Step 1: the mean normal force that a relative threshold refers to.
struct NormalForceSums {
  std::array<double, 2> values{};  // {contacts, sum of normal forces}
  double mean() const;             // 0 without contacts
};
NormalForceSums normal_force_sums(const std::vector<ParticleContact>& contacts,
                                  const std::vector<WallContact>& walls);

// Step 2: per particle, the number of loaded contacts (particles and walls,
// every loaded contact whatever the partner's class) and its fraction.
enum class Fraction : std::uint8_t { loose = 0, primary = 1 };

struct Classification {
  std::vector<int> loaded_contacts;
  std::vector<Fraction> fraction;
  int iterations = 0;     // iterate: recount passes that found new loose ones
  bool converged = true;  // iterate: false when max_iterations stopped it
};
// `prune iterate` over particles spread across MPI ranks. A contact whose
// partner is not in this rank's particle list (complete == false) learns the
// partner's class from `partners_loose`, and each pass ends by the global
// count of new loose particles, so that every rank runs the same passes and
// the result is that of one rank holding everything.
struct PartnerExchange {
  // Collective, called once per pass on every rank: given the current class
  // of every particle of this rank, set partner_loose[k] (sized like the
  // contact list) to 1 for every incomplete contact k whose partner is
  // loose, 0 otherwise. Entries of complete contacts are ignored.
  std::function<void(const std::vector<Fraction>& fraction,
                     std::vector<char>& partner_loose)>
      partners_loose;
  // Collective: the sum of `local` over all ranks.
  std::function<long long(long long local)> global_sum;
};

// Throws std::invalid_argument on an index out of range, a non-finite force,
// a zero normal, or an incomplete contact under `iterate` without `exchange`.
Classification classify(int particles,
                         const std::vector<ParticleContact>& contacts,
                         const std::vector<WallContact>& walls,
                         double threshold_force, const Options& options,
                         const PartnerExchange* exchange = nullptr);

// Step 3: additive sums. Everything global is a sum over particles or
// contacts, stored in one array so that a reduction is one MPI_SUM call.
class FabricSums {
 public:
  enum class Contact {
    contacts,                 // all contacts, particle and wall
    normal_force,             // their summed normal force
    loaded_particle_contacts,
    loaded_wall_contacts,
    loaded_normal_force,      // summed over all loaded contacts
    fabric_contacts,          // the loaded contacts in the fabric tensor
    fabric_normal_force,
    count
  };
  enum class Interval {       // sums over the particles of one size interval
    particles,
    primary_particles,
    primary_mass,
    loose_mass,
    diameter,                 // sum of 2r
    loaded_contacts,
    primary_loaded_contacts,  // of its primary particles only
    loaded_normal_force,      // over the loaded contacts of its particles
    count
  };
  enum class Direction { contacts, normal_force, count };

  FabricSums(int intervals, int direction_bins);

  int intervals() const { return intervals_; }
  int direction_bins() const { return bins_; }
  double& operator[](Contact c) { return values_[index(c)]; }
  double operator[](Contact c) const { return values_[index(c)]; }
  double& at(int interval, Interval s) { return values_[index(interval, s)]; }
  double at(int interval, Interval s) const { return values_[index(interval, s)]; }
  double& at(int bin, Direction s) { return values_[index(bin, s)]; }
  double at(int bin, Direction s) const { return values_[index(bin, s)]; }
  // Sum n n^T and sum f n n^T over the contacts of the fabric tensor.
  using Dyads = Eigen::Map<Eigen::Matrix3d>;
  using ConstDyads = Eigen::Map<const Eigen::Matrix3d>;
  Dyads normal_dyads() { return Dyads(&values_[kContacts]); }
  ConstDyads normal_dyads() const { return ConstDyads(&values_[kContacts]); }
  Dyads force_dyads() { return Dyads(&values_[kContacts + 9]); }
  ConstDyads force_dyads() const { return ConstDyads(&values_[kContacts + 9]); }

  double* data() { return values_.data(); }
  int size() const { return static_cast<int>(values_.size()); }
  FabricSums& operator+=(const FabricSums& other);  // same layout or throws

 private:
  // Layout: contact sums, the two dyad sums (3x3 each), interval rows,
  // direction bins.
  static constexpr int kContacts = static_cast<int>(Contact::count);
  static constexpr int kDyads = 2 * 9;
  static constexpr int kIntervalSums = static_cast<int>(Interval::count);
  static constexpr int kDirectionSums = static_cast<int>(Direction::count);
  int index(Contact c) const { return static_cast<int>(c); }
  int index(int k, Interval s) const;
  int index(int b, Direction s) const;

  int intervals_, bins_;
  std::vector<double> values_;
};

// Throws std::invalid_argument on a particle interval outside 0..intervals-1
// or inputs that classify() would reject.
FabricSums accumulate(const std::vector<Particle>& particles,
                      const std::vector<ParticleContact>& contacts,
                      const std::vector<WallContact>& walls,
                      const Classification& classification,
                      double threshold_force, int intervals,
                      const Options& options);

// Step 4: percentages and means. Every figure is defined without data: a
// ratio whose denominator is zero is 0, the tensors are then zero matrices.
struct IntervalSummary {
  double diameter = 0;               // representative (caller's or measured)
  double measured_diameter = 0;      // mean 2r of its particles
  double particles = 0;
  double mass_percent = 0;           // of the total mass: the PSD
  double primary_mass_percent = 0;   // of the total mass (PFD, Figs. 17-18)
  double loose_mass_percent = 0;     // of the total mass (LPD, Figs. 17-18)
  double primary_percent_of_interval = 0;    // Fig. 19
  double loaded_contacts_per_particle = 0;   // Fig. 13
  double normal_force_per_loaded_contact = 0;  // Fig. 14
};

// Polar angle theta = acos(|n_z|) from the z axis (the loading direction), so
// n and -n fall into the same bin; bin b holds [b, b+1) * 90/M degrees, the
// last bin includes 90. Equal angles, not equal solid angles: an isotropic
// fabric fills bin b in proportion to cos(theta_lo) - cos(theta_hi), which
// density_vs_isotropic divides out (Figs. 15-16).
struct DirectionBin {
  double theta_lo = 0, theta_hi = 0;  // degrees
  double contacts = 0;
  double contact_fraction = 0;
  double density_vs_isotropic = 0;    // contact_fraction / solid-angle share
  double mean_normal_force = 0;
};

// Table 2. r1 is the finest interval holding primary fabric, r2 the coarsest
// holding loose particles; the overlapping zone (OZ) is the mass of all
// intervals from r1 to r2. When r1 is coarser than r2 the two fractions do
// not overlap and the OZ is 0 (a sharp delimitation point). An interval
// index is -1 and its diameter 0 when there is no such particle.
//
// With a tolerance t > 0 an interval counts as holding primary fabric (for
// r1) only when its primary mass exceeds t of the interval's mass, and as
// holding loose particles (for r2) only when its loose mass does: with the
// paper's rule (t = 0) one loose coarse grain makes r2 the coarsest interval
// and the OZ the whole soil.
struct OverlappingZone {
  int lower_interval = -1, upper_interval = -1;
  double r1 = 0, r2 = 0;  // representative diameters (compute primary/fabric
                          // reports half of each: radii, as the paper's Table 2)
  double mass_percent = 0;
};

// Anisotropy of a trace-1 fabric tensor F (the field's usual scalar, e.g.
// Ouadfel & Rothenburg 2001): a = (15/2) dev(F), the coefficients of the
// contact-normal density E(n) = (1 + a_ij n_i n_j) / (4 pi); the scalar is
// sign(a_zz) sqrt(2/3 a_ij a_ij), which is a_zz for a distribution
// symmetric about z, (1 + a/2 (3 cos^2 theta - 1)) / (4 pi). Positive when
// the contacts gather along z, the loading axis of the oedometer.
double fabric_anisotropy(const Eigen::Matrix3d& F);
// Force anisotropy a_n: the same scalar of (15/2) (dev(Phi) - dev(F)), Phi
// the force-weighted fabric tensor (trace 1): the directional variation of
// the mean normal force, f(n) = f0 (1 + a^n_ij n_i n_j), to first order.
double force_anisotropy(const Eigen::Matrix3d& F, const Eigen::Matrix3d& Phi);

struct FabricSummary {
  double particles = 0;
  double loose_particles = 0;
  double loose_percent_by_number = 0;      // Fig. 11
  double primary_percent_by_mass = 0;      // Fig. 12
  double coordination = 0;                 // loaded contacts per particle
  double primary_coordination = 0;         // same, primary fabric only
  double contacts = 0;
  double loaded_contacts = 0;
  double loaded_particle_contacts = 0;
  double loaded_wall_contacts = 0;
  double mean_normal_force = 0;            // over all contacts
  double mean_loaded_normal_force = 0;
  OverlappingZone overlapping_zone;           // the paper's rule (t = 0)
  OverlappingZone overlapping_zone_tolerant;  // Options::oz_tolerance
  double fabric_anisotropy = 0;               // a_c of fabric_tensor
  double force_anisotropy = 0;                // a_n
  Eigen::Matrix3d fabric_tensor = Eigen::Matrix3d::Zero();        // trace 1
  Eigen::Matrix3d force_fabric_tensor = Eigen::Matrix3d::Zero();  // trace 1
  std::vector<IntervalSummary> intervals;
  std::vector<DirectionBin> directions;
};

// interval_diameters: one representative diameter per interval, finest first
// (non-decreasing, else std::invalid_argument), or empty to use the measured
// mean diameter of each interval's particles.
// oz_tolerance: that of Options (the tolerant overlapping zone).
FabricSummary finalise(const FabricSums& sums,
                       const std::vector<double>& interval_diameters = {},
                       double oz_tolerance = Options().oz_tolerance);

// All steps on one rank's complete data.
struct Analysis {
  double threshold_force = 0;
  Classification classification;
  FabricSums sums{0, 1};
  FabricSummary summary;
};
Analysis analyse(const std::vector<Particle>& particles,
                 const std::vector<ParticleContact>& contacts,
                 const std::vector<WallContact>& walls, int intervals,
                 const Options& options = {},
                 const std::vector<double>& interval_diameters = {});

}  // namespace fabric

#endif
