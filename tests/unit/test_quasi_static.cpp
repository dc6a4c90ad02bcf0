// Unit tests of the quasi-static mechanics (core/quasi_static.*): Cundall's
// local damping and the unbalanced-force ratio.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "quasi_static.h"

namespace {

// A grain of mass m under a constant force F from rest, integrated as
// LIGGGHTS' nve/sphere does (velocity Verlet: half kick, drift, force,
// half kick), with the damping applied to the force each step. Returns the
// kinetic energy and the distance travelled.
struct Motion {
  double kinetic, distance;
};
Motion push(double force, double alpha, int steps) {
  const double m = 2.0, dt = 1e-3;
  double x = 0.0, v = 0.0;
  double f = fabric::local_damping(force, v, alpha);
  for (int s = 0; s < steps; ++s) {
    v += 0.5 * dt * f / m;
    x += dt * v;
    f = fabric::local_damping(force, v, alpha);  // v: the half-step velocity
    v += 0.5 * dt * f / m;
  }
  return {0.5 * m * v * v, x};
}

}  // namespace

TEST(LocalDamping, ConstantForceDoesWorkReducedByAlpha) {
  // The damping works against the motion with alpha |F|: the grain gains
  // (1 - alpha) F x of kinetic energy, the damping took alpha F x. (The
  // first half kick from rest, v = 0, is undamped: 1 of 2,000 half kicks,
  // hence the 1e-5.)
  for (double alpha : {0.0, 0.2, 0.7, 0.9}) {
    const Motion m = push(3.0, alpha, 1000);
    ASSERT_GT(m.distance, 0.0);
    EXPECT_NEAR(m.kinetic / (3.0 * m.distance), 1.0 - alpha, 1e-5)
        << "alpha " << alpha;
  }
}

TEST(LocalDamping, OpposesTheVelocityNotTheForce) {
  // A force along the motion is reduced, a force against it (a grain being
  // braked) is raised: both take energy out.
  EXPECT_DOUBLE_EQ(fabric::local_damping(10.0, 1.0, 0.5), 5.0);
  EXPECT_DOUBLE_EQ(fabric::local_damping(-10.0, 1.0, 0.5), -15.0);
  EXPECT_DOUBLE_EQ(fabric::local_damping(10.0, -1.0, 0.5), 15.0);
  EXPECT_DOUBLE_EQ(fabric::local_damping(-10.0, -1.0, 0.5), -5.0);
}

TEST(LocalDamping, NoForceNoDamping) {
  double f[3] = {0.0, 0.0, 0.0};
  const double v[3] = {1.0, -2.0, 3.0};
  fabric::damp_locally(f, v, 0.7);
  EXPECT_EQ(f[0], 0.0);
  EXPECT_EQ(f[1], 0.0);
  EXPECT_EQ(f[2], 0.0);
  // a grain at rest under a force is not held back: it starts to move
  double g[3] = {1.0, -2.0, 3.0};
  const double still[3] = {0.0, 0.0, 0.0};
  fabric::damp_locally(g, still, 0.7);
  EXPECT_EQ(g[0], 1.0);
  EXPECT_EQ(g[1], -2.0);
  EXPECT_EQ(g[2], 3.0);
}

TEST(LocalDamping, ValidRange) {
  EXPECT_TRUE(fabric::valid_local_damping(0.0));
  EXPECT_TRUE(fabric::valid_local_damping(0.7));
  EXPECT_FALSE(fabric::valid_local_damping(1.0));
  EXPECT_FALSE(fabric::valid_local_damping(-0.1));
  EXPECT_FALSE(fabric::valid_local_damping(std::nan("")));
}

TEST(UnbalancedForce, StaticColumnIsBalanced) {
  // Three grains in a column between a floor (j = -1) and a lid pressing
  // with 5 N: every contact carries 5 N, every grain's resultant is 0.
  std::vector<fabric::PairForce> c = {
      {0, -1, {0.0, 0.0, 5.0}},   // floor pushes grain 0 up
      {1, 0, {0.0, 0.0, 5.0}},    // grain 0 pushes grain 1 up
      {2, 1, {0.0, 0.0, 5.0}},    // grain 1 pushes grain 2 up
      {2, -1, {0.0, 0.0, -5.0}},  // the lid pushes grain 2 down
  };
  const fabric::ForceBalance b = fabric::balance_of(3, c, {});
  EXPECT_EQ(b.grains, 3.0);
  EXPECT_EQ(b.contacts, 4.0);
  EXPECT_DOUBLE_EQ(b.contact_sum / b.contacts, 5.0);
  EXPECT_EQ(b.ratio(), 0.0);
}

TEST(UnbalancedForce, OneGrainOffBalance) {
  // The same column with the middle grain pushed sideways by 2 N: one
  // resultant of 2 N over three grains, contacts of 5 N on average.
  std::vector<fabric::PairForce> c = {
      {0, -1, {0.0, 0.0, 5.0}},
      {1, 0, {0.0, 0.0, 5.0}},
      {2, 1, {0.0, 0.0, 5.0}},
      {2, -1, {0.0, 0.0, -5.0}},
  };
  std::vector<std::array<double, 3>> ext = {{0, 0, 0}, {2.0, 0, 0}, {0, 0, 0}};
  const fabric::ForceBalance b = fabric::balance_of(3, c, ext);
  EXPECT_NEAR(b.ratio(), (2.0 / 3.0) / 5.0, 1e-15);
}

TEST(UnbalancedForce, LooseGrainsAreNotCounted) {
  // A grain without contacts (a rattler drifting in a pore) neither adds a
  // resultant nor dilutes the mean.
  std::vector<fabric::PairForce> c = {{0, -1, {0.0, 0.0, 4.0}},
                                      {0, -1, {0.0, 0.0, -3.0}}};
  const fabric::ForceBalance b = fabric::balance_of(2, c, {{0, 0, 0}, {9, 9, 9}});
  EXPECT_EQ(b.grains, 1.0);
  EXPECT_NEAR(b.ratio(), 1.0 / 3.5, 1e-15);
}

TEST(UnbalancedForce, NoContactForceIsNotRest) {
  fabric::ForceBalance b;
  EXPECT_TRUE(std::isinf(b.ratio()));
  const double f[3] = {0.0, 0.0, 0.0};
  b.add_grain(f);
  b.add_contact(0.0);
  EXPECT_TRUE(std::isinf(b.ratio()));
}

TEST(UnbalancedForce, SumsRoundTrip) {
  fabric::ForceBalance b;
  const double f[3] = {3.0, 4.0, 0.0};
  b.add_grain(f);
  b.add_contact(-10.0);
  const fabric::ForceBalance c = fabric::ForceBalance::from_sums(b.sums());
  EXPECT_EQ(c.ratio(), b.ratio());
  EXPECT_DOUBLE_EQ(c.ratio(), 0.5);
}
