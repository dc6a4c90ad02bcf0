// Unit tests of the packing measures (fix_sequential_pack/specimen_measure.*).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <random>

#include "specimen_measure.h"

using fabric::Box;
using fabric::PackingMeasure;
using fabric::sphere_box_volume;
using fabric::Vec3;

namespace {

const double kPi = 3.14159265358979323846;

double ball(double r) { return 4.0 / 3.0 * kPi * r * r * r; }

struct Rng {
  std::mt19937_64 g{2024};
  double uniform(double a, double b) {
    return std::uniform_real_distribution<double>(a, b)(g);
  }
  Vec3 vec(double a, double b) { return Vec3(uniform(a, b), uniform(a, b), uniform(a, b)); }
};

Box box(double x0, double y0, double z0, double x1, double y1, double z1) {
  return Box{Vec3(x0, y0, z0), Vec3(x1, y1, z1)};
}

// m^3 equal spheres of radius 0.5 on a simple cubic lattice of spacing 1,
// in [0, m]^3: each touches its six neighbours.
PackingMeasure cubic_lattice(int m) {
  std::vector<Vec3> c;
  std::vector<double> r;
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        c.emplace_back(i + 0.5, j + 0.5, k + 0.5);
        r.push_back(0.5);
      }
  return PackingMeasure(c, r, box(0, 0, 0, m, m, m));
}

// Spheres on the x axis, each touching the next.
void chain(const std::vector<double>& radius, double y, std::vector<Vec3>& c,
           std::vector<double>& r) {
  double x = 0.0;
  for (std::size_t k = 0; k < radius.size(); ++k) {
    if (k > 0) x += radius[k - 1] + radius[k];
    c.emplace_back(x, y, 0.0);
    r.push_back(radius[k]);
  }
}

// Polydisperse spheres (radius ratio 25) at random places, overlaps allowed.
void random_spheres(int n, double side, Rng& rng, std::vector<Vec3>& c,
                    std::vector<double>& r, bool inside) {
  const double rmin = 0.02 * side / std::cbrt(n);
  for (int i = 0; i < n; ++i) {
    const double ri = rmin * std::exp(rng.uniform(0.0, std::log(25.0)));
    c.push_back(inside ? rng.vec(ri, side - ri) : rng.vec(0.0, side));
    r.push_back(ri);
  }
}

}  // namespace

// --- sphere_box_volume ------------------------------------------------------

TEST(SphereBoxVolume, SphereInsideIsWholeSphere) {
  EXPECT_DOUBLE_EQ(sphere_box_volume(Vec3(1, 2, 3), 0.7, box(0, 0, 0, 4, 4, 4)), ball(0.7));
  // Touching all six faces from inside.
  EXPECT_DOUBLE_EQ(sphere_box_volume(Vec3(1, 1, 1), 1.0, box(0, 0, 0, 2, 2, 2)), ball(1.0));
}

TEST(SphereBoxVolume, FaceThroughCentreGivesHalf) {
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      Box b = box(-5, -5, -5, 5, 5, 5);
      (side ? b.hi : b.lo)[axis] = 0.0;
      EXPECT_NEAR(sphere_box_volume(Vec3::Zero(), 2.0, b), ball(2.0) / 2, 1e-13 * ball(2.0))
          << "axis " << axis << " side " << side;
    }
}

TEST(SphereBoxVolume, EdgeThroughCentreGivesQuarter) {
  for (int axis = 0; axis < 3; ++axis)
    for (int q = 0; q < 4; ++q) {
      Box b = box(-5, -5, -5, 5, 5, 5);
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      (q & 1 ? b.hi : b.lo)[u] = 0.0;
      (q & 2 ? b.hi : b.lo)[v] = 0.0;
      EXPECT_NEAR(sphere_box_volume(Vec3::Zero(), 1.5, b), ball(1.5) / 4, 1e-13 * ball(1.5))
          << "edge along " << axis << " quadrant " << q;
    }
}

