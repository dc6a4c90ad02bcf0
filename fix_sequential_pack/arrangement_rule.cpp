// The arrangement rules, DA (Discrete) and LA (GradedBed): the one place DA
// and LA differ (see arrangement_rule.h).
#include "arrangement_rule.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace fabric {
namespace detail {

namespace {

// DA: how much faster than by number the coarsest size is drawn (x^2
// between).
constexpr double kCoarseBoost = 0.6;
// LA: how strongly a size that falls behind its schedule is favoured:
// e^(100 x) for a size x (as a share of its deck) behind.
constexpr double kCatchUp = 100.0;

// DA: by number, the coarse sizes up to 60 % faster, so a deck's coarse
// grains are placed before the container is nearly full, where they would
// find no room.
class Discrete : public Rule {
 public:
  explicit Discrete(const Sizes& sizes) {
    for (double x : sizes.x) boost_.push_back(1.0 + kCoarseBoost * x * x);
  }
  Start default_start() const override { return Start::automatic; }
  bool touches_smaller_pair() const override { return false; }
  void weigh(const DrawState& st, double* w) const override {
    for (int i = 0; i < st.n; ++i)
      w[i] = static_cast<double>(st.left[i]) * boost_[i];
  }

 private:
  std::vector<double> boost_;
};

// LA, a graded bed: the draw follows the list from the coarsest size to the
// finest. The list ordered coarse first gives each size a share [b, e] of
// its solid volume; at t the size is drawn with weight (left in the deck)
// * exp(-(t - (b + e) / 2)^2 / (2 w^2)), w = spec.layering, and a size that
// falls behind its schedule (by t it should have spent min(1, (t - b) /
// (e - b)) of its deck) is favoured by kCatchUp, so no size is starved.
class GradedBed : public Rule {
 public:
  GradedBed(const Sizes& sizes, double width) : width_(width) {
    if (!(width > 0.0 && std::isfinite(width)))
      throw std::invalid_argument("layering must be positive and finite, got " +
                                  std::to_string(width));
    const int n = static_cast<int>(sizes.count.size());
    double total = 0.0;
    for (int i = 0; i < n; ++i) total += sizes.count[i] * sizes.volume[i];
    begin_.assign(n, 0.0), end_.assign(n, 0.0);
    double done = 0.0;
    for (int i = n - 1; i >= 0; --i) {
      begin_[i] = done / total;
      done += sizes.count[i] * sizes.volume[i];
      end_[i] = done / total;
    }
  }
  Start default_start() const override { return Start::floor; }
  bool touches_smaller_pair() const override { return true; }
  void weigh(const DrawState& st, double* w) const override {
    double top = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < st.n; ++i) {
      w[i] = -std::numeric_limits<double>::infinity();  // ln of the weight
      if (st.left[i] <= 0) continue;
      double d = (st.t - 0.5 * (begin_[i] + end_[i])) / width_;
      double due = end_[i] > begin_[i]
          ? std::clamp((st.t - begin_[i]) / (end_[i] - begin_[i]), 0.0, 1.0)
          : 1.0;
      double behind = std::max(0.0, due - st.spent[i]);
      w[i] = std::log(static_cast<double>(st.left[i])) - 0.5 * d * d +
             kCatchUp * behind;
      top = std::max(top, w[i]);
    }
    for (int i = 0; i < st.n; ++i)
      w[i] = st.left[i] > 0 ? std::exp(w[i] - top) : 0.0;
  }

 private:
  double width_;
  std::vector<double> begin_, end_;  // per rank, shares of the list's volume
};

}  // namespace

std::unique_ptr<Rule> make_rule(Arrangement a, const Sizes& sizes,
                                double layering) {
  if (a == Arrangement::layerwise)
    return std::make_unique<GradedBed>(sizes, layering);
  return std::make_unique<Discrete>(sizes);
}

}  // namespace detail
}  // namespace fabric
