// Unit tests of the outputs of compute constriction/size
// (compute_constriction_size/constriction_outputs.*): every entry of the
// global vector lies where the table puts it by name, and the criteria of
// keyword psd are those of suffusion_criteria.h.
#include <gtest/gtest.h>

#include "constriction_outputs.h"
#include "suffusion_criteria.h"

using fabric::ConstrictionEntry;
using fabric::at;

namespace {

// Ten discs of diameters 1, 2, ..., 10 (by number and by D^3 their
// percentiles differ), and every count of the network set to its own entry's
// position.
fabric::ConstrictionNetwork numbered_network() {
  fabric::ConstrictionNetwork net;
  for (int k = 1; k <= 10; ++k)
    net.discs.push_back({fabric::Vec3(0, 0, k), fabric::Vec3(0, 0, 1), 0.5 * k});
  net.percolation_diameter = 40;
  net.pores = 45, net.spheres = 46, net.hidden = 47, net.wall_excluded = 48;
  net.on_edge = 49, net.unsolved = 50, net.wall_margin = 51;
  return net;
}

fabric::GradingCriteria numbered_criteria() {
  fabric::GradingCriteria c;
  c.kezdi_max_ratio = 52, c.kenney_lau_min_ratio = 53, c.burenkova_h1 = 54;
  c.burenkova_h2 = 55, c.burenkova_stable = 56, c.wan_fell_probability = 57;
  c.wan_fell_sand_gravel_probability = 58;
  return c;
}

}  // namespace

TEST(ConstrictionOutputs, EveryEntryIsWhereTheTableSaysByName) {
  const fabric::ConstrictionNetwork net = numbered_network();
  // Loose grains 2.5 (mass 1) and 50 (mass 3); the pore formers weigh 4.
  fabric::VerdictGrains g;
  g.loose_diameter = {2.5, 50.0};
  g.loose_mass = {1.0, 3.0};
  g.pore_forming_mass = 4.0;
  const std::vector<double> v =
      fabric::constriction_vector(net, 35.0, fabric::CsdWeight::number, g, numbered_criteria());
  ASSERT_EQ(static_cast<int>(v.size()), fabric::kConstrictionVectorEntries);
  EXPECT_EQ(v[at(ConstrictionEntry::constrictions)], 10.0);
  for (int k = 0; k < fabric::kCsdPercentiles; ++k) {
    const double p = 5.0 * (k + 1);
    EXPECT_EQ(v[at(ConstrictionEntry::dc5_number) + k],
              fabric::csd_percentiles(net.discs, {p}, false)[0]) << p;
    EXPECT_EQ(v[at(ConstrictionEntry::dc5_cubed) + k],
              fabric::csd_percentiles(net.discs, {p}, true)[0]) << p;
  }
  EXPECT_LT(v[at(ConstrictionEntry::dc50_number)],
            v[at(ConstrictionEntry::dc50_cubed)]);
  EXPECT_EQ(v[at(ConstrictionEntry::percolation)], 40.0);
  const double dc35 = v[at(ConstrictionEntry::dc35_number)];
  EXPECT_EQ(v[at(ConstrictionEntry::control)], dc35);
  ASSERT_GT(dc35, 2.5);  // the 2.5 grain passes D_c35, the 50 one does not
  EXPECT_EQ(v[at(ConstrictionEntry::loose_finer_control_percent)], 25.0);
  EXPECT_EQ(v[at(ConstrictionEntry::loose_finer_percolation_percent)], 25.0);
  EXPECT_EQ(v[at(ConstrictionEntry::loose_mass_percent)], 50.0);
  // Entries 45..58 hold their own position.
  for (int e = 45; e <= 58; ++e) EXPECT_EQ(v[e - 1], e) << "entry " << e;
}

TEST(ConstrictionOutputs, ControlPicksItsPercentile) {
  fabric::VerdictGrains none;
  const auto net = numbered_network();
  const auto v = fabric::constriction_vector(net, 60.0, fabric::CsdWeight::number, none, {});
  EXPECT_EQ(v[at(ConstrictionEntry::control)],
            v[at(ConstrictionEntry::dc60_number)]);
  // No loose grains, no psd: the verdict and the criteria are 0.
  for (auto e : {ConstrictionEntry::loose_finer_control_percent,
                 ConstrictionEntry::loose_mass_percent,
                 ConstrictionEntry::kezdi_max_ratio,
                 ConstrictionEntry::wan_fell_sand_gravel_probability})
    EXPECT_EQ(v[at(e)], 0.0);
}

TEST(ConstrictionOutputs, PositionsThePageAndToolsRead) {
  // c_ID[I] positions in docs/compute_constriction_size.md, its scene test
  // and tools/constriction_verdict.py (by name there): they must not move.
  EXPECT_EQ(fabric::kConstrictionVectorEntries, 58);
  EXPECT_EQ(at(ConstrictionEntry::dc35_number) + 1, 8);
  EXPECT_EQ(at(ConstrictionEntry::dc50_number) + 1, 11);
  EXPECT_EQ(at(ConstrictionEntry::dc5_cubed) + 1, 21);
  EXPECT_EQ(at(ConstrictionEntry::percolation) + 1, 40);
  EXPECT_EQ(at(ConstrictionEntry::pores) + 1, 45);
  EXPECT_EQ(at(ConstrictionEntry::kezdi_max_ratio) + 1, 52);
  EXPECT_EQ(at(ConstrictionEntry::wan_fell_probability) + 1, 57);
  EXPECT_EQ(at(ConstrictionEntry::wan_fell_sand_gravel_probability) + 1, 58);
}

TEST(ConstrictionOutputs, GradingCriteriaAreThoseOfSuffusionCriteria) {
  // 30 % of 0.1-0.2 mm fines, a gap, 70 % of 2-4 mm gravel: unstable by
  // every criterion, both Wan & Fell models near 0.9.
  const fabric::ParticleSizeDistribution psd(
      {{0.1e-3, 0.0}, {0.2e-3, 30.0}, {2e-3, 30.0}, {4e-3, 100.0}});
  const fabric::GradingCriteria c = fabric::grading_criteria(psd);
  const auto bu = fabric::burenkova(psd);
  const auto wf = fabric::wan_fell(psd);
  EXPECT_EQ(c.kezdi_max_ratio, fabric::kezdi(psd).max_ratio);
  EXPECT_EQ(c.kenney_lau_min_ratio, fabric::kenney_lau(psd).min_ratio);
  EXPECT_EQ(c.burenkova_h1, bu.h1);
  EXPECT_EQ(c.burenkova_h2, bu.h2);
  EXPECT_EQ(c.burenkova_stable, 0.0);
  EXPECT_EQ(c.wan_fell_probability, wf.probability);
  EXPECT_EQ(c.wan_fell_sand_gravel_probability, wf.probability_sand_gravel);
  EXPECT_NE(c.wan_fell_probability, c.wan_fell_sand_gravel_probability);
}
