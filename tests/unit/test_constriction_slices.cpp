// compute constriction/size by height slice (keyword slices;
// constriction_slices() of compute_constriction_size/constriction_outputs.h):
// a hand-built two-layer specimen whose per-slice answer is known, one slice
// that gives the whole specimen's figures, the vector's layout, and a real
// network whose discs carry their face's centroid.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "constriction_outputs.h"

using fabric::ConstrictionDisc;
using fabric::ConstrictionEntry;
using fabric::ConstrictionSliceEntry;
using fabric::CsdWeight;
using fabric::Sphere;
using fabric::Vec3;

namespace {

ConstrictionDisc disc_at(double face_z, double diameter) {
  ConstrictionDisc d{Vec3(0, 0, face_z), Vec3(0, 0, 1), 0.5 * diameter};
  d.face_centroid = Vec3(1, 1, face_z);
  return d;
}

// A graded bed from z = 0 to 4: a coarse floor (z < 2) whose constrictions
// are 1.0, 1.2, 1.4, 1.6 and a fine top (z >= 2) with 0.10, 0.12, 0.14,
// 0.16. Two pore-forming grains span the extent: one from 0 to 1, one from
// 3 to 4. Loose grains: in the floor 0.5 (mass 1) and 1.5 (mass 3), in the
// top 0.05 (mass 2) and 0.5 (mass 2).
struct GradedBed {
  fabric::ConstrictionNetwork net;
  std::vector<Sphere> pore_forming;
  fabric::VerdictGrains grains;
  GradedBed() {
    for (double d : {1.0, 1.2, 1.4, 1.6}) net.discs.push_back(disc_at(1.0, d));
    for (double d : {0.10, 0.12, 0.14, 0.16})
      net.discs.push_back(disc_at(2.9, d));
    pore_forming = {{Vec3(0, 0, 0.5), 0.5}, {Vec3(0, 0, 3.5), 0.5}};
    grains.loose_diameter = {0.5, 0.05, 1.5, 0.5};
    grains.loose_mass = {1.0, 2.0, 3.0, 2.0};
    grains.loose_z = {0.8, 3.0, 1.5, 3.2};
    grains.pore_forming_mass = 8.0;
  }
};

}  // namespace

TEST(ConstrictionSlices, TwoLayersEachGetTheirOwnControlAndVerdict) {
  const GradedBed b;
  const auto s = fabric::constriction_slices(b.net, b.pore_forming, b.grains,
                                             2, 35.0, CsdWeight::number);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].lower, 0.0);
  EXPECT_EQ(s[0].upper, 2.0);
  EXPECT_EQ(s[1].lower, 2.0);
  EXPECT_EQ(s[1].upper, 4.0);
  EXPECT_EQ(s[0].constrictions, 4.0);
  EXPECT_EQ(s[1].constrictions, 4.0);
  // D_c35 by number: 1.2 + 0.05 (1.4 - 1.2) in the floor, a tenth of it on
  // top
  EXPECT_NEAR(s[0].control, 1.21, 1e-12);
  EXPECT_NEAR(s[1].control, 0.121, 1e-12);
  EXPECT_EQ(s[0].loose_mass, 4.0);
  EXPECT_EQ(s[1].loose_mass, 4.0);
  // the 0.5 grain passes the floor's 1.21, the 1.5 one does not; on top
  // only the 0.05 one passes 0.121
  EXPECT_NEAR(s[0].loose_finer_control_percent, 25.0, 1e-12);
  EXPECT_NEAR(s[1].loose_finer_control_percent, 50.0, 1e-12);

  // The whole specimen's D_c35 (0.149) is the fine top's affair: it lets
  // through only the 0.05 grain, 25 % of the loose mass.
  const auto v = fabric::constriction_vector(b.net, 35.0, CsdWeight::number,
                                             b.grains, {});
  EXPECT_NEAR(v[fabric::at(ConstrictionEntry::control)], 0.149, 1e-12);
  EXPECT_NEAR(v[fabric::at(ConstrictionEntry::loose_finer_control_percent)],
              25.0, 1e-12);

  // by area, each layer's D_c35 is its own weighted percentile
  const auto a = fabric::constriction_slices(b.net, b.pore_forming, b.grains,
                                             2, 35.0, CsdWeight::area);
  std::vector<ConstrictionDisc> floor(b.net.discs.begin(),
                                      b.net.discs.begin() + 4);
  EXPECT_EQ(a[0].control,
            fabric::csd_percentiles(floor, {35.0}, CsdWeight::area)[0]);
}

TEST(ConstrictionSlices, OneSliceGivesTheWholeSpecimensFigures) {
  const GradedBed b;
  for (CsdWeight w : {CsdWeight::number, CsdWeight::area})
    for (double p : {5.0, 35.0, 80.0}) {
      const auto s = fabric::constriction_slices(b.net, b.pore_forming,
                                                 b.grains, 1, p, w);
      const auto v =
          fabric::constriction_vector(b.net, p, w, b.grains, {}, s);
      ASSERT_EQ(s.size(), 1u);
      EXPECT_EQ(s[0].lower, 0.0);
      EXPECT_EQ(s[0].upper, 4.0);
      EXPECT_EQ(s[0].constrictions, v[fabric::at(ConstrictionEntry::constrictions)]);
      EXPECT_EQ(s[0].control, v[fabric::at(ConstrictionEntry::control)]) << p;
      EXPECT_EQ(s[0].loose_finer_control_percent,
                v[fabric::at(ConstrictionEntry::loose_finer_control_percent)]) << p;
      EXPECT_EQ(s[0].loose_mass, 8.0);
    }
}

