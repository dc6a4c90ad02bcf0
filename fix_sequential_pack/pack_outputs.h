// The outputs of fix sequential/pack, defined once: the position, name and
// meaning of every entry of its global vector. The fix fills them from this
// table, docs/fix_sequential_pack.md quotes it and the Python tools read it
// from this file (tools/outputs.py), as they read fabric_outputs.h.
// An entry more is one line of the table and its value set in
// pack_report() (pack_outputs.cpp): PackVector gets its field from the table.
//
// Format (kept simple for those readers): one X(position, name, "meaning")
// per line; positions count from 1, as f_ID[I] does. The vector holds the
// entries of PACK_VECTOR_ENTRIES, then the profile by height: for each
// quantity of PACK_PROFILE_ENTRIES (in its order) one entry per layer of
// kProfileLayers (specimen_measure.h), floor first, named layer<L>_<name>;
// {layer} and {layers} in its meaning stand for L and kProfileLayers.
#ifndef FABRIC_PACK_OUTPUTS_H
#define FABRIC_PACK_OUTPUTS_H

#include <array>
#include <string>
#include <vector>

#include "front_packer.h"
#include "output_table.h"
#include "psd.h"
#include "specimen_measure.h"

#define PACK_VECTOR_ENTRIES(X)                                                 \
  X(1, placed, "particles placed")                                             \
  X(2, listed, "particles in the list")                                        \
  X(3, porosity, "achieved porosity over the container, by volume")           \
  X(4, interior_porosity, "porosity of the interior (one coarsest diameter from every wall), by volume; NaN without an interior") \
  X(5, wall_layer_porosity, "porosity of that wall layer, by volume")          \
  X(6, seconds, "wall-clock seconds of the packing on rank 0")                 \
  X(7, few_contacts_percent, "% of the grains with fewer than min_contacts contacts (grains or walls) before loading") \
  X(8, contacts_per_grain, "contacts per grain before loading (grains and walls)") \
  X(9, held_mass_percent, "% of the mass in grains with min_contacts contacts or more before loading") \
  X(10, size_assortativity, "size assortativity (ln r) of the touching pairs; NaN without pairs") \
  X(11, radius_distance_spearman, "Spearman correlation of radius with distance from the container centre; NaN if undefined") \
  X(12, interior_size_assortativity, "size assortativity of the touching pairs in the interior; NaN without such pairs") \
  X(13, local_cu_ratio, "mean Cu of the 27 sub-cubes (grains by centre, sub-cubes of 50 grains or more) over the specimen's Cu: 1 mixed, below 1 like sizes together; NaN without such a sub-cube")

// The profile by height, kProfileLayers equal slabs of the container, floor
// first: per quantity (its position among the quantities, its name, its
// meaning), one entry per layer after those above.
#define PACK_PROFILE_ENTRIES(X)                                                \
  X(1, porosity, "porosity of height layer {layer} of {layers} (equal slabs, floor first), by volume") \
  X(2, mean_diameter, "mass-weighted mean diameter of height layer {layer} of {layers} over the coarsest diameter d_N, by volume; NaN if it holds no solid")

namespace fabric {

enum class PackEntry { PACK_VECTOR_ENTRIES(FABRIC_OUTPUT_NAME) count };
enum class ProfileQuantity { PACK_PROFILE_ENTRIES(FABRIC_OUTPUT_NAME) count };
constexpr int kPackScalarEntries = static_cast<int>(PackEntry::count);
constexpr int kProfileQuantities = static_cast<int>(ProfileQuantity::count);
constexpr int kPackVectorEntries =
    kPackScalarEntries + kProfileQuantities * kProfileLayers;

constexpr int kPackPositions[] = {PACK_VECTOR_ENTRIES(FABRIC_OUTPUT_POSITION)};
static_assert(counts_from_one(kPackPositions),
              "pack_outputs.h: the positions must count 1, 2, 3 ... in order");
constexpr int kProfilePositions[] = {PACK_PROFILE_ENTRIES(FABRIC_OUTPUT_POSITION)};
static_assert(counts_from_one(kProfilePositions),
              "pack_outputs.h: the profile's positions must count 1, 2, 3 ...");

// f_ID[I] of quantity q in height layer `layer` (from 0, the floor's):
// counted from 1.
constexpr int profile_position(ProfileQuantity q, int layer) {
  return kPackScalarEntries + static_cast<int>(q) * kProfileLayers + layer + 1;
}

// The profile by height: per quantity, one value per layer, floor first.
struct PackProfile {
#define PACK_PROFILE_FIELD(position, name, meaning) \
  std::array<double, kProfileLayers> name{};
  PACK_PROFILE_ENTRIES(PACK_PROFILE_FIELD)
#undef PACK_PROFILE_FIELD
};

// The global vector's values, one field per entry of the table, by its name,
// and the profile.
struct PackVector {
#define PACK_FIELD(position, name, meaning) double name = 0.0;
  PACK_VECTOR_ENTRIES(PACK_FIELD)
#undef PACK_FIELD
  PackProfile profile;
};

// The global vector in the table's order: entry I at [I - 1].
std::vector<double> vector_values(const PackVector& v);

// What the fix reports about its specimen: the global vector and the further
// figures its summary prints and its warnings judge.
struct PackReport {
  PackVector vector;
  double container_volume = 0.0;
  double placed_volume = 0.0;         // solid volume of the placed grains
  double list_porosity = 0.0;         // of the list (counts rounded)
  double packed_full_porosity = 0.0;  // of the container packed full
  double wall_layer = 0.0;            // its width: one coarsest diameter
  double narrowest_edge = 0.0;        // in coarsest diameters
  long long not_placed = 0;
  std::vector<double> placed_mass_percent;  // per interval, of the placed mass
};

// The report of a packing `res` of `list` (from `intervals`, finest first)
// in `container`, which took `seconds`.
PackReport pack_report(const PackingResult& res, const ParticleList& list,
                       const std::vector<SizeInterval>& intervals,
                       const Box& container, double seconds);

// Below this size assortativity (in the interior) a layer-wise specimen is
// reported as not layered: discrete specimens measure -0.13 to -0.17 there
// (a random packing of the same grains gives the same within 0.025 over the
// container, bench/random_reference).
constexpr double kLayeredAssortativity = 0.1;

// What is wrong with the specimen, one message each (none: as asked):
// grains not placed (the target too dense for the container, or coarse
// grains that came too late), a porosity off the target by the rounding of
// the counts, a layer-wise specimen that is not layered.
std::vector<std::string> pack_warnings(const PackReport& report,
                                       const PackingResult& res,
                                       const ParticleList& list,
                                       double target_porosity,
                                       Arrangement arrangement);

}  // namespace fabric

#endif
