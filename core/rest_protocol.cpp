#include "rest_protocol.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace fabric {

namespace {

std::string num(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.10g", x);
  return b;
}

std::string num(long x) { return std::to_string(x); }

}  // namespace

std::string check_rule(const RestRule& r) {
  const auto bad = [](const char* kw, const std::string& v, const std::string& rule) {
    return std::string(kw) + " " + v + ": " + rule;
  };
  if (r.block < 1) return bad("every", num(r.block), "must be 1 step or more");
  if (r.check < 1 || r.block % r.check != 0)
    return bad("check", num(r.check),
               "must be 1 step or more and divide every " + num(r.block));
  if (!(r.stress_tol > 0)) return bad("stress_tol", num(r.stress_tol), "must be positive");
  if (!(r.rest_tol >= 0))
    return bad("rest_tol", num(r.rest_tol),
               "must be a positive unbalanced-force ratio, or 0 for the "
               "kinetic-energy rule");
  if (r.rest_tol > 0 && !(r.load_tol > 0))
    return bad("load_tol", num(r.load_tol), "must be a positive ratio");
  if (!(r.pf_tol > 0)) return bad("pf_tol", num(r.pf_tol), "must be positive (points)");
  if (!(r.ramp >= 0)) return bad("ramp", num(r.ramp), "must be 0 or a loading time (s)");
  if (!(r.t_max > r.ramp))
    return bad("t_max", num(r.t_max),
               "must be longer than ramp " + num(r.ramp) +
                   " s: the run could never come to rest at the full stress");
  if (r.rest_tol > 0 && r.relax_max < r.check)
    return bad("relax_max", num(r.relax_max),
               "must be at least one check, " + num(r.check) + " steps");
  if (r.reload_max < 0) return bad("reload_max", num(long(r.reload_max)), "must be 0 or more");
  if (r.relax_zero < 0) return bad("relax_zero", num(long(r.relax_zero)), "must be 0 or more steps");
  if (r.swing_from < 0) return bad("swing_from", num(r.swing_from), "must be 0 or more steps");
  return "";
}

RestProtocol::RestProtocol(const RestRule& rule, long start_step)
    : rule_(rule), start_(start_step), block_start_(start_step) {}

void RestProtocol::add_step(long, double stress, double target) {
  if (phase_ != RestPhase::loading) return;
  const double e = target != 0.0 ? stress / target - 1.0 : 0.0;
  ++n_;
  s_ += stress;
  e_ += e;
  e2_ += e * e;
}

long RestProtocol::next_decision(long step) const {
  const long from = phase_ == RestPhase::relaxing ? relax_start_ : block_start_;
  const long every = phase_ == RestPhase::relaxing ? rule_.check : rule_.block;
  if (step < from) return from + every;
  return from + every * ((step - from) / every + 1);
}

RestDecision RestProtocol::decide(long step, const RestMeasures& m) {
  if (ended()) return {};
  if (phase_ == RestPhase::relaxing) {
    if (step <= relax_start_ || (step - relax_start_) % rule_.check != 0) return {};
    return relax_check(step, m);
  }
  if (step <= block_start_ || (step - block_start_) % rule_.block != 0) return {};
  if (n_ != rule_.block) {  // a block begun under the relaxation: not a measure
    n_ = 0;
    s_ = e_ = e2_ = 0.0;
    return {};
  }
  return end_of_block(step, m);
}

RestDecision RestProtocol::stop(long step, RestPhase phase, std::string line) {
  phase_ = phase;
  end_ = step;
  RestDecision d;
  d.line = std::move(line);
  return d;
}

// The end of a block of loading (docs/fix_servo_rest.md, items 1, 3 and 4):
// the block's means, then the first decision that applies.
RestDecision RestProtocol::end_of_block(long step, const RestMeasures& m) {
  const double steady = close_block(m.primary);
  const long n_load = step - start_;
  // a servo that swings: off the target by more than swing_rms and spread
  // about its block mean by more than swing_sd, two blocks running
  swings_ = (n_load >= rule_.swing_from && block_rms_ > rule_.swing_rms &&
             block_sd_ > rule_.swing_sd)
                ? swings_ + 1
                : 0;
  if (swings_ >= 2) return servo_swings(n_load, m);
  const bool on_target = block_rms_ < rule_.stress_tol && m.t_load >= rule_.ramp;
  if (rule_.rest_tol == 0 && on_target && m.ke < rule_.ke_limit && steady < rule_.pf_tol)
    return rest_by_energy(step, m, steady);
  if (rule_.rest_tol > 0 && on_target && m.ratio < rule_.load_tol)
    return hand_over(step, m);
  if (m.t_load >= rule_.t_max) return loading_time_out(step, m, steady);
  return {};
}

