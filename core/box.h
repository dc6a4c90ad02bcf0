// An axis-aligned box, the container of a specimen: the packer's measures
// (specimen_measure) and the constriction network's wall margin use it.
#ifndef FABRIC_BOX_H
#define FABRIC_BOX_H

#include "geometry.h"

namespace fabric {

struct Box {
  Vec3 lo, hi;
  double volume() const { return (hi - lo).cwiseMax(0.0).prod(); }
};

}  // namespace fabric

#endif
