#include "fabric_outputs.h"

namespace fabric {

namespace {

double vector_value(VectorEntry e, const FabricSummary& s,
                    double threshold_force, int prune_passes) {
  const Eigen::Matrix3d& F = s.fabric_tensor;
  const Eigen::Matrix3d& P = s.force_fabric_tensor;
  switch (e) {
    case VectorEntry::particles: return s.particles;
    case VectorEntry::loose_particles: return s.loose_particles;
    case VectorEntry::loose_percent_by_number: return s.loose_percent_by_number;
    case VectorEntry::primary_percent_by_mass: return s.primary_percent_by_mass;
    case VectorEntry::coordination: return s.coordination;
    case VectorEntry::primary_coordination: return s.primary_coordination;
    // The core's OZ bounds are diameters; the compute reports radii.
    case VectorEntry::r1: return 0.5 * s.overlapping_zone.r1;
    case VectorEntry::r2: return 0.5 * s.overlapping_zone.r2;
    case VectorEntry::overlapping_zone_percent:
      return s.overlapping_zone.mass_percent;
    case VectorEntry::contacts: return s.contacts;
    case VectorEntry::loaded_contacts: return s.loaded_contacts;
    case VectorEntry::mean_normal_force: return s.mean_normal_force;
    case VectorEntry::threshold_force: return threshold_force;
    case VectorEntry::prune_passes: return prune_passes;
    case VectorEntry::fabric_xx: return F(0, 0);
    case VectorEntry::fabric_yy: return F(1, 1);
    case VectorEntry::fabric_zz: return F(2, 2);
    case VectorEntry::fabric_xy: return F(0, 1);
    case VectorEntry::fabric_xz: return F(0, 2);
    case VectorEntry::fabric_yz: return F(1, 2);
    case VectorEntry::force_fabric_xx: return P(0, 0);
    case VectorEntry::force_fabric_yy: return P(1, 1);
    case VectorEntry::force_fabric_zz: return P(2, 2);
    case VectorEntry::force_fabric_xy: return P(0, 1);
    case VectorEntry::force_fabric_xz: return P(0, 2);
    case VectorEntry::force_fabric_yz: return P(1, 2);
    case VectorEntry::fabric_anisotropy: return s.fabric_anisotropy;
    case VectorEntry::force_anisotropy: return s.force_anisotropy;
    case VectorEntry::r1_tolerant: return 0.5 * s.overlapping_zone_tolerant.r1;
    case VectorEntry::r2_tolerant: return 0.5 * s.overlapping_zone_tolerant.r2;
    case VectorEntry::overlapping_zone_tolerant_percent:
      return s.overlapping_zone_tolerant.mass_percent;
    case VectorEntry::count: break;
  }
  return 0.0;
}

double column_value(ArrayColumn c, const IntervalSummary& r) {
  switch (c) {
    case ArrayColumn::diameter: return r.diameter;
    case ArrayColumn::mass_percent: return r.mass_percent;
    case ArrayColumn::primary_percent_of_interval:
      return r.primary_percent_of_interval;
    case ArrayColumn::loose_mass_percent: return r.loose_mass_percent;
    case ArrayColumn::loaded_contacts_per_particle:
      return r.loaded_contacts_per_particle;
    case ArrayColumn::normal_force_per_loaded_contact:
      return r.normal_force_per_loaded_contact;
    case ArrayColumn::primary_mass_percent: return r.primary_mass_percent;
    case ArrayColumn::particles: return r.particles;
    case ArrayColumn::count: break;
  }
  return 0.0;
}

double slice_value(SliceEntry e, const SliceSummary& r) {
  switch (e) {
    case SliceEntry::slice_bottom: return r.lower;
    case SliceEntry::slice_top: return r.upper;
    case SliceEntry::slice_particles: return r.particles;
    case SliceEntry::slice_mass_percent: return r.mass_percent;
    case SliceEntry::slice_primary_percent: return r.primary_percent;
    case SliceEntry::slice_loose_percent_by_number:
      return r.loose_percent_by_number;
    case SliceEntry::slice_coordination: return r.coordination;
    case SliceEntry::slice_fabric_contacts: return r.fabric_contacts;
    case SliceEntry::slice_fabric_anisotropy: return r.fabric_anisotropy;
    case SliceEntry::slice_force_anisotropy: return r.force_anisotropy;
    case SliceEntry::count: break;
  }
  return 0.0;
}

}  // namespace

std::vector<double> global_vector(const FabricSummary& s,
                                  double threshold_force, int prune_passes,
                                  int direction_bins,
                                  const std::vector<SliceSummary>& slices) {
  const int nslices = static_cast<int>(slices.size());
  std::vector<double> v(vector_size(direction_bins, nslices), 0.0);
  for (int e = 0; e < kVectorFixedEntries; ++e)
    v[e] = vector_value(static_cast<VectorEntry>(e), s, threshold_force,
                        prune_passes);
  for (int b = 0; b < direction_bins; ++b)
    if (b < static_cast<int>(s.directions.size())) {
      v[kVectorFixedEntries + 2 * b] = s.directions[b].contact_fraction;
      v[kVectorFixedEntries + 2 * b + 1] = s.directions[b].mean_normal_force;
    }
  for (int k = 0; k < nslices; ++k)
    for (int e = 0; e < kSliceEntries; ++e) {
      const SliceEntry entry = static_cast<SliceEntry>(e);
      v[slice_position(direction_bins, k + 1, entry) - 1] =
          slice_value(entry, slices[k]);
    }
  return v;
}

std::array<double, kArrayColumns> interval_row(const IntervalSummary& r) {
  std::array<double, kArrayColumns> row{};
  for (int c = 0; c < kArrayColumns; ++c)
    row[c] = column_value(static_cast<ArrayColumn>(c), r);
  return row;
}

}  // namespace fabric
