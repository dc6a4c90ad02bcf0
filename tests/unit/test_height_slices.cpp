// Unit tests of the primary fabric by height (compute primary/fabric,
// keyword slices; compute_primary_fabric/height_slices.*) on a hand-built
// specimen of two layers whose per-slice figures are known.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "fabric_analysis.h"
#include "fabric_outputs.h"
#include "height_slices.h"

namespace fabric {
namespace {

using Eigen::Vector3d;

// Two layers of three grains (radius 0.5): 0, 1, 2 on the floor (z 0.5),
// 3, 4, 5 above them (z 2.5); the grains' extent is z 0 to 3.
//   0, 1, 2: touch each other (0-1 along x, 1-2 along y, 0-2 along x) and
//            the floor: 3 loaded contacts, primary; 3 rests on all three
//            (along z, force 2): 4 each.
//   3:       3 loaded contacts (0, 1, 2), primary.
//   4, 5:    touch each other only (along x): loose.
// Masses 1, except grain 4 (2). Forces 1, except 3's contacts (2).
struct TwoLayers {
  std::vector<Particle> particles;
  std::vector<double> z = {0.5, 0.5, 0.5, 2.5, 2.5, 2.5};
  std::vector<ParticleContact> contacts;
  std::vector<WallContact> walls;
  Options options;
  TwoLayers() {
    for (int p = 0; p < 6; ++p)
      particles.push_back({p + 1, 0.5, p == 4 ? 2.0 : 1.0, 0});
    const Vector3d x = Vector3d::UnitX(), y = Vector3d::UnitY(),
                   zz = Vector3d::UnitZ();
    contacts = {{0, 1, 1.0, x, true},  {1, 2, 1.0, y, true},
                {0, 2, 1.0, x, true},  {3, 0, 2.0, zz, true},
                {3, 1, 2.0, zz, true}, {3, 2, 2.0, zz, true},
                {4, 5, 1.0, x, true}};
    for (int p = 0; p < 3; ++p) walls.push_back({p, 1.0, zz});
    options.threshold = LoadThreshold::absolute(0.0);
  }
};

std::vector<SliceSummary> run(const TwoLayers& s, int n) {
  const Analysis a = analyse(s.particles, s.contacts, s.walls, 1, s.options);
  const HeightSlices slices(height_extent(s.particles, s.z), n);
  return finalise_slices(
      accumulate_slices(s.particles, s.z, s.contacts, s.walls,
                        a.classification, a.threshold_force, slices, s.options),
      slices);
}

TEST(HeightSlices, EqualSpansOfTheGrainsExtentTopInTheLastSlice) {
  const HeightSlices s({0.0, 3.0}, 2);
  EXPECT_EQ(s.lower(0), 0.0);
  EXPECT_EQ(s.upper(0), 1.5);
  EXPECT_EQ(s.lower(1), 1.5);
  EXPECT_EQ(s.upper(1), 3.0);
  EXPECT_EQ(s.of(0.0), 0);
  EXPECT_EQ(s.of(std::nextafter(1.5, 0.0)), 0);
  EXPECT_EQ(s.of(1.5), 1);
  EXPECT_EQ(s.of(3.0), 1);
  EXPECT_EQ(s.of(-1e-12), -1);
  EXPECT_EQ(s.of(3.0 + 1e-12), -1);
  EXPECT_EQ(s.of(NAN), -1);
  // a slice boundary decided by lower(), whatever the division rounds to
  const HeightSlices t({0.1, 0.7}, 3);
  for (int k = 1; k < 3; ++k) {
    EXPECT_EQ(t.of(t.lower(k)), k);
    EXPECT_EQ(t.of(std::nextafter(t.lower(k), 0.0)), k - 1);
  }
}

TEST(HeightSlices, ExtentIsTheLowestBottomAndHighestTop) {
  const TwoLayers s;
  const HeightExtent e = height_extent(s.particles, s.z);
  EXPECT_EQ(e.bottom, 0.0);
  EXPECT_EQ(e.top, 3.0);
  const HeightExtent none = height_extent({}, {});
  EXPECT_TRUE(std::isinf(none.bottom) && none.bottom > 0);
  EXPECT_TRUE(std::isinf(none.top) && none.top < 0);
  EXPECT_TRUE(HeightSlices(none, 4).empty());
  EXPECT_EQ(HeightSlices(none, 4).of(0.0), -1);
}

TEST(HeightSlices, PrimaryFractionPerSliceOfTwoLayers) {
  const std::vector<SliceSummary> r = run(TwoLayers(), 2);
  ASSERT_EQ(r.size(), 2u);
  // floor layer: 3 grains of mass 1, all primary, 4 loaded contacts each
  EXPECT_EQ(r[0].lower, 0.0);
  EXPECT_EQ(r[0].upper, 1.5);
  EXPECT_EQ(r[0].particles, 3);
  EXPECT_NEAR(r[0].mass_percent, 100.0 * 3 / 7, 1e-12);
  EXPECT_NEAR(r[0].primary_percent, 100.0, 1e-12);
  EXPECT_EQ(r[0].loose_percent_by_number, 0.0);
  EXPECT_NEAR(r[0].coordination, 4.0, 1e-12);
  // upper layer: grain 3 primary (mass 1 of 4), 4 and 5 loose
  EXPECT_EQ(r[1].particles, 3);
  EXPECT_NEAR(r[1].mass_percent, 100.0 * 4 / 7, 1e-12);
  EXPECT_NEAR(r[1].primary_percent, 25.0, 1e-12);
  EXPECT_NEAR(r[1].loose_percent_by_number, 200.0 / 3, 1e-12);
  EXPECT_NEAR(r[1].coordination, 5.0 / 3, 1e-12);
  // fabric: the three contacts between the layers count half in each
  EXPECT_NEAR(r[0].fabric_contacts, 4.5, 1e-12);
  EXPECT_NEAR(r[1].fabric_contacts, 2.5, 1e-12);
  EXPECT_TRUE(r[0].fabric_tensor.isApprox(
      Vector3d(2.0, 1.0, 1.5).asDiagonal().toDenseMatrix() / 4.5));
  EXPECT_TRUE(r[1].fabric_tensor.isApprox(
      Vector3d(1.0, 0.0, 1.5).asDiagonal().toDenseMatrix() / 2.5));
  EXPECT_NEAR(r[0].fabric_anisotropy,
              fabric_anisotropy(r[0].fabric_tensor), 1e-15);
  EXPECT_NEAR(r[1].force_anisotropy,
              force_anisotropy(r[1].fabric_tensor, r[1].force_fabric_tensor),
              1e-15);
}

TEST(HeightSlices, TheClassificationIsTheWholeSpecimens) {
  // A slice of the upper layer alone would leave grain 3 without its
  // contacts below: it stays primary, the class of the whole specimen.
  const std::vector<SliceSummary> r = run(TwoLayers(), 3);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[1].particles, 0);  // [1, 2): no centre
  EXPECT_EQ(r[1].primary_percent, 0.0);
  EXPECT_EQ(r[1].fabric_contacts, 0.0);
  EXPECT_EQ(r[1].fabric_anisotropy, 0.0);
  EXPECT_NEAR(r[2].primary_percent, 25.0, 1e-12);
}

TEST(HeightSlices, OneSliceIsTheWholeSpecimen) {
  const TwoLayers s;
  const Analysis a = analyse(s.particles, s.contacts, s.walls, 1, s.options);
  const std::vector<SliceSummary> r = run(s, 1);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].particles, a.summary.particles);
  EXPECT_NEAR(r[0].primary_percent, a.summary.primary_percent_by_mass, 1e-12);
  EXPECT_NEAR(r[0].loose_percent_by_number, a.summary.loose_percent_by_number,
              1e-12);
  EXPECT_NEAR(r[0].coordination, a.summary.coordination, 1e-12);
  EXPECT_NEAR(r[0].fabric_contacts, 7.0, 1e-12);
  EXPECT_TRUE(r[0].fabric_tensor.isApprox(a.summary.fabric_tensor));
  EXPECT_NEAR(r[0].fabric_anisotropy, a.summary.fabric_anisotropy, 1e-12);
  EXPECT_NEAR(r[0].force_anisotropy, a.summary.force_anisotropy, 1e-12);
  EXPECT_NEAR(r[0].mass_percent, 100.0, 1e-12);
}