TEST(SphereBoxVolume, CornerThroughCentreGivesOctant) {
  const Vec3 c(0.3, -0.2, 0.1);
  for (int o = 0; o < 8; ++o) {
    Box b{c - Vec3::Constant(3.0), c + Vec3::Constant(3.0)};
    for (int k = 0; k < 3; ++k) (o >> k & 1 ? b.hi : b.lo)[k] = c[k];
    EXPECT_NEAR(sphere_box_volume(c, 1.0, b), ball(1.0) / 8, 1e-13 * ball(1.0)) << "octant " << o;
  }
}

TEST(SphereBoxVolume, DisjointIsZero) {
  EXPECT_EQ(sphere_box_volume(Vec3::Zero(), 1.0, box(1.0, -1, -1, 2, 1, 1)), 0.0);
  EXPECT_EQ(sphere_box_volume(Vec3::Zero(), 1.0, box(3, 3, 3, 4, 4, 4)), 0.0);
  // The bounding boxes meet at a corner, the sphere and the box do not.
  EXPECT_EQ(sphere_box_volume(Vec3::Zero(), 1.0, box(0.6, 0.6, 0.6, 2, 2, 2)), 0.0);
  // Empty box.
  EXPECT_EQ(sphere_box_volume(Vec3::Zero(), 1.0, box(0, 0, 0, 0, 1, 1)), 0.0);
}

TEST(SphereBoxVolume, OffCentrePlaneMatchesCapFormula) {
  const double r = 1.3, h = 0.4;  // plane at distance h from the centre
  const double cap = kPi * (r - h) * (r - h) * (2 * r + h) / 3.0;
  EXPECT_NEAR(sphere_box_volume(Vec3::Zero(), r, box(h, -9, -9, 9, 9, 9)), cap, 1e-14 * ball(r));
  EXPECT_NEAR(sphere_box_volume(Vec3::Zero(), r, box(-9, -9, -9, 9, 9, -h)), cap, 1e-14 * ball(r));
}

TEST(SphereBoxVolume, SlabThroughCentreMatchesClosedForm) {
  const double r = 1.0;
  for (double t : {1e-6, 1e-4, 0.1, 0.7, 1.5, 1.99})
    for (int axis = 0; axis < 3; ++axis) {
      Box b = box(-2, -3, -4, 2, 3, 4);
      b.lo[axis] = -t / 2;
      b.hi[axis] = t / 2;
      const double exact = kPi * (r * r * t - t * t * t / 12.0);
      EXPECT_NEAR(sphere_box_volume(Vec3::Zero(), r, b), exact, 1e-13 * exact)
          << "t " << t << " axis " << axis;
    }
}

TEST(SphereBoxVolume, PartitionOfBoxSumsToSphere) {
  Rng rng;
  for (int trial = 0; trial < 20; ++trial) {
    const double r = rng.uniform(0.5, 2.0);
    const Vec3 c = rng.vec(-0.5, 0.5);
    // A 4 x 4 x 4 partition of a box holding the sphere, with uneven cuts
    // that pass near the centre.
    std::array<std::array<double, 5>, 3> cut;
    for (int k = 0; k < 3; ++k) {
      cut[k] = {c[k] - r - 0.1, rng.uniform(-2.5, -0.5), rng.uniform(-0.5, 0.5),
                rng.uniform(0.5, 2.5), c[k] + r + 0.1};
      std::sort(cut[k].begin() + 1, cut[k].end() - 1);
    }
    double sum = 0.0;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 4; ++k)
          sum += sphere_box_volume(
              c, r, box(cut[0][i], cut[1][j], cut[2][k], cut[0][i + 1], cut[1][j + 1], cut[2][k + 1]));
    EXPECT_NEAR(sum, ball(r), 1e-12 * ball(r)) << "trial " << trial;
  }
}

