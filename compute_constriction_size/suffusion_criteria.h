// Suffusion verdicts from a grading: the share of the loose grains that fit
// through the primary fabric's constrictions, and the classical geometric
// criteria of internal stability computed from the same PSD (see
// docs/compute_constriction_size.md, "Verdict").
//
// Plain C++, no LIGGGHTS include.
#ifndef FABRIC_SUFFUSION_CRITERIA_H
#define FABRIC_SUFFUSION_CRITERIA_H

#include <vector>

#include "psd.h"

namespace fabric {

// Percent of the total mass of grains (diameters d, masses m) whose diameter
// is below `opening`. 0 when there is no mass.
double mass_percent_finer(const std::vector<double>& d,
                          const std::vector<double>& m, double opening);

}  // namespace fabric

#endif
