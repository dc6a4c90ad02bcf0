// Suffusion verdicts from a grading: the share of the loose grains that fit
// through the primary fabric's constrictions, and the classical geometric
// criteria of internal stability computed from the same PSD (see
// docs/compute_constriction_size.md and results/constriction/README.md).
//
// Plain C++, no LIGGGHTS include. Diameters at a percent passing come from
// ParticleSizeDistribution (linear in log d between sieve points).
#ifndef FABRIC_SUFFUSION_CRITERIA_H
#define FABRIC_SUFFUSION_CRITERIA_H

#include <vector>

#include "psd.h"

namespace fabric {

// Percent of the total mass of grains (diameters d, masses m) whose diameter
// is below `opening`. 0 when there is no mass.
double mass_percent_finer(const std::vector<double>& d,
                          const std::vector<double>& m, double opening);

// Sources of the formulas and thresholds below: the criteria's papers as
// quoted by the USACE RMC Internal Instability Toolbox manual (RMC-CPD-2023-10,
// 2023; "Burenkova Method", "Modified Burenkova Method", "Modified Kenney and
// Lau Method" pages; usace-rmc.github.io/RMC-Software-Documentation), which
// interpolates d_x as ParticleSizeDistribution does. Logarithms are decimal
// (the sources write "log").

// Kezdi (1979): split the grading at F % passing into a fine and a coarse
// part; D'15 is the 15 % size of the coarse part, d'85 the 85 % size of the
// fine part. Internally stable if D'15/d'85 <= 4 at every split (Terzaghi's
// filter rule applied to the soil's own parts); here the largest ratio over
// the splits F = 1, 2, ..., 99 %.
struct KezdiResult {
  double max_ratio, at_percent;
  bool stable() const { return max_ratio <= 4.0; }
};
KezdiResult kezdi(const ParticleSizeDistribution& psd);

// Kenney & Lau (1985; boundary revised from 1.3 to 1 in 1986): F the % finer
// than d, H the % between d and 4d; stable if H/F >= 1 for every F up to
// 20 % (widely graded, Cu > 3) or 30 % (narrowly graded, Cu <= 3). Here the
// smallest H/F over F = 0.5, 1.0, ... up to that bound.
struct KenneyLauResult {
  double min_ratio, at_percent, f_max;
  bool stable() const { return min_ratio >= 1.0; }
};
KenneyLauResult kenney_lau(const ParticleSizeDistribution& psd);
// The bound on F for a uniformity coefficient: 30 for Cu <= 3, else 20, Cu
// taken to three significant figures, the precision a grading's Cu is
// stated to (a Cu of 3.0 interpolated from a PSD's points as 3.00001 is
// narrowly graded).
double kenney_lau_f_max(double uniformity_coefficient);

// Burenkova (1993), cohesionless sand-gravel soils (d_max up to 100 mm, Cu
// up to 200): h' = d90/d60, h'' = d90/d15; non-suffusive (zone II) inside
// 0.76 log(h'') + 1 < h' < 1.86 log(h'') + 1, suffusive below (zone I) and
// above (zone III).
struct BurenkovaResult {
  double h1, h2;  // h', h''
  bool stable() const;
};
BurenkovaResult burenkova(const ParticleSizeDistribution& psd);

// Wan & Fell (2008), "modified Burenkova" logistic regressions on Burenkova's
// h' = d90/d60 and h'' = d90/d15: probability of internal instability
// P = e^Z / (1 + e^Z) with
//   Z = 2.378 log(h'') - 3.648 h' + 3.701  (silt-sand-gravel and
//       clay-silt-sand-gravel soils, clay fraction <= 10 %, PI <= 12), and
//   Z = 3.875 log(h'') - 3.591 h' + 2.436  (sand-gravel soils with <= 10 %
//       non-plastic fines).
// Wan & Fell give probability contours, not a single boundary; stable() is
// this code's reading P <= 0.5 (of the silt-sand-gravel regression).
struct WanFellResult {
  double h1, h2;                    // h' = d90/d60, h'' = d90/d15
  double probability;               // silt-sand-gravel regression
  double probability_sand_gravel;   // sand-gravel regression
  bool stable() const { return probability <= 0.5; }
};
WanFellResult wan_fell(const ParticleSizeDistribution& psd);

}  // namespace fabric

#endif