TEST(SphereBoxVolume, RandomBoxesMatchMonteCarlo) {
  Rng rng;
  const int n = 1000000;
  int cut = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const double r = 1.0;
    Box b;
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = rng.uniform(-1.4, 0.7);
      b.hi[k] = b.lo[k] + rng.uniform(0.2, 2.2);
    }
    // Sample the part of the box inside the sphere's bounding box.
    const Box s{b.lo.cwiseMax(Vec3::Constant(-r)), b.hi.cwiseMin(Vec3::Constant(r))};
    const double v = sphere_box_volume(Vec3::Zero(), r, b);
    if (s.volume() <= 0.0) {
      EXPECT_EQ(v, 0.0);
      continue;
    }
    int hit = 0;
    for (int i = 0; i < n; ++i) {
      const Vec3 p(rng.uniform(s.lo[0], s.hi[0]), rng.uniform(s.lo[1], s.hi[1]),
                   rng.uniform(s.lo[2], s.hi[2]));
      hit += p.squaredNorm() < r * r;
    }
    const double p = double(hit) / n;
    const double sigma = s.volume() * std::sqrt(std::max(p * (1 - p), 1.0 / n) / n);
    EXPECT_NEAR(v, p * s.volume(), 4 * sigma) << "trial " << trial;
    cut += p > 0.0 && p < 1.0;
  }
  EXPECT_GE(cut, 6);  // most trials really cut the sphere
}

TEST(SphereBoxVolume, DiscRectangleArea) {
  using fabric::disc_rectangle_area;
  EXPECT_NEAR(disc_rectangle_area(1.0, -2, 2, -2, 2), kPi, 1e-15);
  EXPECT_NEAR(disc_rectangle_area(1.0, 0, 2, 0, 2), kPi / 4, 1e-15);
  // Square inscribed in the disc.
  const double a = 1.0 / std::sqrt(2.0);
  EXPECT_NEAR(disc_rectangle_area(1.0, -a, a, -a, a), 2.0, 1e-15);
  // Segment beyond x = 0.5: R^2 acos(h/R) - h sqrt(R^2 - h^2).
  EXPECT_NEAR(disc_rectangle_area(1.0, 0.5, 3, -3, 3), std::acos(0.5) - 0.5 * std::sqrt(0.75), 1e-15);
  EXPECT_EQ(disc_rectangle_area(1.0, 0.8, 3, 0.8, 3), 0.0);
}

// --- PackingMeasure ---------------------------------------------------------

TEST(PackingMeasure, CubicLatticePorosity) {
  const PackingMeasure m = cubic_lattice(5);
  const double expected = 1.0 - kPi / 6.0;
  EXPECT_NEAR(m.porosity(box(0, 0, 0, 5, 5, 5)), expected, 1e-13);
  EXPECT_NEAR(m.porosity(box(1, 2, 0, 4, 3, 5)), expected, 1e-13);
  // Whole cells of the lattice shifted by half a spacing: faces, edges and
  // corners through sphere centres.
  EXPECT_NEAR(m.porosity(box(0.5, 0.5, 0.5, 3.5, 4.5, 2.5)), expected, 1e-13);
  // A box in the gap between four spheres holds no solid.
  EXPECT_NEAR(m.porosity(box(0.9, 0.9, 0.2, 1.1, 1.1, 0.8)), 1.0, 1e-15);
}

TEST(PackingMeasure, CubicLatticeSubcubes) {
  const PackingMeasure m = cubic_lattice(6);
  const std::vector<double> p3 = m.subcube_porosity(3);
  ASSERT_EQ(p3.size(), 27u);
  for (double p : p3) EXPECT_NEAR(p, 1.0 - kPi / 6.0, 1e-13);
  // Sub-cubes of 1.2 spacings cut spheres off-centre; their average is
  // still the lattice's porosity.
  const std::vector<double> p5 = m.subcube_porosity(5);
  ASSERT_EQ(p5.size(), 125u);
  double mean = 0.0;
  for (double p : p5) mean += p / 125.0;
  EXPECT_NEAR(mean, 1.0 - kPi / 6.0, 1e-13);
  // x fastest: sub-cube (1, 0, 0) is the mirror image of (3, 0, 0) in x,
  // and (0, 1, 0) that of (0, 3, 0) in y.
  EXPECT_NEAR(p5[1], p5[3], 1e-13);
  EXPECT_NEAR(p5[5], p5[15], 1e-13);
  EXPECT_GT(std::abs(p5[0] - p5[1]), 1e-3);
  EXPECT_GT(std::abs(p5[1] - p5[2]), 1e-3);
}

