// The outputs of compute primary/fabric, defined once: the position, name
// and meaning of every entry of its global vector and of every column of its
// global array (one row per size interval). The compute fills them from
// these tables, docs/compute_primary_fabric.md quotes them (a test compares
// the two) and tools/outputs.py reads them from this file (tools/plot_fabric.py,
// tools/fabric_layers.py).
//
// Format (kept simple for those readers): one X(position, name, "meaning")
// per line; positions count from 1, as c_ID[I] and c_ID[I][J] do.
#ifndef FABRIC_FABRIC_OUTPUTS_H
#define FABRIC_FABRIC_OUTPUTS_H

#include <array>
#include <vector>

#include "fabric_analysis.h"
#include "height_slices.h"
#include "output_table.h"

// Global vector, entries 1..31; then two entries per direction bin k = 1..M:
// 31 + 2k - 1 the fraction of the loaded contacts in bin k, 31 + 2k their
// mean normal force; then, with the keyword slices S, the entries of
// FABRIC_SLICE_ENTRIES for each height slice s = 1..S (the lowest first):
// entry J of slice s at 31 + 2M + (s - 1) K + J, K the entries of that table.
#define FABRIC_VECTOR_ENTRIES(X)                                               \
  X(1, particles, "particles of the group")                                    \
  X(2, loose_particles, "loose particles")                                     \
  X(3, loose_percent_by_number, "loose particles, % of the particles by number") \
  X(4, primary_percent_by_mass, "primary fabric, % of the group's mass")       \
  X(5, coordination, "loaded contacts per particle")                           \
  X(6, primary_coordination, "loaded contacts per primary particle")           \
  X(7, r1, "r1: radius of the finest interval holding primary fabric")         \
  X(8, r2, "r2: radius of the coarsest interval holding loose particles")      \
  X(9, overlapping_zone_percent, "overlapping zone, % of the mass")            \
  X(10, contacts, "contacts, loaded or not")                                   \
  X(11, loaded_contacts, "loaded contacts")                                    \
  X(12, mean_normal_force, "mean normal force of all contacts")                \
  X(13, threshold_force, "threshold force in use")                             \
  X(14, prune_passes, "passes of prune iterate that found new loose particles") \
  X(15, fabric_xx, "fabric tensor F_xx")                                       \
  X(16, fabric_yy, "fabric tensor F_yy")                                       \
  X(17, fabric_zz, "fabric tensor F_zz")                                       \
  X(18, fabric_xy, "fabric tensor F_xy")                                       \
  X(19, fabric_xz, "fabric tensor F_xz")                                       \
  X(20, fabric_yz, "fabric tensor F_yz")                                       \
  X(21, force_fabric_xx, "force-weighted fabric tensor Phi_xx")                \
  X(22, force_fabric_yy, "force-weighted fabric tensor Phi_yy")                \
  X(23, force_fabric_zz, "force-weighted fabric tensor Phi_zz")                \
  X(24, force_fabric_xy, "force-weighted fabric tensor Phi_xy")                \
  X(25, force_fabric_xz, "force-weighted fabric tensor Phi_xz")                \
  X(26, force_fabric_yz, "force-weighted fabric tensor Phi_yz")                \
  X(27, fabric_anisotropy, "a_c: contact-normal anisotropy of F")              \
  X(28, force_anisotropy, "a_n: normal-force anisotropy of Phi against F")     \
  X(29, r1_tolerant, "r1 with oz_tolerance: finest interval above it in primary mass") \
  X(30, r2_tolerant, "r2 with oz_tolerance: coarsest interval above it in loose mass") \
  X(31, overlapping_zone_tolerant_percent, "overlapping zone with oz_tolerance, % of the mass")

// Global vector, with slices S: per height slice (heights of equal span
// along z from the lowest grain's bottom to the highest grain's top; a grain
// in the slice of its centre), these entries. The classification is the
// whole group's; a slice selects the grains of its figures
// (height_slices.h).
#define FABRIC_SLICE_ENTRIES(X)                                                \
  X(1, slice_bottom, "lower bound z of the slice")                             \
  X(2, slice_top, "upper bound z of the slice")                                \
  X(3, slice_particles, "particles with their centre in the slice")            \
  X(4, slice_mass_percent, "the slice's mass, % of the group's mass")          \
  X(5, slice_primary_percent, "primary fabric, % of the slice's mass")         \
  X(6, slice_loose_percent_by_number, "loose particles, % of the slice's particles") \
  X(7, slice_coordination, "loaded contacts per particle of the slice")        \
  X(8, slice_fabric_contacts, "loaded contacts of its particles in its F (one with another slice's particle counts half)") \
  X(9, slice_fabric_anisotropy, "a_c of the slice's loaded contacts")          \
  X(10, slice_force_anisotropy, "a_n of the slice's loaded contacts")

