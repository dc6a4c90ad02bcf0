// Placing a sphere on a triangular face of three spheres (paper, section 2.3).
//
// Plain C++ with Eigen, no LIGGGHTS include. Everything is solved in the
// local frame of the face (Eq. 1 and Eq. 2): origin at sphere 1, x towards
// sphere 2, y in the face plane towards sphere 3, z along the face normal.
// In that frame the only divisions are by |c2 - c1| and by the height of
// sphere 3 over the line 1-2, so no orientation of the face in the global
// frame can divide by zero; a face whose centres are (nearly) collinear has
// no frame and is reported as degenerate.
#ifndef FABRIC_TRILATERATION_H
#define FABRIC_TRILATERATION_H

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <optional>

#include "geometry.h"

namespace fabric {

// Orthonormal frame of a face; `normal` = ex x ey follows the right-hand
// rule on the vertex order (1, 2, 3).
struct FaceFrame {
  Vec3 origin, ex, ey, normal;
  double x2;      // local x of centre 2
  double x3, y3;  // local x, y of centre 3 (y3 > 0)
  Vec3 to_global(double x, double y, double z) const {
    return origin + x * ex + y * ey + z * normal;
  }
};

// Frame of the face (c1, c2, c3); empty when the centres are coincident or
// collinear to within `rel_tol` of the face size.
std::optional<FaceFrame> face_frame(const Vec3& c1, const Vec3& c2,
                                    const Vec3& c3, double rel_tol = 1e-9);

// Eq. (1): centre of a sphere of radius r4 touching the three face spheres.
// `positive` lies on the +normal side of the frame, `negative` is its mirror.
// Empty when the sphere cannot touch all three (z^2 < 0: it is smaller than
// the constriction, or the face is too obtuse) or the face is degenerate.
struct MirrorPair {
  Vec3 positive, negative;
};
std::optional<MirrorPair> trilaterate(const Sphere& s1, const Sphere& s2,
                                      const Sphere& s3, double r4);
// The same for a face whose frame is known (face_frame of the three centres,
// default tolerance) and whose spheres have radii r1, r2, r3: a face offered
// several sizes in turn computes its frame once. Bit-identical results.
// (Inline: it is the packer's innermost step.)
inline std::optional<MirrorPair> trilaterate(const FaceFrame& f, double r1,
                                             double r2, double r3, double r4) {
  double R1 = r1 + r4, R2 = r2 + r4, R3 = r3 + r4;
  // Eq. (1), first minus second and first minus third line: linear in x, y.
  double x = (R1 * R1 - R2 * R2 + f.x2 * f.x2) / (2.0 * f.x2);
  double y = (R1 * R1 - R3 * R3 + f.x3 * f.x3 + f.y3 * f.y3 -
              2.0 * f.x3 * x) / (2.0 * f.y3);
  // z from the first line, so |p - c1| = R1 holds whatever the rounding of y,
  // and |p - c2|, |p - c3| depend on y only through terms scaled by y3.
  double z2 = R1 * R1 - x * x - y * y;
  if (!(z2 >= 0.0)) return std::nullopt;
  double z = std::sqrt(z2);
  MirrorPair m{f.to_global(x, y, z), f.to_global(x, y, -z)};
  if (!m.positive.allFinite() || !m.negative.allFinite()) return std::nullopt;
  return m;
}

// Eq. (2): the constriction of the face, the largest circle in the face plane
// that touches the three spheres' great circles from inside the triangle.
struct Constriction {
  Vec3 centre;
  double radius;
};
std::optional<Constriction> constriction(const Sphere& s1, const Sphere& s2,
                                         const Sphere& s3);
// The same for a face whose frame is known (see trilaterate above).
std::optional<Constriction> constriction(const FaceFrame& f, double r1,
                                         double r2, double r3);

// Fig. 8: centre of a sphere of radius r4 in the face plane touching spheres
// a and b, on the side of the third face centre `towards`. Empty when a and
// b are too far apart for it to touch both.
std::optional<Vec3> touch_two_in_plane(const Sphere& a, const Sphere& b,
                                       const Vec3& towards, double r4);

// Eq. (1) with a wall standing in for one face sphere: centres of a sphere of
// radius r4 touching spheres a and b and the plane through `plane_point`
// with unit normal `inward` (pointing to the side the sphere lies on).
std::optional<MirrorPair> touch_two_and_plane(const Sphere& a, const Sphere& b,
                                              const Vec3& plane_point,
                                              const Vec3& inward, double r4);

// A sphere of radius r4 touching sphere a and two perpendicular walls along
// an edge of the container: wall i is the plane {x[axis_i] = plane_i} with
// the sphere on the side inward_i (+1 or -1). The walls fix two coordinates,
// the sphere the third; `positive` has the larger third coordinate.
std::optional<MirrorPair> touch_one_and_two_planes(const Sphere& a, int axis1,
                                                   double plane1,
                                                   double inward1, int axis2,
                                                   double plane2,
                                                   double inward2, double r4);
// Fig. 7: "virtually an equal-sided triangle": longest over shortest side of
// the face within 1 + tolerance.
bool nearly_equilateral(const Vec3& c1, const Vec3& c2, const Vec3& c3,
                        double tolerance);

}  // namespace fabric

#endif