TEST(PackingMeasure, SubcubeOrderIsXFastest) {
  // One sphere in sub-cube (i, j, k) = (2, 0, 1) of a 3 x 3 x 3 split.
  const PackingMeasure m({Vec3(2.5, 0.5, 1.5)}, {0.25}, box(0, 0, 0, 3, 3, 3));
  const std::vector<double> p = m.subcube_porosity(3);
  for (int i = 0; i < 27; ++i)
    EXPECT_EQ(p[i] < 1.0, i == 2 + 3 * (0 + 3 * 1)) << "sub-cube " << i;
}

TEST(PackingMeasure, InteriorAndWallLayerAverageToWhole) {
  const PackingMeasure m = cubic_lattice(6);
  const double whole = m.porosity(box(0, 0, 0, 6, 6, 6));
  for (double layer : {0.3, 0.75, 1.0, 2.2}) {
    const double vi = std::pow(6 - 2 * layer, 3), vw = 216.0 - vi;
    const double pi = m.interior_porosity(layer), pw = m.wall_layer_porosity(layer);
    EXPECT_NEAR((vi * pi + vw * pw) / 216.0, whole, 1e-13) << "layer " << layer;
  }
  // A layer of whole cells holds the lattice's porosity.
  EXPECT_NEAR(m.wall_layer_porosity(1.0), 1.0 - kPi / 6.0, 1e-13);
  // A layer of half a cell cuts every wall sphere through its centre: the
  // same solid fraction again.
  EXPECT_NEAR(m.wall_layer_porosity(0.5), 1.0 - kPi / 6.0, 1e-13);
  EXPECT_THROW(m.interior_porosity(3.0), std::invalid_argument);
  EXPECT_THROW(m.interior_porosity(-0.1), std::invalid_argument);
}

TEST(PackingMeasure, RegionPorosityMatchesBruteForce) {
  Rng rng;
  std::vector<Vec3> c;
  std::vector<double> r;
  random_spheres(3000, 10.0, rng, c, r, false);
  const PackingMeasure m(c, r, box(0, 0, 0, 10, 10, 10));
  for (int trial = 0; trial < 20; ++trial) {
    Box b;
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = rng.uniform(-1.0, 8.0);
      b.hi[k] = b.lo[k] + rng.uniform(0.1, 5.0);
    }
    double solid = 0.0;
    for (std::size_t i = 0; i < c.size(); ++i) solid += sphere_box_volume(c[i], r[i], b);
    const fabric::RegionPorosity got = m.measure(b);
    EXPECT_NEAR(got.solid_volume, solid, 1e-12 * solid) << "trial " << trial;
    EXPECT_DOUBLE_EQ(got.region_volume, b.volume());
    EXPECT_NEAR(got.porosity, 1.0 - solid / b.volume(), 1e-12);
  }
}

TEST(PackingMeasure, SubcubesOf1e5SpheresHoldAllSolid) {
  Rng rng;
  std::vector<Vec3> c;
  std::vector<double> r;
  const double side = 10.0;
  random_spheres(100000, side, rng, c, r, true);
  double solid = 0.0;
  for (double ri : r) solid += ball(ri);
  const auto t0 = std::chrono::steady_clock::now();
  const PackingMeasure m(c, r, box(0, 0, 0, side, side, side));
  const auto t1 = std::chrono::steady_clock::now();
  const std::vector<double> p = m.subcube_porosity(3);
  const auto t2 = std::chrono::steady_clock::now();
  double sum = 0.0;
  for (double pi : p) sum += (1.0 - pi) * std::pow(side / 3, 3);
  EXPECT_NEAR(sum, solid, 1e-11 * solid);
  EXPECT_NEAR(m.porosity(box(0, 0, 0, side, side, side)), 1.0 - solid / (side * side * side), 1e-12);
  std::cout << "[ timing   ] 1e5 spheres: bins "
            << std::chrono::duration<double>(t1 - t0).count() << " s, 27 sub-cubes "
            << std::chrono::duration<double>(t2 - t1).count() << " s\n";
}