TEST(HeightSlices, TheSlicesAddUpToTheWhole) {
  const std::vector<SliceSummary> r = run(TwoLayers(), 5);
  double particles = 0, mass = 0, ends = 0;
  for (const SliceSummary& s : r) {
    particles += s.particles;
    mass += s.mass_percent;
    ends += s.fabric_contacts;
  }
  EXPECT_EQ(particles, 6);
  EXPECT_NEAR(mass, 100.0, 1e-12);
  EXPECT_NEAR(ends, 7.0, 1e-12);
}

// The layers on two ranks (newton off: the contacts between them are listed
// on both, each with its own grain as i): the same sums after the reduction.
TEST(HeightSlices, TwoRanksGiveTheSameSums) {
  const TwoLayers s;
  const Analysis whole = analyse(s.particles, s.contacts, s.walls, 1, s.options);
  const HeightSlices slices(height_extent(s.particles, s.z), 2);
  const SliceSums one =
      accumulate_slices(s.particles, s.z, s.contacts, s.walls,
                        whole.classification, whole.threshold_force, slices,
                        s.options);

  const Vector3d x = Vector3d::UnitX(), y = Vector3d::UnitY(),
                 zz = Vector3d::UnitZ();
  const std::vector<Particle> pa(s.particles.begin(), s.particles.begin() + 3);
  const std::vector<Particle> pb(s.particles.begin() + 3, s.particles.end());
  const std::vector<double> za(s.z.begin(), s.z.begin() + 3),
      zb(s.z.begin() + 3, s.z.end());
  const std::vector<ParticleContact> ca = {
      {0, 1, 1.0, x, true},   {1, 2, 1.0, y, true},   {0, 2, 1.0, x, true},
      {0, -1, 2.0, zz, false}, {1, -1, 2.0, zz, false}, {2, -1, 2.0, zz, false}};
  const std::vector<ParticleContact> cb = {
      {0, -1, 2.0, zz, false}, {0, -1, 2.0, zz, false}, {0, -1, 2.0, zz, false},
      {1, 2, 1.0, x, true}};
  const std::vector<WallContact> wa = s.walls;
  const Classification ka = classify(3, ca, wa, 0.0, s.options);
  const Classification kb = classify(3, cb, {}, 0.0, s.options);
  const HeightExtent ea = height_extent(pa, za), eb = height_extent(pb, zb);
  const HeightSlices both({std::min(ea.bottom, eb.bottom),
                           std::max(ea.top, eb.top)}, 2);
  SliceSums a = accumulate_slices(pa, za, ca, wa, ka, 0.0, both, s.options);
  const SliceSums b = accumulate_slices(pb, zb, cb, {}, kb, 0.0, both, s.options);
  ASSERT_EQ(a.size(), one.size());
  for (int k = 0; k < a.size(); ++k)
    EXPECT_NEAR(a.data()[k] + const_cast<SliceSums&>(b).data()[k],
                const_cast<SliceSums&>(one).data()[k], 1e-12)
        << "sum " << k;
}

