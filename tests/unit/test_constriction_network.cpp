// The constriction network (compute_constriction_size/constriction_network.h)
// against lattices and analytic cases whose constrictions are known.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "constriction_network.h"
#include "suffusion_criteria.h"

using fabric::ConstrictionNetwork;
using fabric::ConstrictionOptions;
using fabric::Sphere;
using fabric::Vec3;

namespace {

// n x n x n unit cells of edge a, one sphere of radius r per basis point.
std::vector<Sphere> lattice(const std::vector<Vec3>& basis, double a, double r,
                            int n) {
  std::vector<Sphere> s;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        for (const Vec3& b : basis)
          s.push_back({a * (Vec3(i, j, k) + b), r});
  return s;
}

const std::vector<Vec3> kSC = {Vec3(0, 0, 0)};
const std::vector<Vec3> kBCC = {Vec3(0, 0, 0), Vec3(0.5, 0.5, 0.5)};
const std::vector<Vec3> kFCC = {Vec3(0, 0, 0), Vec3(0.5, 0.5, 0),
                                Vec3(0.5, 0, 0.5), Vec3(0, 0.5, 0.5)};

// Every counted constriction has radius `expected` (relative 1e-9).
void expect_all(const ConstrictionNetwork& net, double expected) {
  ASSERT_GT(net.discs.size(), 20u);
  double lo = INFINITY, hi = 0.0;
  for (const auto& d : net.discs) {
    lo = std::min(lo, d.radius);
    hi = std::max(hi, d.radius);
  }
  EXPECT_NEAR(lo, expected, 1e-9 * expected);
  EXPECT_NEAR(hi, expected, 1e-9 * expected);
  EXPECT_EQ(net.unsolved, 0);
}

// Spheres without overlap at random positions in a cube (rejection).
std::vector<Sphere> random_spheres(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> pos(0.0, 10.0), rad(0.3, 0.8);
  std::vector<Sphere> s;
  while ((int)s.size() < n) {
    Sphere c{Vec3(pos(rng), pos(rng), pos(rng)), rad(rng)};
    bool free = true;
    for (const Sphere& o : s)
      if ((o.centre - c.centre).norm() < o.radius + c.radius) free = false;
    if (free) s.push_back(c);
  }
  return s;
}

}  // namespace

TEST(ConstrictionNetwork, BodyCentredCubicEveryConstrictionIs0_22474R) {
  const double R = 1.3;
  auto net = fabric::constriction_network(
      lattice(kBCC, 4.0 * R / std::sqrt(3.0), R, 6), {});
  expect_all(net, (std::sqrt(1.5) - 1.0) * R);
  EXPECT_NEAR(net.discs[0].radius / R, 0.22474, 1e-5);
}

TEST(ConstrictionNetwork, FaceCentredCubicOnly0_15470RNoOctahedralDiagonal) {
  const double R = 0.7;
  auto net = fabric::constriction_network(
      lattice(kFCC, 2.0 * std::sqrt(2.0) * R, R, 5), {});
  expect_all(net, (2.0 / std::sqrt(3.0) - 1.0) * R);
  EXPECT_NEAR(net.discs[0].radius / R, 0.15470, 1e-5);
  // 4 spheres per cell: one octahedral and two tetrahedral pores each.
  EXPECT_LT(net.pores, net.cells);
}

TEST(ConstrictionNetwork, SimpleCubicOnly0_41421R) {
  const double R = 2.0;
  auto net = fabric::constriction_network(lattice(kSC, 2.0 * R, R, 8), {});
  expect_all(net, (std::sqrt(2.0) - 1.0) * R);
  // One pore per cube, one opening per square face.
  EXPECT_EQ(net.pores, 7 * 7 * 7);
  // A straight channel of square openings from floor to lid.
  EXPECT_NEAR(net.percolation_diameter, 2.0 * (std::sqrt(2.0) - 1.0) * R,
              1e-9 * R);
}

TEST(ConstrictionNetwork, ThreeTouchingSpheresRadii123Give6Over23) {
  // Centres at mutual distances 3, 4, 5: the inner Soddy circle.
  Sphere a{Vec3(0, 0, 0), 1.0}, b{Vec3(3, 0, 0), 2.0}, c{Vec3(0, 4, 0), 3.0};
  auto k = fabric::constriction(a, b, c);
  ASSERT_TRUE(k);
  EXPECT_NEAR(k->radius, 6.0 / 23.0, 1e-12);
  // The same face inside a network: two pores (apexes above and below)
  // share it; the box margin 0 keeps it.
  ConstrictionOptions o;
  o.wall_margin = 0.0;
  o.container = fabric::Box{Vec3(-20, -20, -20), Vec3(20, 20, 20)};
  auto net = fabric::constriction_network(
      {a, b, c, {Vec3(1, 1.3, 6), 1.0}, {Vec3(1, 1.3, -6), 1.0}}, o);
  bool found = false;
  for (const auto& d : net.discs)
    if (std::abs(d.radius - 6.0 / 23.0) < 1e-12 && std::abs(d.normal.z()) > 0.999)
      found = true;
  EXPECT_TRUE(found);
}