TEST(PackingMeasure, SpearmanOfRadiusAndDistance) {
  Rng rng;
  std::vector<Vec3> c;
  std::vector<double> r;
  for (int i = 0; i < 2000; ++i) {
    c.push_back(rng.vec(0.0, 10.0));
    r.push_back(0.01 + 0.003 * (c.back() - Vec3::Constant(5.0)).norm());
  }
  const Box container = box(0, 0, 0, 10, 10, 10);
  EXPECT_NEAR(PackingMeasure(c, r, container).radius_distance_spearman(), 1.0, 1e-12);
  std::shuffle(r.begin(), r.end(), rng.g);
  EXPECT_LT(std::abs(PackingMeasure(c, r, container).radius_distance_spearman()),
            4.0 / std::sqrt(2000.0));
  // Ties get the average rank: ranks (1.5, 1.5, 3.5, 3.5) against
  // (1, 2, 3, 4) correlate 4 / sqrt(20).
  const PackingMeasure tied({Vec3(6, 5, 5), Vec3(7, 5, 5), Vec3(8, 5, 5), Vec3(9, 5, 5)},
                            {1.0, 1.0, 2.0, 2.0}, container);
  EXPECT_NEAR(tied.radius_distance_spearman(), 4.0 / std::sqrt(20.0), 1e-14);
}

TEST(PackingMeasure, TouchingPairsOfChains) {
  std::vector<Vec3> c;
  std::vector<double> r;
  chain({1, 1, 1, 1, 1}, 0.0, c, r);
  chain({2, 2, 2, 2}, 50.0, c, r);
  const PackingMeasure m(c, r, box(-5, -5, -5, 40, 60, 5));
  const auto pairs = m.touching_pairs();
  const std::vector<std::pair<int, int>> expected = {{0, 1}, {1, 2}, {2, 3}, {3, 4},
                                                      {5, 6}, {6, 7}, {7, 8}};
  EXPECT_EQ(pairs, expected);
  EXPECT_LT(m.worst_overlap(), 1e-14);
}

TEST(PackingMeasure, ContactCountsWithWalls) {
  // A row of three unit spheres along x from wall to wall, in a box 6 wide
  // and 2 deep and high: the end spheres touch one x wall, every sphere the
  // four y and z faces; a fourth sphere floats apart and touches nothing.
  const PackingMeasure m({Vec3(1, 1, 1), Vec3(3, 1, 1), Vec3(5, 1, 1), Vec3(3, 1, 1.0 + 1e-3)},
                         {1.0, 1.0, 1.0, 1e-4}, box(0, 0, 0, 6, 2, 2));
  // the small sphere lies inside sphere 1: it "touches" it (overlap), and no wall
  EXPECT_EQ(m.contact_counts(), (std::vector<int>{6, 7, 6, 1}));
  const PackingMeasure loose({Vec3(1, 1, 1), Vec3(3.01, 1, 1)}, {1.0, 1.0}, box(0, 0, 0, 10, 10, 10));
  EXPECT_EQ(loose.contact_counts(), (std::vector<int>{3, 2}));  // walls x0 y0 z0; y0 z0
  EXPECT_EQ(loose.contact_counts(0.02), (std::vector<int>{4, 3}));  // and the 0.01 gap
}

