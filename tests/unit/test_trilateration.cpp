// Unit tests of Eq. (1), Eq. (2) and the fallback placements
// (core/trilateration.*).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdio>
#include <cmath>
#include <random>

#include "trilateration.h"

using fabric::Sphere;
using fabric::Vec3;

namespace {

struct Rng {
  std::mt19937_64 g{12345};
  double uniform(double a, double b) {
    return std::uniform_real_distribution<double>(a, b)(g);
  }
  double log_uniform(double a, double b) {
    return std::exp(uniform(std::log(a), std::log(b)));
  }
  Vec3 vec(double s) { return Vec3(uniform(-s, s), uniform(-s, s), uniform(-s, s)); }
};

// Relative miss of a sphere (c, r) touching s.
double miss(const Vec3& c, double r, const Sphere& s) {
  return std::abs((c - s.centre).norm() - (r + s.radius)) / (r + s.radius);
}

// Three mutually touching spheres of the given radii, in a random pose.
void touching_face(Rng& rng, double r1, double r2, double r3, Sphere* s) {
  s[0] = Sphere{rng.vec(10), r1};
  Vec3 u = rng.vec(1).normalized();
  s[1] = Sphere{s[0].centre + (r1 + r2) * u, r2};
  Vec3 w = rng.vec(1);
  auto c3 = fabric::touch_two_in_plane(s[0], s[1], s[0].centre + w, r3);
  ASSERT_TRUE(c3.has_value());
  s[2] = Sphere{*c3, r3};
}

// Whether a sphere of radius r4 touching the three exists, found without
// the solver: the centres at r4 + r1 from c1 and r4 + r2 from c2 form a
// circle; one touches the third sphere when r4 + r3 lies between the
// circle's least and greatest distance from c3. 1 yes, 0 no, -1 within 1e-9
// of either bound (not judged).
int touching_sphere_exists(const Sphere* s, double r4) {
  const double R1 = r4 + s[0].radius, R2 = r4 + s[1].radius, R3 = r4 + s[2].radius;
  const Vec3 axis = s[1].centre - s[0].centre;
  const double d = axis.norm();
  const Vec3 u = axis / d;
  const double a = (R1 * R1 - R2 * R2 + d * d) / (2.0 * d);
  const double h2 = R1 * R1 - a * a;
  if (h2 < -1e-9 * R1 * R1) return 0;
  if (h2 <= 1e-9 * R1 * R1) return -1;
  const double h = std::sqrt(h2);
  const Vec3 v = s[2].centre - (s[0].centre + a * u);
  const double along = v.dot(u), across = (v - along * u).norm();
  const double lo = std::hypot(along, across - h), hi = std::hypot(along, across + h);
  const double tol = 1e-9 * (R3 + hi);
  if (R3 < lo - tol || R3 > hi + tol) return 0;
  if (R3 > lo + tol && R3 < hi - tol) return 1;
  return -1;
}

// A face whose third centre lies eps of the edge length off the line of the
// other two: the solution's miss grows as 1/eps (rounding of the face plane's
// normal); this bound holds down to eps 1e-6 (measured: up to 3.4e-16/eps).
constexpr double kCollinearMiss = 1e-15;

}  // namespace

TEST(Trilateration, TouchesTheThreeSpheresForRandomFaces) {
  Rng rng;
  int solved = 0, near_collinear = 0, touching = 0, fall_through = 0;
  double worst = 0.0;  // the largest miss over its tolerance
  for (int trial = 0; trial < 20000; ++trial) {
    Sphere s[3];
    double r4, tol = 1e-10;
    if (trial % 2 == 0) {  // touching faces, radius ratios up to 100
      touching_face(rng, rng.log_uniform(0.01, 1), rng.log_uniform(0.01, 1),
                    rng.log_uniform(0.01, 1), s);
      r4 = rng.log_uniform(0.01, 1);
    } else if (trial % 4 == 1) {
      // nearly collinear centres that a fourth sphere does touch: the
      // fourth sphere (P, r4) first, each radius its centre's distance to
      // P less r4
      const Vec3 a = rng.vec(3), d = rng.uniform(0.5, 2) * rng.vec(1).normalized();
      const double eps = rng.log_uniform(1e-6, 1e-2);
      tol = std::max(tol, kCollinearMiss / eps);
      const Vec3 c[3] = {a, a + d,
                         a + rng.uniform(-1, 2) * d + eps * d.norm() * d.unitOrthogonal()};
      r4 = rng.log_uniform(0.01, 0.4);
      const Vec3 P = a + rng.uniform(0, 1) * d +
                     rng.uniform(0.5, 2) * d.cross(rng.vec(1)).normalized();
      for (int i = 0; i < 3; ++i) s[i] = Sphere{c[i], (P - c[i]).norm() - r4};
    } else {  // arbitrary faces
      for (auto& q : s) q = Sphere{rng.vec(3), rng.log_uniform(0.01, 1)};
      r4 = rng.log_uniform(0.01, 3);
    }
    auto m = fabric::trilaterate(s[0], s[1], s[2], r4);
    // solved exactly when a touching sphere exists (an independent test of
    // existence; faces within 1e-9 of the boundary are not judged)
    const int exists = touching_sphere_exists(s, r4);
    if (exists == 1) {
      EXPECT_TRUE(m.has_value()) << "trial " << trial << ", r4 " << r4;
    }
    if (exists == 0) {
      EXPECT_FALSE(m.has_value()) << "trial " << trial << ", r4 " << r4;
    }
    if (trial % 2 == 0) {
      touching += exists == 1;
      fall_through += exists == 0;
    }
    if (!m) continue;
    ++solved;
    if (trial % 4 == 1) ++near_collinear;
    for (const Vec3& p : {m->positive, m->negative}) {
      ASSERT_TRUE(p.allFinite());
      for (const auto& q : s) {
        ASSERT_LT(miss(p, r4, q), tol);
        worst = std::max(worst, miss(p, r4, q) / tol);
      }
    }
    // positive lies on the right-hand normal side of (1, 2, 3)
    Vec3 n = (s[1].centre - s[0].centre).cross(s[2].centre - s[0].centre);
    EXPECT_GE((m->positive - s[0].centre).dot(n), 0.0);
    EXPECT_LE((m->negative - s[0].centre).dot(n), 0.0);
  }
  std::printf("solved %d of 20000: touching faces %d with a touching sphere, %d without "
              "(of 10000); %d of 5000 nearly collinear; largest miss %.2g of its tolerance\n",
              solved, touching, fall_through, near_collinear, worst);
  EXPECT_GT(touching, 1000);      // both sides of the existence boundary drawn
  EXPECT_GT(fall_through, 1000);
  EXPECT_EQ(near_collinear, 5000);  // each built around a fourth sphere
}