TEST(ConstrictionNetwork, ObtuseFaceGetsTheLargestEmptyCircleOnAnEdge) {
  // Two fine spheres above each other with a coarse one to the side: the
  // circle touching all three lies outside the triangle (Eq. 2 has none).
  Sphere a{Vec3(0, 0, -1), 0.25}, b{Vec3(0, 0, 1), 0.25},
      c{Vec3(std::sqrt(2.0), 0, 0), 1.0005};
  ASSERT_FALSE(fabric::constriction(a, b, c));
  // Brute force along the three edges: the largest gap to the three discs.
  std::array<Sphere, 3> s{a, b, c};
  double best = 0.0;
  for (int e = 0; e < 3; ++e)
    for (int k = 0; k <= 200000; ++k) {
      Vec3 p = s[e].centre + (k / 200000.0) * (s[(e + 1) % 3].centre - s[e].centre);
      double g = INFINITY;
      for (const Sphere& q : s) g = std::min(g, (p - q.centre).norm() - q.radius);
      best = std::max(best, g);
    }
  ConstrictionOptions o;
  o.wall_margin = 0.0;
  o.container = fabric::Box{Vec3(-20, -20, -20), Vec3(20, 20, 20)};
  auto net = fabric::constriction_network(
      {a, b, c, {Vec3(0.3, 3, 0), 1.0}, {Vec3(0.3, -3, 0), 1.0}}, o);
  bool found = false;
  for (const auto& d : net.discs)
    if (d.on_edge && std::abs(d.normal.y()) > 0.999) {
      found = true;
      EXPECT_NEAR(d.radius, best, 1e-6);
    }
  EXPECT_TRUE(found);
  EXPECT_GT(net.on_edge, 0);
}

TEST(ConstrictionNetwork, ScalingEveryLengthScalesEveryConstriction) {
  auto s = random_spheres(400, 7);
  auto base = fabric::constriction_network(s, {});
  for (double f : {1e-3, 7.3}) {
    auto t = s;
    for (auto& x : t) x.centre *= f, x.radius *= f;
    auto net = fabric::constriction_network(t, {});
    ASSERT_EQ(net.discs.size(), base.discs.size());
    EXPECT_EQ(net.pores, base.pores);
    auto a = fabric::cumulative_csd(base.discs);
    auto b = fabric::cumulative_csd(net.discs);
    for (std::size_t i = 0; i < a.size(); ++i)
      EXPECT_NEAR(b[i].diameter, f * a[i].diameter, 1e-9 * f * a[i].diameter);
    EXPECT_NEAR(net.percolation_diameter, f * base.percolation_diameter,
                1e-9 * f * base.percolation_diameter);
  }
}

// The primary fabric's CSD without the loose grains is the adapter's part
// (the skeleton group; tests/scene/test_constriction_size.py, fabric pf):
// here the lattice's own CSD, what the loose grains do to the whole
// specimen's, and which of them pass the lattice's opening.
TEST(ConstrictionNetwork, LooseGrainsInTheLatticePoresSplitItsPoresAndTheFineOnesPass) {
  const double R = 1.0;
  auto primary = lattice(kSC, 2.0 * R, R, 7);
  auto clean = fabric::constriction_network(primary, {});
  // Small loose grains at the cube centres: 0.4 R and 1.2 R in diameter.
  std::vector<double> loose_d, loose_m;
  auto whole = primary;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k) {
        double d = (i + j + k) % 2 ? 0.4 * R : 1.2 * R;
        whole.push_back({2.0 * R * Vec3(i + 0.5, j + 0.5, k + 0.5), d / 2});
        loose_d.push_back(d);
        loose_m.push_back(d * d * d);
      }
  // The lattice alone: one opening, (sqrt 2 - 1) R ...
  expect_all(clean, (std::sqrt(2.0) - 1.0) * R);
  // ... the whole specimen a finer one (the loose grains split the pores).
  auto all = fabric::constriction_network(whole, {});
  auto p50 = fabric::csd_percentiles(all.discs, {50.0}, false);
  EXPECT_LT(p50[0], 2.0 * (std::sqrt(2.0) - 1.0) * R * 0.99);
  // The loose grains finer than the opening 0.828 R pass: the 0.4 R ones.
  double dc = 2.0 * clean.discs[0].radius;
  int small = 0;
  for (double d : loose_d) small += d < 1.0 * R;
  double expect = 100.0 * small * 0.064 / (small * 0.064 + (216 - small) * 1.728);
  EXPECT_NEAR(fabric::mass_percent_finer(loose_d, loose_m, dc), expect, 1e-9);
}

