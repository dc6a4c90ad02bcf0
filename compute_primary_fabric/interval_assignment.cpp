#include "interval_assignment.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace fabric {

namespace {
constexpr double kBoundsTolerance = 1e-6;    // PSD range, relative
constexpr double kInnerBoundTolerance = 1e-12;
constexpr double kDiameterTolerance = 1e-9;  // discrete sizes, relative

[[noreturn]] void fail(const std::string& message) {
  throw std::invalid_argument("primary/fabric: " + message);
}
}  // namespace

IntervalAssignment::IntervalAssignment(Kind kind, std::vector<double> lower,
                                       std::vector<double> upper)
    : kind_(kind), lower_(std::move(lower)), upper_(std::move(upper)) {
  if (lower_.size() != upper_.size())
    fail("interval bounds: " + std::to_string(lower_.size()) +
         " lower but " + std::to_string(upper_.size()) + " upper bounds");
}

IntervalAssignment IntervalAssignment::from_bounds(std::vector<double> lower,
                                                   std::vector<double> upper) {
  IntervalAssignment a(Kind::bounds, std::move(lower), std::move(upper));
  if (a.lower_.empty()) fail("a PSD needs at least one interval");
  if (!std::is_sorted(a.upper_.begin(), a.upper_.end()))
    fail("PSD interval bounds must be given finest first");
  return a;
}

IntervalAssignment IntervalAssignment::from_ranges(std::vector<double> lower,
                                                   std::vector<double> upper) {
  return IntervalAssignment(Kind::ranges, std::move(lower), std::move(upper));
}

std::vector<double> IntervalAssignment::distinct(std::vector<double> d) {
  std::sort(d.begin(), d.end());
  std::vector<double> out;
  for (double v : d)
    if (out.empty() || v > out.back() * (1 + kDiameterTolerance))
      out.push_back(v);
  return out;
}

int IntervalAssignment::of_diameter(double d) const {
  if (!(d > 0.0) || !std::isfinite(d) || lower_.empty()) return -1;
  if (kind_ == Kind::bounds) {
    if (d < lower_.front() * (1 - kBoundsTolerance) ||
        d > upper_.back() * (1 + kBoundsTolerance))
      return -1;
    auto it = std::lower_bound(upper_.begin(), upper_.end(),
                               d * (1 - kInnerBoundTolerance));
    return std::min<int>(static_cast<int>(it - upper_.begin()),
                         intervals() - 1);
  }
  for (int k = 0; k < intervals(); ++k)
    if (lower_[k] <= upper_[k] && d >= lower_[k] * (1 - kDiameterTolerance) &&
        d <= upper_[k] * (1 + kDiameterTolerance))
      return k;
  return -1;
}

int IntervalAssignment::of(double stored_index, double diameter) const {
  if (stored_index == 0.0) return of_diameter(diameter);
  if (!(stored_index >= 1.0) || stored_index > intervals() ||
      stored_index != std::floor(stored_index)) {
    std::ostringstream m;
    m << "stored interval index " << stored_index
      << " is not an integer in 0.." << intervals()
      << " (0: a particle the packing fix did not create)";
    fail(m.str());
  }
  return static_cast<int>(stored_index) - 1;
}

}  // namespace fabric