double RestProtocol::close_block(double primary) {
  const double n = static_cast<double>(n_);
  block_mean_ = s_ / n;
  block_rms_ = std::sqrt(e2_ / n);
  block_sd_ = std::sqrt(std::fabs(e2_ / n - (e_ / n) * (e_ / n)));
  n_ = 0;
  s_ = e_ = e2_ = 0.0;
  ++blocks_;
  p_[2] = p_[1];
  p_[1] = p_[0];
  p_[0] = primary;
  return std::fabs(p_[0] - p_[1]) + std::fabs(p_[1] - p_[2]);
}

std::string RestProtocol::lid_stress() const {
  return "lid stress " + num(block_mean_) + " Pa";
}

RestDecision RestProtocol::servo_swings(long n_load, const RestMeasures& m) const {
  RestDecision d;
  d.swing = true;
  d.line = "the lid servo swings: over the last block (step " + num(n_load) +
           " of the loading) the lid stress averaged " + num(block_mean_) +
           " Pa against the target " + num(m.target) + " Pa, off it by " +
           num(block_rms_) + " (rms) and spread by " + num(block_sd_) +
           " about its mean, as fractions of the target, two blocks running";
  return d;
}

RestDecision RestProtocol::rest_by_energy(long step, const RestMeasures& m,
                                          double steady) {
  rest_stress_ = block_mean_;
  return stop(step, RestPhase::rest,
              "STOP: at rest after " + num(step - start_) + " steps (t = " + num(m.t_load) +
                  " s): unbalanced-force ratio " + num(m.ratio) +
                  " (rest_tol 0), kinetic energy " + num(m.ke) + " J (limit " +
                  num(rule_.ke_limit) + " J), " + lid_stress() + " (rms error " +
                  num(block_rms_) + ", tolerance " + num(rule_.stress_tol) +
                  "), primary fabric moved " + num(steady) +
                  " points over the last two blocks (tolerance " + num(rule_.pf_tol) + ")");
}

RestDecision RestProtocol::hand_over(long step, const RestMeasures& m) {
  phase_ = RestPhase::relaxing;
  relax_start_ = step;
  RestDecision d;
  d.lid = LidAction::hold;
  d.zero = rule_.relax_zero;
  d.line = "LOADED: " + lid_stress() + " over the last block (rms error " +
           num(block_rms_) + ") after " + num(step - start_) + " steps (t = " +
           num(m.t_load) + " s), unbalanced-force ratio " + num(m.ratio) +
           " (load_tol " + num(rule_.load_tol) + "): " +
           (rule_.lid_held ? "the lid is held and the grains relaxed "
                           : "the grains relaxed under the servo ") +
           "(velocities zeroed every " + num(long(rule_.relax_zero)) +
           " steps) until the ratio is below rest_tol " + num(rule_.rest_tol);
  return d;
}

RestDecision RestProtocol::loading_time_out(long step, const RestMeasures& m,
                                            double steady) {
  rest_stress_ = block_mean_;
  const std::string moved =
      p_[2] < 0 ? "primary fabric steadiness not known yet: it needs three "
                  "blocks of loading (tolerance " + num(rule_.pf_tol) + " points)"
                : "primary fabric moved " + num(steady) +
                      " points over the last two blocks (tolerance " +
                      num(rule_.pf_tol) + ")";
  RestDecision d = stop(
      step, RestPhase::time_limit,
      "STOP: maximum time " + num(rule_.t_max) + " s reached after " + num(step - start_) +
          " steps, not at rest: unbalanced-force ratio " + num(m.ratio) +
          ", kinetic energy " + num(m.ke) + " J" +
          (rule_.ke_limit > 0 ? " (limit " + num(rule_.ke_limit) + " J)" : std::string()) +
          ", " + lid_stress() + " (rms error " + num(block_rms_) + ", tolerance " +
          num(rule_.stress_tol) + "), " + moved);
  d.warning = "WARNING: not at rest at t_max " + num(rule_.t_max) + " s (stress " +
              num(m.target) +
              " Pa): the numbers below are of grains still moving; raise t_max "
              "(a lower stress takes longer), see docs/user_guide.md";
  return d;
}

