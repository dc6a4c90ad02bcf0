// The outputs of fix sequential/pack, defined once: the position, name and
// meaning of every entry of its global vector. The fix fills them from this
// table, docs/fix_sequential_pack.md quotes it and the Python tools read it
// from this file (tools/outputs.py), as they read fabric_outputs.h.
//
// Format (kept simple for those readers): one X(position, name, "meaning")
// per line; positions count from 1, as f_ID[I] does.
#ifndef FABRIC_PACK_OUTPUTS_H
#define FABRIC_PACK_OUTPUTS_H

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
  X(12, interior_size_assortativity, "size assortativity of the touching pairs in the interior; NaN without such pairs")

namespace fabric {

#define PACK_ENUM_ENTRY(position, name, meaning) name,
enum class PackEntry { PACK_VECTOR_ENTRIES(PACK_ENUM_ENTRY) count };
#undef PACK_ENUM_ENTRY

constexpr int kPackVectorEntries = static_cast<int>(PackEntry::count);

// The positions written in the table are the enumerators' order + 1.
#define PACK_CHECK_ENTRY(position, name, meaning)                         \
  static_assert(static_cast<int>(PackEntry::name) + 1 == position,        \
                "pack_outputs.h: vector entry " #name " out of order");
PACK_VECTOR_ENTRIES(PACK_CHECK_ENTRY)
#undef PACK_CHECK_ENTRY

}  // namespace fabric

#endif