TEST(Trilateration, SolutionMovesWithTheFace) {
  Rng rng;
  int moved = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    Sphere s[3];
    touching_face(rng, rng.log_uniform(0.05, 1), rng.log_uniform(0.05, 1),
                  rng.log_uniform(0.05, 1), s);
    double r4 = rng.log_uniform(0.2, 1);
    if (touching_sphere_exists(s, r4) != 1) continue;
    auto m = fabric::trilaterate(s[0], s[1], s[2], r4);
    ASSERT_TRUE(m.has_value()) << "trial " << trial;
    ++moved;
    Eigen::Matrix3d R =
        Eigen::AngleAxisd(rng.uniform(0, 2 * M_PI), rng.vec(1).normalized())
            .toRotationMatrix();
    Vec3 T = rng.vec(100);
    Sphere t[3];
    for (int i = 0; i < 3; ++i) t[i] = Sphere{R * s[i].centre + T, s[i].radius};
    auto mt = fabric::trilaterate(t[0], t[1], t[2], r4);
    ASSERT_TRUE(mt.has_value());
    EXPECT_LT((mt->positive - (R * m->positive + T)).norm(), 1e-9 * (1 + T.norm()));
    EXPECT_LT((mt->negative - (R * m->negative + T)).norm(), 1e-9 * (1 + T.norm()));
  }
  EXPECT_GT(moved, 1000);  // of 2000 faces, those a sphere can touch
}

TEST(Trilateration, AxisAlignedFacesNeedNoSpecialCase) {
  // Centres aligned with global axes: the case Eq. (1) must survive.
  Sphere s[3] = {{Vec3(0, 0, 0), 1}, {Vec3(2, 0, 0), 1}, {Vec3(1, std::sqrt(3.0), 0), 1}};
  auto m = fabric::trilaterate(s[0], s[1], s[2], 1.0);
  ASSERT_TRUE(m.has_value());
  EXPECT_NEAR(m->positive.z(), 2.0 * std::sqrt(2.0 / 3.0), 1e-14);
  Sphere v[3] = {{Vec3(0, 0, 0), 1}, {Vec3(0, 0, 2), 1}, {Vec3(0, std::sqrt(3.0), 1), 1}};
  ASSERT_TRUE(fabric::trilaterate(v[0], v[1], v[2], 1.0).has_value());
}

TEST(Trilateration, DetectsWhenThereIsNoSolution) {
  // Three touching unit spheres: the constriction radius is 2/sqrt(3) - 1.
  Sphere s[3] = {{Vec3(0, 0, 0), 1}, {Vec3(2, 0, 0), 1}, {Vec3(1, std::sqrt(3.0), 0), 1}};
  double rc = 2.0 / std::sqrt(3.0) - 1.0;
  EXPECT_FALSE(fabric::trilaterate(s[0], s[1], s[2], 0.9 * rc).has_value());
  EXPECT_TRUE(fabric::trilaterate(s[0], s[1], s[2], 1.01 * rc).has_value());
  // spheres too far apart for a small sphere to bridge
  Sphere f[3] = {{Vec3(0, 0, 0), 1}, {Vec3(10, 0, 0), 1}, {Vec3(5, 9, 0), 1}};
  EXPECT_FALSE(fabric::trilaterate(f[0], f[1], f[2], 1.0).has_value());
  // degenerate faces
  Sphere c[3] = {{Vec3(0, 0, 0), 1}, {Vec3(2, 0, 0), 1}, {Vec3(4, 0, 0), 1}};
  EXPECT_FALSE(fabric::trilaterate(c[0], c[1], c[2], 1.0).has_value());
  Sphere d[3] = {{Vec3(0, 0, 0), 1}, {Vec3(0, 0, 0), 1}, {Vec3(4, 0, 0), 1}};
  EXPECT_FALSE(fabric::trilaterate(d[0], d[1], d[2], 1.0).has_value());
}

