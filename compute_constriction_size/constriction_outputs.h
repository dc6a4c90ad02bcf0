// The outputs of compute constriction/size, defined once: the position,
// name and meaning of every entry of its global vector. The compute fills
// them from this table (constriction_vector), docs/compute_constriction_size.md
// quotes it (a scene test compares the two) and the Python tools read it
// from this file (tools/outputs.py), as they read fabric_outputs.h.
//
// Format (kept simple for those readers): one X(position, name, "meaning")
// per line; positions count from 1, as c_ID[I] does.
#ifndef FABRIC_CONSTRICTION_OUTPUTS_H
#define FABRIC_CONSTRICTION_OUTPUTS_H

#include <vector>

#include "constriction_network.h"
#include "output_table.h"
#include "psd.h"

// Entries 2..20 are the percentiles 5, 10, ..., 95 of the constriction
// diameters by number, 21..39 the same weighted by D_c^3 (as a PSD is by
// mass); 52..58 the classical criteria of the grading of keyword psd (0
// without it).
#define CONSTRICTION_VECTOR_ENTRIES(X)                                         \
  X(1, constrictions, "constrictions counted")                                 \
  X(2, dc5_number, "D_c5 by number")                                           \
  X(3, dc10_number, "D_c10 by number")                                         \
  X(4, dc15_number, "D_c15 by number")                                         \
  X(5, dc20_number, "D_c20 by number")                                         \
  X(6, dc25_number, "D_c25 by number")                                         \
  X(7, dc30_number, "D_c30 by number")                                         \
  X(8, dc35_number, "D_c35 by number")                                         \
  X(9, dc40_number, "D_c40 by number")                                         \
  X(10, dc45_number, "D_c45 by number")                                        \
  X(11, dc50_number, "D_c50 by number")                                        \
  X(12, dc55_number, "D_c55 by number")                                        \
  X(13, dc60_number, "D_c60 by number")                                        \
  X(14, dc65_number, "D_c65 by number")                                        \
  X(15, dc70_number, "D_c70 by number")                                        \
  X(16, dc75_number, "D_c75 by number")                                        \
  X(17, dc80_number, "D_c80 by number")                                        \
  X(18, dc85_number, "D_c85 by number")                                        \
  X(19, dc90_number, "D_c90 by number")                                        \
  X(20, dc95_number, "D_c95 by number")                                        \
  X(21, dc5_cubed, "D_c5 weighted by D_c³")                                    \
  X(22, dc10_cubed, "D_c10 weighted by D_c³")                                  \
  X(23, dc15_cubed, "D_c15 weighted by D_c³")                                  \
  X(24, dc20_cubed, "D_c20 weighted by D_c³")                                  \
  X(25, dc25_cubed, "D_c25 weighted by D_c³")                                  \
  X(26, dc30_cubed, "D_c30 weighted by D_c³")                                  \
  X(27, dc35_cubed, "D_c35 weighted by D_c³")                                  \
  X(28, dc40_cubed, "D_c40 weighted by D_c³")                                  \
  X(29, dc45_cubed, "D_c45 weighted by D_c³")                                  \
  X(30, dc50_cubed, "D_c50 weighted by D_c³")                                  \
  X(31, dc55_cubed, "D_c55 weighted by D_c³")                                  \
  X(32, dc60_cubed, "D_c60 weighted by D_c³")                                  \
  X(33, dc65_cubed, "D_c65 weighted by D_c³")                                  \
  X(34, dc70_cubed, "D_c70 weighted by D_c³")                                  \
  X(35, dc75_cubed, "D_c75 weighted by D_c³")                                  \
  X(36, dc80_cubed, "D_c80 weighted by D_c³")                                  \
  X(37, dc85_cubed, "D_c85 weighted by D_c³")                                  \
  X(38, dc90_cubed, "D_c90 weighted by D_c³")                                  \
  X(39, dc95_cubed, "D_c95 weighted by D_c³")                                  \
  X(40, percolation, "percolation opening (0: no path)")                       \
  X(41, control, "controlling constriction D_cP (`control`, `control_by`)")                  \
  X(42, loose_finer_control_percent, "loose mass finer than entry 41, % of the loose mass") \
  X(43, loose_finer_percolation_percent, "loose mass finer than entry 40, % of the loose mass") \
  X(44, loose_mass_percent, "loose mass, % of the loose and pore-forming mass") \
  X(45, pores, "pores (after merging)")                                        \
  X(46, grains, "grains triangulated")                                         \
  X(47, hidden, "grains hidden by the regular triangulation (overlapping others so much that their power cell is empty): left out, with a warning") \
  X(48, wall_excluded, "faces between pores not counted, near the walls")      \
  X(49, on_edge, "constrictions on an edge (obtuse faces)")                    \
  X(50, unsolved, "faces without any circle")                                  \
  X(51, wall_margin, "wall margin in use")                                     \
  X(52, kezdi_max_ratio, "Kézdi: largest D′15/d′85 (`psd`)")                   \
  X(53, kenney_lau_min_ratio, "Kenney & Lau: smallest H/F")                    \
  X(54, burenkova_h1, "Burenkova h′ = d90/d60")                                \
  X(55, burenkova_h2, "Burenkova h″ = d90/d15")                                \
  X(56, burenkova_stable, "Burenkova: 1 inside the non-suffusive zone, else 0") \
  X(57, wan_fell_probability, "Wan & Fell, silt-sand-gravel soils: probability of internal instability") \
  X(58, wan_fell_sand_gravel_probability, "Wan & Fell, sand-gravel soils: probability of internal instability")