TEST(HeightSlices, BadInputIsRejectedNamingIt) {
  const TwoLayers s;
  EXPECT_THROW(HeightSlices({0.0, 1.0}, 0), std::invalid_argument);
  EXPECT_THROW(HeightSlices({0.0, INFINITY}, 2), std::invalid_argument);
  EXPECT_THROW(SliceSums(0), std::invalid_argument);
  const Analysis a = analyse(s.particles, s.contacts, s.walls, 1, s.options);
  // a grain outside the slices' extent
  const HeightSlices low({0.0, 1.0}, 2);
  try {
    accumulate_slices(s.particles, s.z, s.contacts, s.walls, a.classification,
                      0.0, low, s.options);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("particle 4 at height 2.5"),
              std::string::npos) << e.what();
  }
  const HeightSlices ok(height_extent(s.particles, s.z), 2);
  // a grain at a non-finite height (a broken state) is in no slice
  std::vector<double> broken = s.z;
  broken[4] = NAN;
  const std::vector<SliceSummary> r = finalise_slices(
      accumulate_slices(s.particles, broken, s.contacts, s.walls,
                        a.classification, 0.0, ok, s.options), ok);
  EXPECT_EQ(r[0].particles + r[1].particles, 5);
  EXPECT_NEAR(r[1].fabric_contacts, 2.0, 1e-12);  // 4-5: only the end at 5
  EXPECT_THROW(accumulate_slices(s.particles, {0.5}, s.contacts, s.walls,
                                 a.classification, 0.0, ok, s.options),
               std::invalid_argument);
  Classification short_one = a.classification;
  short_one.fraction.pop_back();
  EXPECT_THROW(accumulate_slices(s.particles, s.z, s.contacts, s.walls,
                                 short_one, 0.0, ok, s.options),
               std::invalid_argument);
  std::vector<ParticleContact> bad = s.contacts;
  bad[0].j = 9;
  EXPECT_THROW(accumulate_slices(s.particles, s.z, bad, s.walls,
                                 a.classification, 0.0, ok, s.options),
               std::invalid_argument);
  EXPECT_THROW(finalise_slices(SliceSums(3), ok), std::invalid_argument);
}

TEST(HeightSlices, TheGlobalVectorAppendsEachSlicesEntries) {
  const std::vector<SliceSummary> r = run(TwoLayers(), 2);
  FabricSummary whole;
  const std::vector<double> v = global_vector(whole, 0.0, 0, 3, r);
  ASSERT_EQ(static_cast<int>(v.size()), vector_size(3, 2));
  EXPECT_EQ(vector_size(3, 2), kVectorFixedEntries + 6 + 2 * kSliceEntries);
  EXPECT_EQ(vector_size(3), kVectorFixedEntries + 6);
  // c_ID[I] of slice 2's primary share: after the 31, 6 and slice 1's K
  const int pos = slice_position(3, 2, SliceEntry::slice_primary_percent);
  EXPECT_EQ(pos, kVectorFixedEntries + 6 + kSliceEntries + 5);
  EXPECT_NEAR(v[pos - 1], 25.0, 1e-12);
  EXPECT_EQ(v[slice_position(3, 1, SliceEntry::slice_bottom) - 1], 0.0);
  EXPECT_EQ(v[slice_position(3, 2, SliceEntry::slice_top) - 1], 3.0);
  EXPECT_EQ(v[slice_position(3, 2, SliceEntry::slice_particles) - 1], 3.0);
  EXPECT_NEAR(v[slice_position(3, 1, SliceEntry::slice_fabric_anisotropy) - 1],
              r[0].fabric_anisotropy, 0.0);
  EXPECT_NEAR(v[slice_position(3, 2, SliceEntry::slice_force_anisotropy) - 1],
              r[1].force_anisotropy, 0.0);
}

}  // namespace
}  // namespace fabric