// Per-atom array: one row per atom, these columns (0 for an atom outside
// the group).
#define FABRIC_PERATOM_COLUMNS(X)                                              \
  X(1, loaded_contacts, "loaded contacts of the particle (particles and walls)") \
  X(2, primary, "class: 1 primary fabric, 0 loose or outside the group")      \
  X(3, interval, "size interval, 1 the finest (0 outside the group)")

// Global array: one row per size interval (row 1 the finest), these columns.
#define FABRIC_ARRAY_COLUMNS(X)                                                \
  X(1, diameter, "representative diameter of the interval")                    \
  X(2, mass_percent, "mass of the interval, % of the group's mass")            \
  X(3, primary_percent_of_interval, "primary fabric, % of the interval's mass") \
  X(4, loose_mass_percent, "loose mass of the interval, % of the group's mass") \
  X(5, loaded_contacts_per_particle, "loaded contacts per particle")           \
  X(6, normal_force_per_loaded_contact, "mean normal force per loaded contact") \
  X(7, primary_mass_percent, "primary mass of the interval, % of the group's mass") \
  X(8, particles, "particles in the interval")

namespace fabric {

enum class VectorEntry { FABRIC_VECTOR_ENTRIES(FABRIC_OUTPUT_NAME) count };
enum class ArrayColumn { FABRIC_ARRAY_COLUMNS(FABRIC_OUTPUT_NAME) count };
enum class PeratomColumn { FABRIC_PERATOM_COLUMNS(FABRIC_OUTPUT_NAME) count };
enum class SliceEntry { FABRIC_SLICE_ENTRIES(FABRIC_OUTPUT_NAME) count };

constexpr int kVectorFixedEntries = static_cast<int>(VectorEntry::count);
constexpr int kArrayColumns = static_cast<int>(ArrayColumn::count);
constexpr int kPeratomColumns = static_cast<int>(PeratomColumn::count);
constexpr int kSliceEntries = static_cast<int>(SliceEntry::count);

constexpr int kVectorPositions[] = {
    FABRIC_VECTOR_ENTRIES(FABRIC_OUTPUT_POSITION)};
constexpr int kArrayPositions[] = {FABRIC_ARRAY_COLUMNS(FABRIC_OUTPUT_POSITION)};
constexpr int kPeratomPositions[] = {FABRIC_PERATOM_COLUMNS(FABRIC_OUTPUT_POSITION)};
constexpr int kSlicePositions[] = {FABRIC_SLICE_ENTRIES(FABRIC_OUTPUT_POSITION)};
static_assert(counts_from_one(kVectorPositions),
              "fabric_outputs.h: the vector positions must count 1, 2, 3 ...");
static_assert(counts_from_one(kArrayPositions),
              "fabric_outputs.h: the array positions must count 1, 2, 3 ...");
static_assert(counts_from_one(kPeratomPositions),
              "fabric_outputs.h: the per-atom positions must count 1, 2, 3 ...");
static_assert(counts_from_one(kSlicePositions),
              "fabric_outputs.h: the slice positions must count 1, 2, 3 ...");

// Column c of the per-atom array, counted from 0 as array_atom counts.
constexpr int peratom_column(PeratomColumn c) { return static_cast<int>(c); }

// Size of the global vector with M direction bins and S height slices.
inline int vector_size(int direction_bins, int slices = 0) {
  return kVectorFixedEntries + 2 * direction_bins + kSliceEntries * slices;
}

// Position (from 1, as c_ID[I]) of entry e of height slice s (from 1).
inline int slice_position(int direction_bins, int s, SliceEntry e) {
  return kVectorFixedEntries + 2 * direction_bins + (s - 1) * kSliceEntries +
         static_cast<int>(e) + 1;
}

// The global vector: the 31 entries, then (fraction, mean normal force) per
// direction bin, M = direction_bins entries of summary.directions (missing
// bins are 0), then the entries of each height slice of `slices`.
std::vector<double> global_vector(const FabricSummary& summary,
                                  double threshold_force, int prune_passes,
                                  int direction_bins,
                                  const std::vector<SliceSummary>& slices = {});
// One row of the global array.
std::array<double, kArrayColumns> interval_row(const IntervalSummary& row);

}  // namespace fabric

#endif