TEST(PackingMeasure, TouchingPairsMatchBruteForce) {
  Rng rng;
  std::vector<Vec3> c;
  std::vector<double> r;
  random_spheres(4000, 10.0, rng, c, r, false);
  const PackingMeasure m(c, r, box(0, 0, 0, 10, 10, 10));
  for (double tol : {0.0, 0.3, -0.2}) {
    std::vector<std::pair<int, int>> brute;
    double worst = 0.0;
    for (int i = 0; i < 4000; ++i)
      for (int j = i + 1; j < 4000; ++j) {
        const double gap = (c[i] - c[j]).norm() - r[i] - r[j];
        if (gap < tol * std::min(r[i], r[j])) brute.emplace_back(i, j);
        worst = std::max(worst, -gap / std::min(r[i], r[j]));
      }
    EXPECT_EQ(m.touching_pairs(tol), brute) << "tol " << tol;
    ASSERT_GT(brute.size(), 20u);
    EXPECT_NEAR(m.worst_overlap(), worst, 1e-12);
  }
}

TEST(PackingMeasure, SizeAssortativity) {
  std::vector<Vec3> c;
  std::vector<double> r;
  chain({1, 1, 1, 1, 1}, 0.0, c, r);
  chain({3, 3, 3, 3}, 50.0, c, r);
  EXPECT_NEAR(PackingMeasure(c, r, box(-5, -5, -5, 40, 60, 5)).size_assortativity(), 1.0, 1e-12);
  c.clear(), r.clear();
  chain({1, 2, 1, 2, 1, 2, 1}, 0.0, c, r);
  EXPECT_NEAR(PackingMeasure(c, r, box(-5, -5, -5, 40, 5, 5)).size_assortativity(), -1.0, 1e-12);
  // Without contacts the coefficient is undefined.
  EXPECT_TRUE(std::isnan(
      PackingMeasure({Vec3(0, 0, 0), Vec3(5, 0, 0)}, {1.0, 2.0}, box(-5, -5, -5, 9, 5, 5))
          .size_assortativity()));
}

// The pairs of a region: a like-size chain (a "floor layer") beside an
// alternating one. Over both the value is above 0; over the region that
// holds only the alternating chain it is -1, and a pair with one centre
// outside the region does not count.
TEST(PackingMeasure, SizeAssortativityOfARegion) {
  std::vector<Vec3> c;
  std::vector<double> r;
  chain({1, 1, 1, 3, 3, 3}, 0.0, c, r);
  chain({1, 2, 1, 2, 1, 2, 1}, 50.0, c, r);
  const PackingMeasure m(c, r, box(-5, -5, -5, 40, 60, 5));
  EXPECT_GT(m.size_assortativity(), 0.0);
  EXPECT_DOUBLE_EQ(m.size_assortativity(box(-5, -5, -5, 40, 60, 5)),
                   m.size_assortativity());
  EXPECT_NEAR(m.size_assortativity(box(-5, 40, -5, 40, 60, 5)), -1.0, 1e-12);
  // The like-size chain alone: the region cuts it between its 1s and its
  // 3s (centres at x = 0, 2, 4 and 8, 14, 20): only (1,1) pairs remain, no
  // spread, undefined; with the first 3 inside, the value is defined.
  EXPECT_TRUE(std::isnan(m.size_assortativity(box(-5, -5, -5, 5, 5, 5))));
  EXPECT_FALSE(std::isnan(m.size_assortativity(box(-5, -5, -5, 9, 5, 5))));
}

