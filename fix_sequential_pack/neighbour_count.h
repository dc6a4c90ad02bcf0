// How many neighbours LIGGGHTS' granular neighbour list will hold per grain
// of a packing, so that fix sequential/pack can stop with the right
// neigh_modify settings before the run overflows the list.
//
// Plain C++, no LIGGGHTS include. LIGGGHTS lists j for grain i when
// |x_i - x_j| <= (r_i + r_j) cdf + skin (granular_bin_no_newton; cdf the
// contact distance factor, at least 1).
#ifndef FABRIC_NEIGHBOUR_COUNT_H
#define FABRIC_NEIGHBOUR_COUNT_H

#include <cmath>
#include <vector>

#include "front_packer.h"
#include "specimen_measure.h"

namespace fabric {

// A safe bound first: every neighbour of the coarsest grain lies wholly
// inside the ball of radius (2 rmax) cdf + rmax + skin around it and holds
// at least a finest grain's volume. True when no grain can have more than
// `one` neighbours.
bool neighbours_surely_fit(const std::vector<double>& radius, double skin,
                           double cdf, long long one);

struct NeighbourCount {
  long long most = 0;       // the most neighbours of one grain
  double diameter = 0.0;    // that grain's diameter
  double skin_for_keep = INFINITY;  // the largest skin with which no grain
                                    // has more than `keep` (inf: any skin)
};

// The count from the packing `res` (size classes of `class_diameter`) in
// `container`, for every grain of at least half the coarsest radius (the
// count grows with the grain's size).
NeighbourCount count_neighbours(const PackingResult& res,
                                const std::vector<double>& class_diameter,
                                const Box& container, double skin, double cdf,
                                long long keep);

}  // namespace fabric

#endif