RestDecision RestProtocol::relax_check(long step, const RestMeasures& m) {
  const long n_relax = relaxed_ + (step - relax_start_);
  const long n_load = step - start_;
  const double off = 100.0 * (m.stress_now / m.target - 1.0);
  const bool off_target = std::fabs(off) > 100.0 * rule_.stress_tol;
  const bool balanced = m.ratio < rule_.rest_tol;
  // a stress lost while relaxing (reload_early), or relaxed off the
  // target: the servo takes the lid again
  if (off_target && (balanced || rule_.reload_early) && reloads_ < rule_.reload_max) {
    relaxed_ = n_relax;
    rest_stress_ = m.stress_now;
    ++reloads_;
    phase_ = RestPhase::loading;
    block_start_ = step;
    n_ = 0;
    s_ = e_ = e2_ = 0.0;
    RestDecision d;
    d.lid = LidAction::release;
    d.line = std::string(balanced ? "RELOAD: relaxed" : "RELOAD: relaxing") +
             ", the lid stress is " + num(m.stress_now) + " Pa, " + num(off) +
             " % from the target (stress_tol " + num(rule_.stress_tol) +
             "), unbalanced-force ratio " + num(m.ratio) +
             ": the servo takes the lid again (" + num(long(reloads_)) + " of at most " +
             num(long(rule_.reload_max)) + ")";
    return d;
  }
  if (balanced) {
    rest_stress_ = m.stress_now;
    relaxed_ = n_relax;
    RestDecision d = stop(
        step, RestPhase::rest,
        "STOP: at rest after " + num(n_load) + " steps (t = " + num(m.t_load) + " s): " +
            num(n_load - relaxed_) + " of loading, " + num(relaxed_) +
            " of relaxation" + (rule_.lid_held ? " with the lid held" : " under the servo") +
            "; unbalanced-force ratio " + num(m.ratio) +
            " (rest_tol " + num(rule_.rest_tol) + "), lid stress " + num(m.stress_now) +
            " Pa (" + num(off) + " % from the target " + num(m.target) +
            " Pa, tolerance " + num(rule_.stress_tol) + "), the servo taken up again " +
            num(long(reloads_)) + " times");
    if (off_target)
      d.warning = "WARNING: relaxed " + num(long(reloads_)) +
                  " times, the lid stress is still " + num(off) +
                  " % from the target, more than stress_tol " + num(rule_.stress_tol) +
                  ": the packing is not static at this stress; lower load_tol (" +
                  num(rule_.load_tol) + ") or raise reload_max (" +
                  num(long(rule_.reload_max)) + ")";
    return d;
  }
  if (step - relax_start_ >= rule_.relax_max) {
    relaxed_ = n_relax;
    rest_stress_ = m.stress_now;
    RestDecision d = stop(
        step, RestPhase::relax_limit,
        "STOP: maximum time of relaxation (relax_max " + num(rule_.relax_max) +
            " steps) reached after " + num(n_load) +
            " steps, not at rest: unbalanced-force ratio " + num(m.ratio) +
            " (rest_tol " + num(rule_.rest_tol) + "), lid stress " + num(m.stress_now) +
            " Pa");
    d.warning = "WARNING: not at rest: the ratio did not fall below rest_tol " +
                num(rule_.rest_tol) + " in relax_max " + num(rule_.relax_max) +
                " steps of relaxation; the numbers below are of a packing off balance";
    return d;
  }
  return {};
}

std::array<double, 14> RestProtocol::state() const {
  return {static_cast<double>(phase_), static_cast<double>(start_), static_cast<double>(end_),
          static_cast<double>(relax_start_), static_cast<double>(relaxed_),
          static_cast<double>(reloads_), static_cast<double>(swings_),
          p_[0], p_[1], p_[2], block_mean_, block_rms_, block_sd_,
          static_cast<double>(block_start_)};
}

void RestProtocol::restore(const std::array<double, 14>& s) {
  phase_ = static_cast<RestPhase>(static_cast<int>(s[0]));
  start_ = static_cast<long>(s[1]);
  end_ = static_cast<long>(s[2]);
  relax_start_ = static_cast<long>(s[3]);
  relaxed_ = static_cast<long>(s[4]);
  reloads_ = static_cast<int>(s[5]);
  swings_ = static_cast<int>(s[6]);
  p_[0] = s[7];
  p_[1] = s[8];
  p_[2] = s[9];
  block_mean_ = s[10];
  block_rms_ = s[11];
  block_sd_ = s[12];
  block_start_ = static_cast<long>(s[13]);
  n_ = 0;
  s_ = e_ = e2_ = 0.0;
  blocks_ = 0;
}

}  // namespace fabric