// Global vector, with slices S: after the entries above, these entries for
// each height slice s = 1..S (the lowest first): entry J of slice s at
// 58 + (s - 1) K + J, K the entries of this table. The slices are those of
// compute primary/fabric's keyword slices (height_slices.h): S of equal
// height along z from the lowest grain's bottom to the highest grain's top,
// over the pore-forming and the loose grains.
#define CONSTRICTION_SLICE_ENTRIES(X)                                          \
  X(1, slice_bottom, "lower bound z of the slice")                             \
  X(2, slice_top, "upper bound z of the slice")                                \
  X(3, slice_constrictions, "constrictions counted whose face's centroid lies in the slice") \
  X(4, slice_control, "D_cP of the slice's constrictions (`control`, `control_by`; NaN without any)") \
  X(5, slice_loose_mass, "mass of the loose grains whose centre lies in the slice") \
  X(6, slice_loose_finer_control_percent, "the slice's loose mass finer than its entry 4, % of the slice's loose mass")

namespace fabric {

enum class ConstrictionEntry {
  CONSTRICTION_VECTOR_ENTRIES(FABRIC_OUTPUT_NAME) count
};
constexpr int kConstrictionVectorEntries =
    static_cast<int>(ConstrictionEntry::count);

enum class ConstrictionSliceEntry {
  CONSTRICTION_SLICE_ENTRIES(FABRIC_OUTPUT_NAME) count
};
constexpr int kConstrictionSliceEntries =
    static_cast<int>(ConstrictionSliceEntry::count);

constexpr int kConstrictionPositions[] = {
    CONSTRICTION_VECTOR_ENTRIES(FABRIC_OUTPUT_POSITION)};
static_assert(counts_from_one(kConstrictionPositions),
              "constriction_outputs.h: the positions must count 1, 2, 3 ...");
constexpr int kConstrictionSlicePositions[] = {
    CONSTRICTION_SLICE_ENTRIES(FABRIC_OUTPUT_POSITION)};
static_assert(counts_from_one(kConstrictionSlicePositions),
              "constriction_outputs.h: the slice positions must count 1, 2, 3 ...");

// Size of the global vector with S height slices (0: without slices).
constexpr int constriction_vector_size(int slices) {
  return kConstrictionVectorEntries + kConstrictionSliceEntries * slices;
}
// Position (from 1, as c_ID[I]) of entry e of height slice s (from 1).
constexpr int constriction_slice_position(int s, ConstrictionSliceEntry e) {
  return kConstrictionVectorEntries + (s - 1) * kConstrictionSliceEntries +
         static_cast<int>(e) + 1;
}

// Index of an entry in the vector (its position - 1).
constexpr int at(ConstrictionEntry e) { return static_cast<int>(e); }

// The percentiles of entries 2..39: 5, 10, ..., 95, by number, then cubed.
constexpr int kCsdPercentiles = 19;
static_assert(at(ConstrictionEntry::dc95_number) -
                      at(ConstrictionEntry::dc5_number) + 1 == kCsdPercentiles &&
                  at(ConstrictionEntry::dc5_cubed) ==
                      at(ConstrictionEntry::dc95_number) + 1 &&
                  at(ConstrictionEntry::dc95_cubed) -
                      at(ConstrictionEntry::dc5_cubed) + 1 == kCsdPercentiles,
              "constriction_outputs.h: the percentiles must run 5..95 in order");

// The classical criteria of a grading (suffusion_criteria.h), as entries
// 52..58 report them; all 0 without keyword psd.
struct GradingCriteria {
  double kezdi_max_ratio = 0.0, kenney_lau_min_ratio = 0.0;
  double burenkova_h1 = 0.0, burenkova_h2 = 0.0, burenkova_stable = 0.0;
  double wan_fell_probability = 0.0, wan_fell_sand_gravel_probability = 0.0;
};
GradingCriteria grading_criteria(const ParticleSizeDistribution& psd);

// The grains of the verdict: the loose grains' diameters and masses, and
// the mass of the pore-forming grains; for keyword slices also the heights
// (z) of the loose grains' centres (else it may stay empty).
struct VerdictGrains {
  std::vector<double> loose_diameter, loose_mass, loose_z;
  double pore_forming_mass = 0.0;
};

// One height slice's figures (CONSTRICTION_SLICE_ENTRIES).
struct ConstrictionSlice {
  double lower = 0.0, upper = 0.0;  // its heights (z)
  double constrictions = 0.0;       // discs whose face centroid lies in it
  double control = 0.0;             // their D_cP; NaN without discs
  double loose_mass = 0.0;          // loose grains with their centre in it
  double loose_finer_control_percent = 0.0;  // of loose_mass; 0 without
};

// The network's discs and the loose grains cut into `count` height slices
// of equal height (HeightSlices of height_slices.h, as compute
// primary/fabric's keyword slices) spanning the lowest bottom (z - r) to
// the highest top (z + r) of the pore-forming spheres and the loose grains
// (grains.loose_z; radius half the diameter). A disc belongs to the slice of
// its face_centroid's z, a loose grain to that of its centre; a grain at a
// non-finite height is in no slice. Each slice's D_cP is the percentile
// control_percent (counted by control_weight) of its own discs, and its
// verdict the share of its loose mass finer than that, as entries 41 and
// 42 of the whole specimen: one slice gives the whole specimen's figures.
// Throws std::invalid_argument for count < 1, loose_z not one height per
// loose grain, or no finite extent.
std::vector<ConstrictionSlice> constriction_slices(
    const ConstrictionNetwork& net, const std::vector<Sphere>& pore_forming,
    const VerdictGrains& grains, int count, double control_percent,
    CsdWeight control_weight);

// The global vector in the table's order (entry I at [I - 1]) of the
// network `net`, with the controlling constriction D_cP at
// P = control_percent of the CSD counted by `control_weight`, then the
// entries of each height slice of `slices` (constriction_slices).
std::vector<double> constriction_vector(
    const ConstrictionNetwork& net, double control_percent,
    CsdWeight control_weight, const VerdictGrains& grains,
    const GradingCriteria& criteria,
    const std::vector<ConstrictionSlice>& slices = {});

}  // namespace fabric

#endif
