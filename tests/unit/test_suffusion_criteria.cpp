// The classical internal-stability criteria (suffusion_criteria.h) on two
// gradings worked out by hand below (log-linear between sieve points, as
// ParticleSizeDistribution interpolates): a uniform grading d..2d (stable by
// every criterion but Wan & Fell's band) and a gap grading, 30 % of
// 0.1-0.2 mm fines and 70 % of 2-4 mm gravel (unstable).
#include <gtest/gtest.h>

#include <cmath>

#include "suffusion_criteria.h"

using fabric::ParticleSizeDistribution;

namespace {
// d(p) = 1 mm * 2^(p/100).
ParticleSizeDistribution uniform() {
  return ParticleSizeDistribution({{1e-3, 0.0}, {2e-3, 100.0}});
}
// fines 0.1-0.2 mm: 0-30 %; gap; gravel 2-4 mm: 30-100 %.
ParticleSizeDistribution gap_graded() {
  return ParticleSizeDistribution(
      {{0.1e-3, 0.0}, {0.2e-3, 30.0}, {2e-3, 30.0}, {4e-3, 100.0}});
}
}  // namespace

TEST(SuffusionCriteria, KezdiUniformStableGapGradedUnstable) {
  // Uniform: at split F, D'15/d'85 = 2^((F + 0.15(100-F) - 0.85F)/100)
  // = 2^0.15 at every split.
  auto u = fabric::kezdi(uniform());
  EXPECT_NEAR(u.max_ratio, std::pow(2.0, 0.15), 1e-9);
  EXPECT_TRUE(u.stable());
  // Gap graded at F = 30: D'15 = 2 mm 2^(10.5/70), d'85 = 0.1 mm 2^(25.5/30).
  auto g = fabric::kezdi(gap_graded());
  double at30 = 2.0 * std::pow(2.0, 10.5 / 70.0) / (0.1 * std::pow(2.0, 25.5 / 30.0));
  EXPECT_GE(g.max_ratio, at30 - 1e-9);
  EXPECT_NEAR(at30, 12.311, 1e-3);
  EXPECT_FALSE(g.stable());
}

TEST(SuffusionCriteria, KenneyLauUniformStableGapGradedUnstable) {
  // Uniform (Cu = 2^0.5 <= 3: F up to 30): 4d lies above d_max, so H = 100 - F;
  // smallest H/F at F = 30: 70/30.
  auto u = fabric::kenney_lau(uniform());
  EXPECT_EQ(u.f_max, 30.0);
  EXPECT_NEAR(u.min_ratio, 70.0 / 30.0, 1e-9);
  EXPECT_TRUE(u.stable());
  // Gap graded (Cu = d60/d10 = 2 mm 2^(30/70) / 0.1 mm 2^(10/30) = 21.4: F up
  // to 20): at F = 20, d = 0.159 mm, 4d = 0.635 mm lies in the gap: H = 10.
  auto g = fabric::kenney_lau(gap_graded());
  EXPECT_EQ(g.f_max, 20.0);
  EXPECT_NEAR(g.min_ratio, 10.0 / 20.0, 1e-9);
  EXPECT_FALSE(g.stable());
}

TEST(SuffusionCriteria, BurenkovaUniformInsideGapGradedOutside) {
  auto u = fabric::burenkova(uniform());
  EXPECT_NEAR(u.h1, std::pow(2.0, 0.30), 1e-9);   // 1.231
  EXPECT_NEAR(u.h2, std::pow(2.0, 0.75), 1e-9);   // 1.682: band 1.172 .. 1.420
  EXPECT_TRUE(u.stable());
  auto g = fabric::burenkova(gap_graded());
  EXPECT_NEAR(g.h1, std::pow(2.0, 30.0 / 70.0), 1e-9);                 // 1.346
  EXPECT_NEAR(g.h2, 20.0 * std::pow(2.0, 60.0 / 70.0 - 0.5), 1e-9);     // 25.6
  EXPECT_FALSE(g.stable());  // h' below the band's lower edge 2.07
}

TEST(SuffusionCriteria, WanFellProbabilityFromTheFormula) {
  // Uniform: h' = 2^0.3, h'' = d20/d5 = 2^0.15.
  auto u = fabric::wan_fell(uniform());
  double z = 2.378 * std::log10(std::pow(2.0, 0.15)) - 3.648 * std::pow(2.0, 0.3) + 3.701;
  EXPECT_NEAR(u.probability, std::exp(z) / (1.0 + std::exp(z)), 1e-12);
  EXPECT_NEAR(u.probability, 0.336, 1e-3);
  EXPECT_TRUE(u.stable());
  // A broadly graded soil with a long fine tail: h'' = d20/d5 large.
  ParticleSizeDistribution tail({{1e-6, 0.0}, {1e-4, 20.0}, {1e-3, 60.0}, {1.2e-3, 90.0}, {1.3e-3, 100.0}});
  auto t = fabric::wan_fell(tail);
  EXPECT_GT(t.probability, 0.5);
  EXPECT_FALSE(t.stable());
}

TEST(SuffusionCriteria, LooseMassFinerThanAnOpening) {
  EXPECT_NEAR(fabric::mass_percent_finer({1, 2, 3}, {1, 1, 2}, 2.5), 50.0, 1e-12);
  EXPECT_EQ(fabric::mass_percent_finer({}, {}, 1.0), 0.0);
  // Strictly finer: a grain of the opening's size does not pass.
  EXPECT_EQ(fabric::mass_percent_finer({2}, {1}, 2.0), 0.0);
}
