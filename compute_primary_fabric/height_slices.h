// The primary fabric by height (compute primary/fabric, keyword slices N):
// the specimen cut into N slices of equal height along z, the loading axis,
// from the lowest grain's bottom to the highest grain's top. A grain belongs
// to the slice of its centre. The classification stays the whole specimen's
// (fabric_analysis.h, classify()); a slice only selects which grains enter
// its figures: their mass, their classes, their loaded contacts, and the
// fabric tensors of those contacts.
//
// A loaded particle contact enters the fabric of the slices of its two
// grains, half for each end (a contact between two slices counts half in
// each; with the `newton off` halves of fabric_analysis.h, each rank adds
// the half of its own grain). So the slices' contacts add up to the whole
// specimen's, and one slice gives the whole specimen's figures. A wall
// contact (with walls_in_fabric) enters its grain's slice whole.
//
// Plain C++ with Eigen, no LIGGGHTS include; as fabric_analysis.h, in steps
// that an MPI adapter joins by reductions:
//
//   HeightExtent e = height_extent(z, particles);        // rank-local
//   MPI_Allreduce(e.bottom MIN, e.top MAX)
//   HeightSlices slices(e, N);
//   SliceSums s = accumulate_slices(particles, z, contacts, walls,
//                                   classification, threshold, slices,
//                                   options);            // rank-local
//   MPI_Allreduce(s.data(), s.size(), MPI_SUM)
//   std::vector<SliceSummary> rows = finalise_slices(total, slices);
#ifndef FABRIC_HEIGHT_SLICES_H
#define FABRIC_HEIGHT_SLICES_H

#include <vector>

#include "fabric_analysis.h"

namespace fabric {

// The grains' extent along z: the lowest bottom (z - r) and the highest top
// (z + r). Without grains bottom = +inf and top = -inf, so that MPI_MIN and
// MPI_MAX over the ranks give the extent of all grains.
struct HeightExtent {
  double bottom, top;
};
// z[p]: the height of particle p's centre (sized like particles, else
// std::invalid_argument).
HeightExtent height_extent(const std::vector<Particle>& particles,
                           const std::vector<double>& z);

// N slices of equal height from bottom to top; slice k (from 0, the lowest)
// holds heights in [bottom + k h, bottom + (k+1) h), the last one also its
// top. Without grains (top < bottom) every height is outside.
class HeightSlices {
 public:
  // Throws std::invalid_argument for count < 1 or a non-finite extent with
  // grains.
  HeightSlices(HeightExtent extent, int count);
  int count() const { return count_; }
  bool empty() const { return !(top_ >= bottom_); }
  double lower(int k) const;   // bounds of slice k
  double upper(int k) const;
  // The slice of height z, -1 outside [bottom, top] (or without grains).
  int of(double z) const;

 private:
  double bottom_, top_;
  int count_;
};

// Additive sums per slice, one array for one MPI_SUM.
class SliceSums {
 public:
  enum class Sum {
    particles,
    loose_particles,
    mass,
    primary_mass,
    loaded_contacts,        // summed over its grains (particles and walls)
    fabric_contacts,        // contact ends in its fabric tensors
    fabric_normal_force,
    count
  };
  explicit SliceSums(int slices);

  int slices() const { return slices_; }
  double& at(int slice, Sum s) { return values_[index(slice) + static_cast<int>(s)]; }
  double at(int slice, Sum s) const { return values_[index(slice) + static_cast<int>(s)]; }
  // Sum n n^T and sum f n n^T over the contact ends of slice k.
  Eigen::Map<Eigen::Matrix3d> normal_dyads(int k) {
    return Eigen::Map<Eigen::Matrix3d>(&values_[index(k) + kSums]);
  }
  Eigen::Map<const Eigen::Matrix3d> normal_dyads(int k) const {
    return Eigen::Map<const Eigen::Matrix3d>(&values_[index(k) + kSums]);
  }
  Eigen::Map<Eigen::Matrix3d> force_dyads(int k) {
    return Eigen::Map<Eigen::Matrix3d>(&values_[index(k) + kSums + 9]);
  }
  Eigen::Map<const Eigen::Matrix3d> force_dyads(int k) const {
    return Eigen::Map<const Eigen::Matrix3d>(&values_[index(k) + kSums + 9]);
  }

  double* data() { return values_.data(); }
  int size() const { return static_cast<int>(values_.size()); }

 private:
  static constexpr int kSums = static_cast<int>(Sum::count);
  static constexpr int kPerSlice = kSums + 18;
  int index(int k) const;
  int slices_;
  std::vector<double> values_;
};

// The sums of this rank's grains (z as for height_extent), with the
// classification and threshold of the whole specimen. A grain at a
// non-finite height (a broken state, which the compute warns of) is in no
// slice. Throws std::invalid_argument on inputs that accumulate() would
// reject, or on a grain whose finite centre lies outside the slices' extent.
SliceSums accumulate_slices(const std::vector<Particle>& particles,
                            const std::vector<double>& z,
                            const std::vector<ParticleContact>& contacts,
                            const std::vector<WallContact>& walls,
                            const Classification& classification,
                            double threshold_force, const HeightSlices& slices,
                            const Options& options);

// One slice's figures. A ratio of nothing (a slice without grains or
// without loaded contacts) is 0, as in finalise().
struct SliceSummary {
  double lower = 0, upper = 0;     // its heights (z)
  double particles = 0;
  double mass_percent = 0;         // of the whole group's mass
  double primary_percent = 0;      // primary fabric, % of the slice's mass
  double loose_percent_by_number = 0;
  double coordination = 0;         // loaded contacts per grain of the slice
  double fabric_contacts = 0;      // loaded contacts (ends) in its tensors
  double fabric_anisotropy = 0;    // a_c of its tensor F
  double force_anisotropy = 0;     // a_n of its Phi against F
  Eigen::Matrix3d fabric_tensor = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d force_fabric_tensor = Eigen::Matrix3d::Zero();
};
std::vector<SliceSummary> finalise_slices(const SliceSums& sums,
                                          const HeightSlices& slices);

}  // namespace fabric

#endif
