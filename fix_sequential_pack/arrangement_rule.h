// The arrangement rules of the packer, DA and LA: which size is drawn next,
// which two face spheres a Fig. 8 grain touches and where a specimen starts
// by default. The rule classes are in arrangement_rule.cpp, the one place
// DA and LA differ; the packer sees them through Rule and make_rule.
#ifndef FABRIC_ARRANGEMENT_RULE_H
#define FABRIC_ARRANGEMENT_RULE_H

#include <memory>
#include <vector>

#include "front_packer.h"

namespace fabric {
namespace detail {

// ---- The arrangement rules: the one place DA and LA differ. ----
// Both place a drawn grain on the lowest site that fits it; a rule decides
// which size is drawn next, which two face spheres a Fig. 8 grain touches
// and where a specimen starts by default.

// The sizes as a rule sees them, per rank (finest first): the list's count
// and where the size lies between the finest and the coarsest, in ln r.
struct Sizes {
  std::vector<long long> count;
  std::vector<double> volume;  // of one grain
  std::vector<double> x;       // 0 the finest, 1 the coarsest
};

// The deck as the next draw finds it, per rank: grains left and the share
// of the size's decks spent; t the solid volume placed so far as a share of
// the list's. Ranks 0 .. n-1 may be drawn.
struct DrawState {
  const long long* left;
  const double* spent;
  int n;
  double t;
};

class Rule {
 public:
  virtual ~Rule() = default;
  virtual Start default_start() const = 0;
  // Fig. 8: the grain touches the two smaller face spheres, else the two
  // larger.
  virtual bool touches_smaller_pair() const = 0;
  // The weight w[i] >= 0 of each rank i < st.n in the draw; all 0 when
  // none of these sizes is left in the deck.
  virtual void weigh(const DrawState& st, double* w) const = 0;
};

// The rule of arrangement a (spec.layering is LA's width; DA ignores it).
std::unique_ptr<Rule> make_rule(Arrangement a, const Sizes& sizes,
                                double layering);

}  // namespace detail
}  // namespace fabric

#endif