TEST(ConstrictionSlices, TheVectorHoldsEachSliceAfterTheFixedEntries) {
  const GradedBed b;
  const auto s = fabric::constriction_slices(b.net, b.pore_forming, b.grains,
                                             2, 35.0, CsdWeight::number);
  const auto v =
      fabric::constriction_vector(b.net, 35.0, CsdWeight::number, b.grains, {}, s);
  ASSERT_EQ(static_cast<int>(v.size()), fabric::constriction_vector_size(2));
  EXPECT_EQ(fabric::constriction_vector_size(0), fabric::kConstrictionVectorEntries);
  EXPECT_EQ(fabric::kConstrictionSliceEntries, 6);
  // entry J of slice s at 58 + (s - 1) K + J, as the page says
  EXPECT_EQ(fabric::constriction_slice_position(1, ConstrictionSliceEntry::slice_bottom), 59);
  EXPECT_EQ(fabric::constriction_slice_position(2, ConstrictionSliceEntry::slice_bottom), 65);
  const auto at = [&](int slice, ConstrictionSliceEntry e) {
    return v[fabric::constriction_slice_position(slice, e) - 1];
  };
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(at(k + 1, ConstrictionSliceEntry::slice_bottom), s[k].lower);
    EXPECT_EQ(at(k + 1, ConstrictionSliceEntry::slice_top), s[k].upper);
    EXPECT_EQ(at(k + 1, ConstrictionSliceEntry::slice_constrictions), s[k].constrictions);
    EXPECT_EQ(at(k + 1, ConstrictionSliceEntry::slice_control), s[k].control);
    EXPECT_EQ(at(k + 1, ConstrictionSliceEntry::slice_loose_mass), s[k].loose_mass);
    EXPECT_EQ(at(k + 1, ConstrictionSliceEntry::slice_loose_finer_control_percent),
              s[k].loose_finer_control_percent);
  }
  // without slices the vector is unchanged
  const auto w = fabric::constriction_vector(b.net, 35.0, CsdWeight::number, b.grains, {});
  EXPECT_EQ(std::vector<double>(v.begin(), v.begin() + w.size()), w);
}

TEST(ConstrictionSlices, ASliceWithoutConstrictionsHasNoControlAndNoVerdict) {
  const GradedBed b;
  // four slices of height 1: the discs lie in slices 2 (z 1.0) and 3 (z 2.9)
  const auto s = fabric::constriction_slices(b.net, b.pore_forming, b.grains,
                                             4, 35.0, CsdWeight::number);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[0].constrictions, 0.0);
  EXPECT_TRUE(std::isnan(s[0].control));
  EXPECT_EQ(s[0].loose_mass, 1.0);  // the 0.5 grain at z 0.8
  EXPECT_EQ(s[0].loose_finer_control_percent, 0.0);
  EXPECT_EQ(s[1].constrictions, 4.0);
  EXPECT_EQ(s[2].constrictions, 4.0);
  EXPECT_EQ(s[3].constrictions, 0.0);
  EXPECT_EQ(s[2].loose_mass, 0.0);
  EXPECT_EQ(s[2].loose_finer_control_percent, 0.0);
  EXPECT_EQ(s[3].loose_mass, 4.0);  // the grains at z 3.0 and 3.2
  EXPECT_EQ(s[3].loose_finer_control_percent, 0.0);
  double mass = 0.0;
  for (const auto& r : s) mass += r.loose_mass;
  EXPECT_EQ(mass, 8.0);
}

TEST(ConstrictionSlices, BadInput) {
  GradedBed b;
  EXPECT_THROW(fabric::constriction_slices(b.net, b.pore_forming, b.grains, 0,
                                           35.0, CsdWeight::number),
               std::invalid_argument);
  b.grains.loose_z.pop_back();
  EXPECT_THROW(fabric::constriction_slices(b.net, b.pore_forming, b.grains, 2,
                                           35.0, CsdWeight::number),
               std::invalid_argument);
  // a loose grain at a non-finite height is in no slice
  b.grains.loose_z.push_back(NAN);
  const auto s = fabric::constriction_slices(b.net, b.pore_forming, b.grains,
                                             2, 35.0, CsdWeight::number);
  EXPECT_EQ(s[1].loose_mass, 2.0);
  EXPECT_EQ(s[1].upper, 4.0);
}

TEST(ConstrictionSlices, ARealNetworksDiscsLieInTheirFacesAndEverySliceCountsThem) {
  // body-centred cubic, every constriction 0.22474 R: every slice's D_cP is
  // that diameter, and the slices count every disc once
  const double R = 1.0, a = 4.0 * R / std::sqrt(3.0);
  std::vector<Sphere> s;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 5; ++k)
        for (const Vec3& c : {Vec3(0, 0, 0), Vec3(0.5, 0.5, 0.5)})
          s.push_back({a * (Vec3(i, j, k) + c), R});
  const auto net = fabric::constriction_network(s, {});
  ASSERT_GT(net.discs.size(), 20u);
  for (const auto& d : net.discs) {
    EXPECT_NEAR((d.face_centroid - d.centre).dot(d.normal), 0.0, 1e-9);
    EXPECT_LT((d.face_centroid - d.centre).norm(), a);
  }
  const auto rows = fabric::constriction_slices(net, s, {}, 3, 35.0,
                                                CsdWeight::number);
  double counted = 0.0;
  for (const auto& r : rows) {
    counted += r.constrictions;
    ASSERT_GT(r.constrictions, 0.0);
    EXPECT_NEAR(r.control, 2.0 * (std::sqrt(1.5) - 1.0) * R, 1e-9);
  }
  EXPECT_EQ(counted, static_cast<double>(net.discs.size()));
}
