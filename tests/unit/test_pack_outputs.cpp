// Unit tests of the outputs of fix sequential/pack
// (fix_sequential_pack/pack_outputs.*): the global vector's layout, the
// figures of a hand-built specimen whose answer is known, and which
// warnings a specimen gets.
#include <gtest/gtest.h>

#include <cmath>

#include "min_contacts.h"
#include "pack_outputs.h"

using fabric::PackReport;
using fabric::PackVector;
using fabric::Vec3;

namespace {

const double kPi = 3.14159265358979323846;

// Three unit spheres in the box [0, 10]^3: one in a corner (3 walls), two
// touching each other in the middle (1 contact each).
struct ThreeSpheres {
  fabric::PackingResult res;
  fabric::ParticleList list;
  std::vector<fabric::SizeInterval> intervals{{1.9, 2.1, 2.0, 1.0}};
  fabric::Box box{Vec3(0, 0, 0), Vec3(10, 10, 10)};
  ThreeSpheres() {
    res.centre = {Vec3(1, 1, 1), Vec3(5, 5, 5), Vec3(7, 5, 5)};
    res.radius = {1.0, 1.0, 1.0};
    res.size_class = {0, 0, 0};
    res.placed_per_class = {3};
    res.unplaced_per_class = {0};
    res.packed_volume = 600.0;
    list.diameter = {2.0};
    list.target_count = {3.0};
    list.count = {3};
  }
  PackReport report(double seconds = 2.0) const {
    return fabric::pack_report(res, list, intervals, box, seconds);
  }
};

}  // namespace

TEST(PackOutputs, VectorValuesFollowTheTable) {
  // Each field set to its own position: the vector must read 1, 2, ... N.
  PackVector v;
#define SET_TO_POSITION(position, name, meaning) v.name = position;
  PACK_VECTOR_ENTRIES(SET_TO_POSITION)
#undef SET_TO_POSITION
  // the profile: quantity by quantity, each over the layers, floor first
  int next = fabric::kPackScalarEntries + 1;
#define SET_PROFILE(position, name, meaning) \
  for (double& x : v.profile.name) x = next++;
  PACK_PROFILE_ENTRIES(SET_PROFILE)
#undef SET_PROFILE
  const std::vector<double> values = fabric::vector_values(v);
  ASSERT_EQ(values.size(), static_cast<size_t>(fabric::kPackVectorEntries));
  for (int i = 0; i < fabric::kPackVectorEntries; ++i)
    EXPECT_EQ(values[i], i + 1) << "entry " << i + 1;
}

TEST(PackOutputs, TheProfileIsSizedByKProfileLayers) {
  // the scalar entries, then porosity and mean diameter of each of the
  // kProfileLayers layers (6: layer1_porosity f_ID[14], layer1_mean_diameter
  // f_ID[20], as before the profile was one array)
  using fabric::ProfileQuantity;
  EXPECT_EQ(fabric::kPackVectorEntries,
            fabric::kPackScalarEntries +
                fabric::kProfileQuantities * fabric::kProfileLayers);
  EXPECT_EQ(fabric::profile_position(ProfileQuantity::porosity, 0),
            fabric::kPackScalarEntries + 1);
  EXPECT_EQ(fabric::profile_position(ProfileQuantity::mean_diameter, 0),
            fabric::kPackScalarEntries + fabric::kProfileLayers + 1);
  EXPECT_EQ(fabric::profile_position(ProfileQuantity::mean_diameter,
                                     fabric::kProfileLayers - 1),
            fabric::kPackVectorEntries);
  PackVector v;
  v.profile.porosity[2] = 0.4;
  v.profile.mean_diameter.back() = 0.7;
  const std::vector<double> values = fabric::vector_values(v);
  EXPECT_EQ(values[fabric::kPackScalarEntries + 2], 0.4);  // layer3_porosity
  EXPECT_EQ(values.back(), 0.7);  // the top layer's mean diameter
}

TEST(PackOutputs, PositionsTheToolsRead) {
  // f_ID[I] positions that scripts and tools read (in.oedometer, the
  // validation study): they must not move.
  const std::vector<double> values = fabric::vector_values([] {
    PackVector v;
    v.placed = 11, v.porosity = 13, v.few_contacts_percent = 17;
    v.interior_size_assortativity = 22;
    return v;
  }());
  EXPECT_EQ(values[0], 11);
  EXPECT_EQ(values[2], 13);
  EXPECT_EQ(values[6], 17);
  EXPECT_EQ(values[11], 22);
}

TEST(PackOutputs, ContactsOfThreeHandPlacedGrains) {
  ThreeSpheres s;
  const PackReport r = s.report();
  ASSERT_EQ(fabric::kMinContacts, 3);
  // contacts 3, 1, 1: two of three grains have fewer than 3
  EXPECT_NEAR(r.vector.few_contacts_percent, 200.0 / 3.0, 1e-9);
  EXPECT_NEAR(r.vector.contacts_per_grain, 5.0 / 3.0, 1e-12);
  EXPECT_NEAR(r.vector.held_mass_percent, 100.0 / 3.0, 1e-9);
  EXPECT_EQ(r.vector.placed, 3);
  EXPECT_EQ(r.vector.listed, 3);
  EXPECT_EQ(r.vector.seconds, 2.0);
  EXPECT_EQ(r.not_placed, 0);
}