TEST(Trilateration, ConstrictionOfKnownFaces) {
  Sphere s[3] = {{Vec3(0, 0, 0), 1}, {Vec3(2, 0, 0), 1}, {Vec3(1, std::sqrt(3.0), 0), 1}};
  auto c = fabric::constriction(s[0], s[1], s[2]);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->radius, 2.0 / std::sqrt(3.0) - 1.0, 1e-14);
  EXPECT_LT((c->centre - Vec3(1, 1 / std::sqrt(3.0), 0)).norm(), 1e-14);
  // Random touching faces: the constriction touches all three great circles.
  Rng rng;
  for (int trial = 0; trial < 5000; ++trial) {
    Sphere t[3];
    touching_face(rng, rng.log_uniform(0.01, 1), rng.log_uniform(0.01, 1),
                  rng.log_uniform(0.01, 1), t);
    auto k = fabric::constriction(t[0], t[1], t[2]);
    ASSERT_TRUE(k.has_value());
    for (const auto& q : t) ASSERT_LT(miss(k->centre, k->radius, q), 1e-9);
    // and is exactly the limit of Eq. (1)
    EXPECT_FALSE(fabric::trilaterate(t[0], t[1], t[2], k->radius * (1 - 1e-6)).has_value());
    EXPECT_TRUE(fabric::trilaterate(t[0], t[1], t[2], k->radius * (1 + 1e-6)).has_value());
  }
}

TEST(Trilateration, FallbackPlacements) {
  Sphere a{Vec3(0, 0, 0), 1}, b{Vec3(2.5, 0, 0), 1};
  auto p = fabric::touch_two_in_plane(a, b, Vec3(1, 5, 0), 0.5);
  Sphere b2{Vec3(2.0, 0, 0), 1};
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR((*p - a.centre).norm(), 1.5, 1e-14);
  EXPECT_NEAR((*p - b.centre).norm(), 1.5, 1e-14);
  EXPECT_GT(p->y(), 0.0);  // on the side of `towards`
  EXPECT_NEAR(p->z(), 0.0, 1e-14);
  EXPECT_FALSE(fabric::touch_two_in_plane(a, b, Vec3(1, 5, 0), 0.1).has_value());
  // touching two spheres and a wall
  auto w = fabric::touch_two_and_plane(a, b2, Vec3(0, 0, -1.2), Vec3(0, 0, 1), 0.4);
  ASSERT_TRUE(w.has_value());
  for (const Vec3& q : {w->positive, w->negative}) {
    EXPECT_NEAR(q.z(), -1.2 + 0.4, 1e-14);
    EXPECT_NEAR((q - a.centre).norm(), 1.4, 1e-13);
    EXPECT_NEAR((q - b2.centre).norm(), 1.4, 1e-13);
  }
  EXPECT_TRUE(fabric::nearly_equilateral(Vec3(0, 0, 0), Vec3(2, 0, 0),
                                         Vec3(1, std::sqrt(3.0), 0), 0.1));
  EXPECT_FALSE(fabric::nearly_equilateral(Vec3(0, 0, 0), Vec3(3, 0, 0),
                                          Vec3(1, std::sqrt(3.0), 0), 0.1));
}

TEST(Trilateration, FuzzedInputGivesNoNaN) {
  Rng rng;
  const double specials[] = {0.0, -1.0, 1e-300, 1e300, NAN, INFINITY, -INFINITY};
  for (int trial = 0; trial < 50000; ++trial) {
    Sphere s[3];
    for (auto& q : s) {
      q.centre = rng.vec(rng.log_uniform(1e-6, 1e6));
      q.radius = rng.log_uniform(1e-6, 1e6);
      if (rng.g() % 10 == 0) q.centre[rng.g() % 3] = specials[rng.g() % 7];
      if (rng.g() % 10 == 0) q.radius = specials[rng.g() % 7];
    }
    double r4 = rng.g() % 10 ? rng.log_uniform(1e-6, 1e6) : specials[rng.g() % 7];
    if (auto m = fabric::trilaterate(s[0], s[1], s[2], r4)) {
      ASSERT_TRUE(m->positive.allFinite() && m->negative.allFinite());
    }
    if (auto c = fabric::constriction(s[0], s[1], s[2])) {
      ASSERT_TRUE(c->centre.allFinite() && std::isfinite(c->radius));
    }
    if (auto p = fabric::touch_two_in_plane(s[0], s[1], s[2].centre, r4)) {
      ASSERT_TRUE(p->allFinite());
    }
    if (auto w = fabric::touch_two_and_plane(s[0], s[1], s[2].centre, Vec3(0, 0, 1), r4)) {
      ASSERT_TRUE(w->positive.allFinite() && w->negative.allFinite());
    }
  }
}