TEST(PackingMeasure, UniformityCoefficient) {
  std::vector<Vec3> c;
  std::vector<double> r;
  Rng rng;
  for (int i = 0; i < 10; ++i) c.push_back(rng.vec(0, 1)), r.push_back(0.3);
  EXPECT_DOUBLE_EQ(PackingMeasure(c, r, box(0, 0, 0, 1, 1, 1)).cu(), 1.0);
  // Inside [0, 1]^3: 8 spheres of d = 1 (volume share 1 each) and 2 of
  // d = 2 (8 each): P = 1/24 .. 8/24 at d = 1, then 16/24, 1 at d = 2.
  // d10 = 1 (between 2/24 and 3/24); d60 = 1 + (0.6 - 1/3) / (1/3) = 1.8.
  c.clear(), r.clear();
  for (int i = 0; i < 8; ++i) c.push_back(rng.vec(0, 1)), r.push_back(0.5);
  for (int i = 0; i < 2; ++i) c.push_back(rng.vec(0, 1)), r.push_back(1.0);
  // Outside it: fine spheres that would lower d10 (to about 0.58).
  for (int i = 0; i < 20; ++i) c.push_back(rng.vec(2, 3)), r.push_back(0.25);
  const PackingMeasure m(c, r, box(0, 0, 0, 3, 3, 3));
  EXPECT_NEAR(m.local_cu(box(0, 0, 0, 1, 1, 1)), 1.8, 1e-14);
  EXPECT_GT(std::abs(m.cu() - 1.8), 0.1);
  EXPECT_TRUE(std::isnan(m.local_cu(box(5, 5, 5, 6, 6, 6))));
  EXPECT_TRUE(std::isnan(PackingMeasure({Vec3(0.5, 0.5, 0.5)}, {0.1}, box(0, 0, 0, 1, 1, 1)).cu()));
}

// 27 sub-cubes of [0, 3]^3, 64 grains each at random places (overlaps do
// not matter here): two diameters, 1 and 2 (radius 0.05 and 0.1), by
// volume 1/9 and 8/9 of each cell in the mixture. Sorted, a cell holds one
// size only (local Cu 1): the ratio is 1 / Cu of the whole.
TEST(PackingMeasure, MeanLocalCuRatioOfMixedAndSortedGrains) {
  Rng rng;
  std::vector<Vec3> c;
  std::vector<double> mixed, sorted;
  for (int cell = 0; cell < 27; ++cell) {
    const Vec3 lo(cell % 3, (cell / 3) % 3, cell / 9);
    for (int g = 0; g < 64; ++g) {
      c.push_back(lo + rng.vec(0.1, 0.9));
      mixed.push_back(g % 2 == 0 ? 0.05 : 0.1);
      sorted.push_back(cell % 2 == 0 ? 0.05 : 0.1);
    }
  }
  const Box cube = box(0, 0, 0, 3, 3, 3);
  const PackingMeasure mix(c, mixed, cube), sort(c, sorted, cube);
  EXPECT_NEAR(mix.mean_local_cu_ratio(3), 1.0, 1e-12);
  EXPECT_GT(sort.cu(), 1.2);
  EXPECT_NEAR(sort.mean_local_cu_ratio(3), 1.0 / sort.cu(), 1e-12);
  // Cells of fewer grains than asked for are left out; none left: NaN.
  EXPECT_TRUE(std::isnan(mix.mean_local_cu_ratio(3, 65)));
  EXPECT_THROW(mix.mean_local_cu_ratio(0), std::invalid_argument);
}

