// Unit tests of the quasi-static loading protocol (core/rest_protocol.*):
// every transition of the state machine driven by made-up measures.
#include <gtest/gtest.h>

#include <string>

#include "rest_protocol.h"

namespace {

using fabric::LidAction;
using fabric::RestDecision;
using fabric::RestMeasures;
using fabric::RestPhase;
using fabric::RestProtocol;
using fabric::RestRule;

RestRule small_rule() {
  RestRule r;
  r.block = 10;
  r.check = 5;
  r.swing_from = 30;
  r.relax_max = 40;
  r.t_max = 1.0;
  return r;
}

// Runs the protocol from its current step to its next decision with the lid
// at `stress` (target 100) on every step; returns the decision.
struct Driver {
  RestProtocol p;
  long step = 0;
  explicit Driver(const RestRule& r) : p(r, 0) {}
  RestDecision next(double stress, RestMeasures m, double swing = 0.0) {
    const long until = p.next_decision(step);
    for (long s = step + 1; s <= until; ++s)
      p.add_step(s, stress + ((s % 2) ? swing : -swing), 100.0);
    step = until;
    m.target = 100.0;
    m.t_load = step * 1e-3;
    return p.decide(step, m);
  }
};

RestMeasures ratio(double r, double stress_now = 100.0) {
  RestMeasures m;
  m.ratio = r;
  m.stress_now = stress_now;
  m.primary = 50.0;
  return m;
}

}  // namespace

TEST(RestProtocol, HandsOverOnlyWhenOnTargetAndNearlyBalanced) {
  Driver d(small_rule());
  // off target: the servo keeps the lid whatever the ratio
  EXPECT_EQ(d.next(80.0, ratio(1e-4)).lid, LidAction::none);
  // on target but the grains not balanced
  EXPECT_EQ(d.next(100.0, ratio(0.05)).lid, LidAction::none);
  EXPECT_EQ(d.p.phase(), RestPhase::loading);
  const RestDecision h = d.next(100.0, ratio(0.005));
  EXPECT_EQ(h.lid, LidAction::hold);
  EXPECT_EQ(h.zero, 100);
  EXPECT_EQ(d.p.phase(), RestPhase::relaxing);
  EXPECT_EQ(h.line.rfind("LOADED: lid stress 100 Pa", 0), 0u) << h.line;
  EXPECT_EQ(d.p.blocks(), 3);
}

TEST(RestProtocol, RelaxationChecksEveryCheckAndCallsRest) {
  Driver d(small_rule());
  d.next(100.0, ratio(0.005));  // handed over at step 10
  ASSERT_EQ(d.p.phase(), RestPhase::relaxing);
  EXPECT_EQ(d.p.next_decision(d.step), 15);
  EXPECT_FALSE(d.next(100.0, ratio(2e-3)).line.size());  // step 15: not yet
  const RestDecision s = d.next(100.0, ratio(5e-4, 99.0));  // step 20
  EXPECT_TRUE(d.p.ended());
  EXPECT_EQ(d.p.phase(), RestPhase::rest);
  EXPECT_EQ(s.line.rfind("STOP: at rest after 20 steps", 0), 0u) << s.line;
  EXPECT_NE(s.line.find("10 of loading, 10 of relaxation"), std::string::npos) << s.line;
  EXPECT_NE(s.line.find("-1 % from the target 100 Pa"), std::string::npos) << s.line;
  EXPECT_TRUE(s.warning.empty());
  EXPECT_DOUBLE_EQ(d.p.rest_stress(), 99.0);
}

TEST(RestProtocol, StressLostInTheRelaxationSendsTheLidBackToTheServo) {
  RestRule r = small_rule();
  r.reload_max = 1;
  Driver d(r);
  d.next(100.0, ratio(0.005));                             // hold at 10
  const RestDecision back = d.next(100.0, ratio(5e-4, 90.0));  // 15: lost 10 %
  EXPECT_EQ(back.lid, LidAction::release);
  EXPECT_EQ(d.p.phase(), RestPhase::loading);
  EXPECT_EQ(d.p.reloads(), 1);
  EXPECT_NE(back.line.find("-10 % from the target"), std::string::npos) << back.line;
  // after a reload the blocks of loading are counted from the reload: a
  // whole block of the servo (steps 16-25), not the rest of the block
  // begun under the relaxation (16-20) and then another (21-30)
  EXPECT_EQ(d.p.next_decision(d.step), 25);
  EXPECT_EQ(d.next(100.0, ratio(1e-4)).lid, LidAction::hold);  // step 25
  EXPECT_EQ(d.step, 25);
  // relaxed off the target again, no reload left: rest with a warning
  const RestDecision s = d.next(100.0, ratio(5e-4, 90.0));  // 30
  EXPECT_EQ(d.p.phase(), RestPhase::rest);
  EXPECT_NE(s.line.find("20 of loading, 10 of relaxation"), std::string::npos) << s.line;
  EXPECT_NE(s.warning.find("still -10 %"), std::string::npos) << s.warning;
}

