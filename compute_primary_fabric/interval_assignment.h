// Which size interval a particle of compute primary/fabric belongs to.
//
// Plain C++, no LIGGGHTS include. Three sources, finest interval first
// (index 0):
//   * the index that a packing fix stored with the particle (fix
//     sequential/pack: 1..N, 0 for atoms it did not create): of(index, d);
//   * a PSD's equal-mass intervals, contiguous diameter bounds: from_bounds;
//   * discrete sizes, each interval a range of diameters (one diameter per
//     interval for the specimen's distinct diameters, or the diameters the
//     fix's own particles have in each interval): from_ranges.
// A particle without a stored index (0) is placed by its diameter.
#ifndef FABRIC_INTERVAL_ASSIGNMENT_H
#define FABRIC_INTERVAL_ASSIGNMENT_H

#include <vector>

namespace fabric {

class IntervalAssignment {
 public:
  // Contiguous intervals [lower[k], upper[k]] of a PSD. A diameter on an
  // inner bound goes to the finer interval; one outside [lower[0],
  // upper[N-1]] by more than a relative 1e-6 fits none.
  static IntervalAssignment from_bounds(std::vector<double> lower,
                                        std::vector<double> upper);
  // Discrete intervals: interval k holds the diameters lower[k]..upper[k],
  // to a relative 1e-9. An interval with lower > upper (e.g. +inf, -inf) is
  // empty and takes no diameter. The first (finest) matching interval wins.
  static IntervalAssignment from_ranges(std::vector<double> lower,
                                        std::vector<double> upper);
  // The distinct values of `diameters` (equal to a relative 1e-9), sorted.
  static std::vector<double> distinct(std::vector<double> diameters);

  IntervalAssignment() = default;
  int intervals() const { return static_cast<int>(lower_.size()); }
  // The interval holding diameter d, or -1 if none does.
  int of_diameter(double d) const;
  // The interval of a particle with the index a packing fix stored:
  // 1..N gives interval index-1; 0 (not created by the fix) falls back to
  // of_diameter(d). Returns -1 when the fallback finds no interval.
  // Throws std::invalid_argument for an index that is not an integer in
  // 0..N (N = intervals()), naming it.
  int of(double stored_index, double diameter) const;

 private:
  enum class Kind { bounds, ranges };
  IntervalAssignment(Kind kind, std::vector<double> lower,
                     std::vector<double> upper);
  Kind kind_ = Kind::ranges;
  std::vector<double> lower_, upper_;
};

}  // namespace fabric

#endif