TEST(ConstrictionNetwork, OverlapMergingAloneJoinsTheCubeOfSimpleCubic) {
  // Tolerance 0: coincidence alone joins only what rounds alike; the
  // inscribed pore spheres of a cube's tetrahedra are all the cube's
  // centre sphere, so overlap joins every cube into one pore.
  const double R = 1.0;
  ConstrictionOptions o;
  o.coincident_tolerance = 0.0;
  o.merging = fabric::PoreMerging::overlap;
  auto net = fabric::constriction_network(lattice(kSC, 2.0 * R, R, 6), o);
  EXPECT_EQ(net.pores, 5 * 5 * 5);
  expect_all(net, (std::sqrt(2.0) - 1.0) * R);
}

TEST(ConstrictionNetwork, OverlapMergingNeverAddsPores) {
  auto s = random_spheres(400, 11);
  ConstrictionOptions o;
  auto a = fabric::constriction_network(s, o);
  o.merging = fabric::PoreMerging::overlap;
  auto b = fabric::constriction_network(s, o);
  EXPECT_LT(b.pores, a.pores);
  EXPECT_LE(b.discs.size(), a.discs.size());
}

TEST(ConstrictionNetwork, InscribedPoreSphereOfARegularTetrahedron) {
  const double R = 1.0, e = 2.0 * R;  // touching spheres
  std::array<Sphere, 4> t{Sphere{Vec3(0, 0, 0), R}, Sphere{Vec3(e, 0, 0), R},
                          Sphere{Vec3(e / 2, e * std::sqrt(3.0) / 2, 0), R},
                          Sphere{Vec3(e / 2, e * std::sqrt(3.0) / 6,
                                      e * std::sqrt(2.0 / 3.0)), R}};
  auto p = fabric::inscribed_pore_sphere(t);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->radius, (std::sqrt(1.5) - 1.0) * R, 1e-12);
}

TEST(ConstrictionNetwork, BadInput) {
  std::vector<Sphere> three = {{Vec3(0, 0, 0), 1}, {Vec3(2, 0, 0), 1},
                               {Vec3(0, 2, 0), 1}};
  EXPECT_THROW(fabric::constriction_network(three, {}), std::invalid_argument);
  auto s = random_spheres(50, 3);
  s.push_back({Vec3(1, 1, 1), -1.0});
  EXPECT_THROW(fabric::constriction_network(s, {}), std::invalid_argument);
  s.back() = {Vec3(NAN, 1, 1), 1.0};
  EXPECT_THROW(fabric::constriction_network(s, {}), std::invalid_argument);
  // A small sphere inside a big one is hidden by the regular triangulation,
  // and counted.
  s.pop_back();
  s.push_back({s[0].centre + Vec3(0.01, 0, 0), 0.05});
  auto net = fabric::constriction_network(s, {});
  EXPECT_EQ(net.hidden, 1);
  // Coplanar centres: no pores.
  std::vector<Sphere> flat;
  for (int i = 0; i < 5; ++i) flat.push_back({Vec3(i, i * i, 0), 0.3});
  EXPECT_THROW(fabric::constriction_network(flat, {}), std::invalid_argument);
}

TEST(ConstrictionNetwork, PercentilesByNumberAndByDiameterCubed) {
  std::vector<fabric::ConstrictionDisc> d(4);
  for (int i = 0; i < 4; ++i) d[i].radius = i < 3 ? 1.0 : 2.0;  // D 2, 2, 2, 4
  // By number: linear between order statistics, 50 % at position 1.5.
  auto n = fabric::csd_percentiles(d, {50.0, 95.0}, false);
  EXPECT_DOUBLE_EQ(n[0], 2.0);
  EXPECT_DOUBLE_EQ(n[1], 2.0 + 0.85 * 2.0);
  // By D^3: weights 8, 8, 8, 64; the three small reach 27.3 % only.
  auto c = fabric::csd_percentiles(d, {25.0, 50.0}, true);
  EXPECT_DOUBLE_EQ(c[0], 2.0);
  EXPECT_DOUBLE_EQ(c[1], 4.0);
  auto cum = fabric::cumulative_csd(d);
  EXPECT_NEAR(cum[2].percent_cubic, 100.0 * 24.0 / 88.0, 1e-12);
  EXPECT_TRUE(std::isnan(fabric::csd_percentiles({}, {50.0}, false)[0]));
}

TEST(ConstrictionNetwork, PercentilesByArea) {
  // D 2, 2, 2, 4: areas 4, 4, 4, 16 (the three small hold 42.9 %), so D_c35
  // by area is 2 and D_c50 by area 4; by number both are 2.
  std::vector<fabric::ConstrictionDisc> d(4);
  for (int i = 0; i < 4; ++i) d[i].radius = i < 3 ? 1.0 : 2.0;
  auto a = fabric::csd_percentiles(d, {35.0, 50.0}, fabric::CsdWeight::area);
  EXPECT_DOUBLE_EQ(a[0], 2.0);
  EXPECT_DOUBLE_EQ(a[1], 4.0);
  auto cum = fabric::cumulative_csd(d);
  EXPECT_NEAR(cum[2].percent_area, 100.0 * 12.0 / 28.0, 1e-12);
  auto n = fabric::csd_percentiles(d, {50.0}, fabric::CsdWeight::number);
  EXPECT_DOUBLE_EQ(n[0], 2.0);
}