TEST(RestProtocol, StressLostBeforeBalanceReloadsAtOnceUnlessToldToWait) {
  Driver d(small_rule());
  d.next(100.0, ratio(0.005));  // hold at 10
  // still off balance (ratio 2e-3 > rest_tol) and 8 % below the target
  const RestDecision back = d.next(100.0, ratio(2e-3, 92.0));
  EXPECT_EQ(back.lid, LidAction::release);
  EXPECT_EQ(back.line.rfind("RELOAD: relaxing, the lid stress is 92 Pa", 0), 0u) << back.line;
  EXPECT_EQ(d.p.steps_relaxed(), 5);
  RestRule r = small_rule();
  r.reload_early = false;
  Driver wait(r);
  wait.next(100.0, ratio(0.005));
  EXPECT_EQ(wait.next(100.0, ratio(2e-3, 92.0)).lid, LidAction::none);
  EXPECT_EQ(wait.p.phase(), RestPhase::relaxing);
  EXPECT_EQ(wait.next(100.0, ratio(5e-4, 92.0)).lid, LidAction::release);  // balanced
}

TEST(RestProtocol, RelaxationThatNeverBalancesEndsAtRelaxMax) {
  Driver d(small_rule());
  d.next(100.0, ratio(0.005));
  RestDecision s;
  for (int i = 0; i < 20 && !d.p.ended(); ++i) s = d.next(100.0, ratio(2e-3));
  EXPECT_EQ(d.p.phase(), RestPhase::relax_limit);
  EXPECT_EQ(d.step, 50);  // 40 steps of relaxation after the hold at 10
  EXPECT_EQ(s.line.rfind("STOP: maximum time of relaxation", 0), 0u) << s.line;
  EXPECT_FALSE(s.warning.empty());
}

TEST(RestProtocol, EnergyRuleNeedsEnergyStressAndASteadyFabric) {
  RestRule r = small_rule();
  r.rest_tol = 0.0;
  r.ke_limit = 1.0;
  Driver d(r);
  RestMeasures m = ratio(0.5);
  m.ke = 0.5;
  // the first two blocks cannot tell a steady fabric
  EXPECT_TRUE(d.next(100.0, m).line.empty());
  EXPECT_TRUE(d.next(100.0, m).line.empty());
  m.ke = 2.0;  // energy above the limit
  EXPECT_TRUE(d.next(100.0, m).line.empty());
  m.ke = 0.5;
  m.primary = 52.0;  // moved 2 points
  EXPECT_TRUE(d.next(100.0, m).line.empty());
  EXPECT_TRUE(d.next(100.0, m).line.empty());  // 2 + 0 points: not yet
  const RestDecision s = d.next(100.0, m);
  EXPECT_EQ(d.p.phase(), RestPhase::rest);
  EXPECT_EQ(s.lid, LidAction::none);  // the servo keeps the lid
  EXPECT_EQ(s.line.rfind("STOP: at rest after 60 steps", 0), 0u) << s.line;
}

TEST(RestProtocol, MaximumTimeEndsTheLoadingNotAtRest) {
  RestRule r = small_rule();
  r.t_max = 0.02;
  Driver d(r);
  EXPECT_TRUE(d.next(50.0, ratio(0.5)).line.empty());
  const RestDecision s = d.next(50.0, ratio(0.5));  // t = 0.02
  EXPECT_EQ(d.p.phase(), RestPhase::time_limit);
  EXPECT_EQ(s.line.rfind("STOP: maximum time 0.02 s reached after 20 steps", 0), 0u)
      << s.line;
  EXPECT_NE(s.line.find("steadiness not known yet"), std::string::npos);
  EXPECT_FALSE(s.warning.empty());
}

TEST(RestProtocol, ServoThatSwingsTwoBlocksRunningStops) {
  Driver d(small_rule());
  // swinging about a mean 40 % off: rms about 0.64, spread 0.5
  for (int i = 0; i < 3; ++i) EXPECT_FALSE(d.next(140.0, ratio(0.5), 50.0).swing);
  // step 40: the second swinging block after swing_from 30
  const RestDecision s = d.next(140.0, ratio(0.5), 50.0);
  EXPECT_TRUE(s.swing);
  EXPECT_NE(s.line.find("the lid servo swings"), std::string::npos);
  // a lid that lags steadily (no spread) is let be
  Driver lag(small_rule());
  for (int i = 0; i < 6; ++i) EXPECT_FALSE(lag.next(40.0, ratio(0.5)).swing);
}

TEST(RestProtocol, CheckpointStateCarriesTheLoadingOn) {
  RestRule r = small_rule();
  r.rest_tol = 0.0;
  r.ke_limit = 1.0;
  Driver a(r);
  RestMeasures m = ratio(0.5);
  m.ke = 0.5;
  a.next(100.0, m);
  a.next(100.0, m);
  Driver b(r);
  b.p.restore(a.p.state());
  b.step = a.step;
  // both call rest at the same block: the primary fractions went along
  EXPECT_EQ(a.next(100.0, m).line, b.next(100.0, m).line);
  EXPECT_TRUE(b.p.ended());
}

TEST(RestProtocol, RuleChecksNameTheKeyword) {
  RestRule r;
  EXPECT_EQ(fabric::check_rule(r), "");
  r.check = 300;  // does not divide 2000
  EXPECT_EQ(fabric::check_rule(r).rfind("check 300", 0), 0u);
  r = RestRule();
  r.rest_tol = -1e-3;
  EXPECT_EQ(fabric::check_rule(r).rfind("rest_tol -0.001", 0), 0u);
  r = RestRule();
  r.ramp = 0.5;
  r.t_max = 0.3;
  EXPECT_EQ(fabric::check_rule(r).rfind("t_max 0.3", 0), 0u);
}
