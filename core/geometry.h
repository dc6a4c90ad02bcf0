// Plain geometry shared by every style: a point or vector in space (Vec3)
// and a sphere (its centre and radius).
//
// Plain C++ with Eigen, no LIGGGHTS include.
#ifndef FABRIC_GEOMETRY_H
#define FABRIC_GEOMETRY_H

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace fabric {

using Vec3 = Eigen::Vector3d;

struct Sphere {
  Vec3 centre;
  double radius;
};

}  // namespace fabric

#endif
