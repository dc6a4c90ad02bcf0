#include "trilateration.h"

#include <algorithm>
#include <cmath>

namespace fabric {

std::optional<FaceFrame> face_frame(const Vec3& c1, const Vec3& c2,
                                    const Vec3& c3, double rel_tol) {
  Vec3 u = c2 - c1, v = c3 - c1;
  double x2 = u.norm();
  double size = std::max(x2, v.norm());
  if (!(x2 > 0.0) || !std::isfinite(size)) return std::nullopt;
  FaceFrame f;
  f.origin = c1;
  f.ex = u / x2;
  f.x2 = x2;
  f.x3 = v.dot(f.ex);
  Vec3 w = v - f.x3 * f.ex;
  f.y3 = w.norm();
  if (!(f.y3 > rel_tol * size)) return std::nullopt;
  f.ey = w / f.y3;
  f.normal = f.ex.cross(f.ey);
  return f;
}

std::optional<MirrorPair> trilaterate(const Sphere& s1, const Sphere& s2,
                                      const Sphere& s3, double r4) {
  auto f = face_frame(s1.centre, s2.centre, s3.centre);
  if (!f) return std::nullopt;
  return trilaterate(*f, s1.radius, s2.radius, s3.radius, r4);
}

std::optional<Constriction> constriction(const Sphere& s1, const Sphere& s2,
                                         const Sphere& s3) {
  auto f = face_frame(s1.centre, s2.centre, s3.centre);
  if (!f) return std::nullopt;
  return constriction(*f, s1.radius, s2.radius, s3.radius);
}

std::optional<Constriction> constriction(const FaceFrame& f, double r1,
                                         double r2, double r3) {
  const double x2 = f.x2, x3 = f.x3, y3 = f.y3;
  // Eq. (2): differences of the lines give x = a0 + a1 rc, y = b0 + b1 rc;
  // the first line then is quadratic in rc.
  double a0 = (x2 * x2 + r1 * r1 - r2 * r2) / (2.0 * x2);
  double a1 = (r1 - r2) / x2;
  double b0 = (r1 * r1 - r3 * r3 + x3 * x3 + y3 * y3 - 2.0 * a0 * x3) /
              (2.0 * y3);
  double b1 = ((r1 - r3) - a1 * x3) / y3;
  double A = a1 * a1 + b1 * b1 - 1.0;
  double B = 2.0 * (a0 * a1 + b0 * b1 - r1);
  double C = a0 * a0 + b0 * b0 - r1 * r1;
  double roots[2];
  int nroots = 0;
  if (std::abs(A) < 1e-14) {
    if (B != 0.0) roots[nroots++] = -C / B;
  } else {
    double disc = B * B - 4.0 * A * C;
    if (disc < 0.0) return std::nullopt;
    double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
    roots[nroots++] = q / A;
    if (q != 0.0) roots[nroots++] = C / q;
  }
  std::optional<Constriction> best;
  for (int i = 0; i < nroots; ++i) {
    double rc = roots[i];
    if (!(rc > 0.0) || !std::isfinite(rc)) continue;
    double x = a0 + a1 * rc, y = b0 + b1 * rc;
    // Inside the triangle (0,0), (x2,0), (x3,y3), with a little slack.
    double eps = 1e-12 * x2;
    double l3 = y / y3;
    double l2 = (x - x3 * l3) / x2;
    double l1 = 1.0 - l2 - l3;
    if (l1 < -eps || l2 < -eps || l3 < -eps) continue;
    Vec3 centre = f.to_global(x, y, 0.0);
    if (!centre.allFinite()) continue;
    if (!best || rc < best->radius) best = Constriction{centre, rc};
  }
  return best;
}

std::optional<Vec3> touch_two_in_plane(const Sphere& a, const Sphere& b,
                                       const Vec3& towards, double r4) {
  Vec3 u = b.centre - a.centre;
  double d = u.norm();
  double Ra = a.radius + r4, Rb = b.radius + r4;
  if (!(d > 0.0) || d > Ra + Rb || d < std::abs(Ra - Rb)) return std::nullopt;
  Vec3 ex = u / d;
  Vec3 w = towards - a.centre;
  w -= w.dot(ex) * ex;
  double wn = w.norm();
  if (!(wn > 1e-12 * d)) return std::nullopt;
  double x = (Ra * Ra - Rb * Rb + d * d) / (2.0 * d);
  double h = std::sqrt(std::max(0.0, Ra * Ra - x * x));
  Vec3 p = a.centre + x * ex + h * (w / wn);
  if (!p.allFinite()) return std::nullopt;
  return p;
}

std::optional<MirrorPair> touch_two_and_plane(const Sphere& a, const Sphere& b,
                                              const Vec3& plane_point,
                                              const Vec3& inward, double r4) {
  // The centre lies on the plane shifted by r4; each sphere cuts that plane
  // in a circle, and the two circles meet in the two mirror solutions.
  const Vec3 q0 = plane_point + r4 * inward;
  double ha = (a.centre - q0).dot(inward), hb = (b.centre - q0).dot(inward);
  double Ra = a.radius + r4, Rb = b.radius + r4;
  double ra2 = Ra * Ra - ha * ha, rb2 = Rb * Rb - hb * hb;
  if (ra2 < 0.0 || rb2 < 0.0) return std::nullopt;
  Vec3 pa = a.centre - ha * inward, pb = b.centre - hb * inward;
  Vec3 u = pb - pa;
  double d = u.norm();
  if (!(d > 1e-12 * (Ra + Rb))) return std::nullopt;
  Vec3 ex = u / d, ey = inward.cross(ex);
  double x = (ra2 - rb2 + d * d) / (2.0 * d);
  double h2 = ra2 - x * x;
  if (h2 < 0.0) return std::nullopt;
  double h = std::sqrt(h2);
  MirrorPair m{pa + x * ex + h * ey, pa + x * ex - h * ey};
  if (!m.positive.allFinite() || !m.negative.allFinite()) return std::nullopt;
  return m;
}

std::optional<MirrorPair> touch_one_and_two_planes(const Sphere& a, int axis1,
                                                   double plane1,
                                                   double inward1, int axis2,
                                                   double plane2,
                                                   double inward2, double r4) {
  if (axis1 == axis2 || axis1 < 0 || axis2 < 0 || axis1 > 2 || axis2 > 2)
    return std::nullopt;
  const int axis3 = 3 - axis1 - axis2;
  Vec3 c;
  c[axis1] = plane1 + inward1 * r4;
  c[axis2] = plane2 + inward2 * r4;
  double d1 = c[axis1] - a.centre[axis1], d2 = c[axis2] - a.centre[axis2];
  double R = a.radius + r4;
  double h2 = R * R - d1 * d1 - d2 * d2;
  if (!(h2 >= 0.0)) return std::nullopt;
  double h = std::sqrt(h2);
  MirrorPair m{c, c};
  m.positive[axis3] = a.centre[axis3] + h;
  m.negative[axis3] = a.centre[axis3] - h;
  if (!m.positive.allFinite() || !m.negative.allFinite()) return std::nullopt;
  return m;
}

bool nearly_equilateral(const Vec3& c1, const Vec3& c2, const Vec3& c3,
                        double tolerance) {
  double s[3] = {(c2 - c1).norm(), (c3 - c2).norm(), (c1 - c3).norm()};
  double lo = *std::min_element(s, s + 3), hi = *std::max_element(s, s + 3);
  return hi <= (1.0 + tolerance) * lo;
}

}  // namespace fabric