TEST(PackOutputs, PorositiesOfThreeHandPlacedGrains) {
  ThreeSpheres s;
  const PackReport r = s.report();
  const double solid = 3 * 4.0 / 3.0 * kPi;
  EXPECT_NEAR(r.container_volume, 1000.0, 1e-9);
  EXPECT_NEAR(r.placed_volume, solid, 1e-9);
  EXPECT_NEAR(r.vector.porosity, 1.0 - solid / 1000.0, 1e-12);
  EXPECT_NEAR(r.list_porosity, 1.0 - solid / 1000.0, 1e-12);
  EXPECT_NEAR(r.packed_full_porosity, 0.4, 1e-12);
  EXPECT_EQ(r.wall_layer, 2.0);
  EXPECT_NEAR(r.narrowest_edge, 5.0, 1e-12);
  ASSERT_EQ(r.placed_mass_percent.size(), 1u);
  EXPECT_NEAR(r.placed_mass_percent[0], 100.0, 1e-9);
  // interior [2, 8]^3 holds the two middle spheres whole; the corner
  // sphere lies in the wall layer
  EXPECT_NEAR(r.vector.interior_porosity, 1.0 - 2 * 4.0 / 3.0 * kPi / 216.0,
              1e-9);
  EXPECT_NEAR(r.vector.wall_layer_porosity,
              1.0 - 4.0 / 3.0 * kPi / (1000.0 - 216.0), 1e-9);
}

TEST(PackOutputs, NoInteriorInANarrowContainer) {
  ThreeSpheres s;
  s.box = fabric::Box{Vec3(0, 0, 0), Vec3(10, 10, 3.5)};
  s.res.centre = {Vec3(1, 1, 1), Vec3(5, 5, 1), Vec3(7, 5, 1)};
  const PackReport r = s.report();
  EXPECT_TRUE(std::isnan(r.vector.interior_porosity));
  EXPECT_TRUE(std::isnan(r.vector.wall_layer_porosity));
  EXPECT_TRUE(std::isnan(r.vector.interior_size_assortativity));
}

TEST(PackOutputs, NoWarningWhenAsAsked) {
  ThreeSpheres s;
  const PackReport r = s.report();
  EXPECT_TRUE(fabric::pack_warnings(r, s.res, s.list, r.vector.porosity,
                                    fabric::Arrangement::discrete)
                  .empty());
}

TEST(PackOutputs, WarnsOfAPorosityOffTheTarget) {
  ThreeSpheres s;
  const PackReport r = s.report();
  EXPECT_EQ(fabric::pack_warnings(r, s.res, s.list, r.vector.porosity - 0.01,
                                  fabric::Arrangement::discrete)
                .size(),
            1u);
  EXPECT_TRUE(fabric::pack_warnings(r, s.res, s.list,
                                    r.vector.porosity - 0.004,
                                    fabric::Arrangement::discrete)
                  .empty());
}

TEST(PackOutputs, WarnsOfGrainsNotPlaced) {
  ThreeSpheres s;
  s.list.count = {4};
  s.res.unplaced_per_class = {1};
  const PackReport r = s.report();
  EXPECT_EQ(r.not_placed, 1);
  // too dense (the full packing's 0.4 against 0.395) or too late (0.3)
  for (double target : {0.395, 0.3})
    EXPECT_EQ(fabric::pack_warnings(r, s.res, s.list, target,
                                    fabric::Arrangement::discrete)
                  .size(),
              1u)
        << "target " << target;
}

TEST(PackOutputs, WarnsOfALayerwisePackingThatIsNotLayered) {
  ThreeSpheres s;
  PackReport r = s.report();
  const double target = r.vector.porosity;
  r.vector.interior_size_assortativity = -0.15;
  EXPECT_EQ(fabric::pack_warnings(r, s.res, s.list, target,
                                  fabric::Arrangement::layerwise)
                .size(),
            1u);
  EXPECT_TRUE(fabric::pack_warnings(r, s.res, s.list, target,
                                    fabric::Arrangement::discrete)
                  .empty());
  r.vector.interior_size_assortativity = fabric::kLayeredAssortativity + 0.2;
  EXPECT_TRUE(fabric::pack_warnings(r, s.res, s.list, target,
                                    fabric::Arrangement::layerwise)
                  .empty());
}

// The message prints the value to three decimals and must not contradict
// the threshold: 0.0998 prints as +0.100, which is not below 0.1, so it is
// no warning; 0.0994 prints as +0.099 and is one.
TEST(PackOutputs, JudgesLayeringAsPrinted) {
  ThreeSpheres s;
  PackReport r = s.report();
  const double target = r.vector.porosity;
  r.vector.interior_size_assortativity = 0.0998;
  EXPECT_TRUE(fabric::pack_warnings(r, s.res, s.list, target,
                                    fabric::Arrangement::layerwise)
                  .empty());
  r.vector.interior_size_assortativity = 0.0994;
  const auto w = fabric::pack_warnings(r, s.res, s.list, target,
                                       fabric::Arrangement::layerwise);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("+0.099, below 0.1"), std::string::npos) << w[0];
}