// The profile by height is by volume: a sphere cut by a layer boundary
// counts in both layers by its volume in each, never by its centre.
TEST(PackingMeasure, LayerProfileIsByVolume) {
  // One sphere of radius 1 centred on the boundary of two layers of [0, 4]
  // x [0, 4] x [0, 4] (layers [0, 2] and [2, 4]): half of it in each.
  const PackingMeasure one({Vec3(2, 2, 2)}, {1.0}, box(0, 0, 0, 4, 4, 4));
  auto two = one.layer_profile(2);
  ASSERT_EQ(two.size(), 2u);
  for (const auto& l : two) {
    EXPECT_NEAR(l.solid_volume, 0.5 * ball(1.0), 1e-12);
    EXPECT_NEAR(l.porosity, 1.0 - 0.5 * ball(1.0) / 32.0, 1e-12);
    EXPECT_NEAR(l.mean_diameter, 2.0, 1e-12);
  }
  // Along x, three layers: a cap of height 1/3 in each outer layer, the
  // rest in the middle one (cap formula).
  auto three = one.layer_profile(3, 0);
  const double h = 4.0 / 3.0 - 1.0;  // cap height past each inner boundary
  const double cap = kPi * h * h * (3.0 - h) / 3.0;
  EXPECT_NEAR(three[0].solid_volume, cap, 1e-12);
  EXPECT_NEAR(three[2].solid_volume, cap, 1e-12);
  EXPECT_NEAR(three[1].solid_volume, ball(1.0) - 2 * cap, 1e-12);
  EXPECT_TRUE(std::isnan(one.layer_profile(8)[0].mean_diameter));  // empty
  // A bed of coarse spheres under fine ones: the profile's mean diameter
  // falls with height and its layers add up to the whole.
  std::vector<Vec3> c;
  std::vector<double> r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      c.emplace_back(i + 0.5, j + 0.5, 0.5), r.push_back(0.5);
      for (int k = 0; k < 4; ++k)
        c.emplace_back(i + 0.25 + 0.5 * (k % 2), j + 0.25 + 0.5 * (k / 2), 1.25),
            r.push_back(0.25);
    }
  const PackingMeasure bed(c, r, box(0, 0, 0, 4, 4, 2));
  auto prof = bed.layer_profile(4);
  double solid = 0.0;
  for (const auto& l : prof) solid += l.solid_volume;
  EXPECT_NEAR(solid, 16 * ball(0.5) + 64 * ball(0.25), 1e-10);
  EXPECT_NEAR(prof[0].mean_diameter, 1.0, 1e-12);
  EXPECT_NEAR(prof[1].mean_diameter, 1.0, 1e-12);
  EXPECT_NEAR(prof[2].mean_diameter, 0.5, 1e-12);
  EXPECT_TRUE(std::isnan(prof[3].mean_diameter));  // above the bed
  EXPECT_NEAR(prof[3].porosity, 1.0, 1e-12);
  EXPECT_THROW(bed.layer_profile(0), std::invalid_argument);
  EXPECT_THROW(bed.layer_profile(2, 3), std::invalid_argument);
}

TEST(PackingMeasure, WorstOverlap) {
  // Pair (0, 1) overlaps by 0.1 of the smaller radius 0.5, pair (2, 3) by
  // 0.1 of radius 1; (4, 5) only touches.
  const PackingMeasure m({Vec3(0, 0, 0), Vec3(1.4, 0, 0), Vec3(10, 0, 0), Vec3(11.9, 0, 0),
                          Vec3(20, 0, 0), Vec3(22, 0, 0)},
                         {1.0, 0.5, 1.0, 1.0, 1.0, 1.0}, box(-2, -2, -2, 24, 2, 2));
  EXPECT_NEAR(m.worst_overlap(), 0.2, 1e-12);
  const PackingMeasure apart({Vec3(0, 0, 0), Vec3(2.5, 0, 0)}, {1.0, 1.0}, box(-2, -2, -2, 4, 2, 2));
  EXPECT_EQ(apart.worst_overlap(), 0.0);
}

TEST(PackingMeasure, AllInside) {
  const Box unit = box(0, 0, 0, 1, 1, 1);
  EXPECT_TRUE(PackingMeasure({Vec3(0.1, 0.5, 0.9)}, {0.1}, unit).all_inside());
  EXPECT_TRUE(PackingMeasure({Vec3(0.5, 0.5, 0.5), Vec3(0.2, 0.2, 0.2)}, {0.5, 0.2}, unit).all_inside());
  const PackingMeasure out({Vec3(0.5, 0.5, 0.5), Vec3(0.5, 0.0999, 0.5)}, {0.2, 0.1}, unit);
  EXPECT_FALSE(out.all_inside());
  EXPECT_TRUE(out.all_inside(0.01));  // sticks out by 1e-4 = 0.001 r
  EXPECT_FALSE(PackingMeasure({Vec3(0.5, 0.5, 0.95)}, {0.1}, unit).all_inside());
}
