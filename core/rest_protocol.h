// The quasi-static loading protocol as a state machine, with no LIGGGHTS
// include (fix servo/rest is its adapter, docs/fix_servo_rest.md): a servo
// loads the specimen until its stress is on target and the grains nearly
// balanced, then the lid is held and the grains relaxed until the
// unbalanced-force ratio calls rest; a relaxed stress off the target sends
// the lid back to the servo. Under the kinetic-energy rule (rest_tol 0) the
// servo keeps the lid and rest is called by the energy, the stress and a
// steady primary fraction. A servo that swings, a maximum loading time and
// a maximum relaxation end the run too.
//
// The caller feeds every step's lid stress (add_step) and, on the steps
// next_decision() names, the measures of the packing (decide); the answer
// says what to do with the lid and the grains, and carries the line to
// print.
#ifndef FABRIC_REST_PROTOCOL_H
#define FABRIC_REST_PROTOCOL_H

#include <array>
#include <string>

namespace fabric {

struct RestRule {
  long block = 2000;         // steps of a block of loading: its stress means
                             // and the loading's checks
  long check = 500;          // steps between the relaxation's checks
  double stress_tol = 0.05;  // rms of the lid's relative stress error
  double load_tol = 0.01;    // ratio at which the servo hands the lid over
  double rest_tol = 1e-3;    // ratio of rest; 0: the kinetic-energy rule
  double ke_limit = 0.0;     // kinetic-energy rule: energy of rest (J),
                             // positive (the caller sets it)
  double pf_tol = 1.0;       // kinetic-energy rule: primary % steady within
  double t_max = 0.3;        // loading time (s) after which the run ends
  double ramp = 0.0;         // no rest before this loading time (s)
  long relax_max = 40000;    // steps of relaxation after which it ends
  int reload_max = 3;        // the servo taken up again at most this often
  bool reload_early = true;  // ... as soon as a relaxation loses the target,
                             // not only once it is balanced
  long swing_from = 6000;    // steps of loading before the swing check
  double swing_rms = 0.5;    // a swing: rms error above this ...
  double swing_sd = 0.2;     // ... and spread about the block mean above this
  int relax_zero = 100;      // kinetic damping of the relaxation (steps)
  bool lid_held = true;      // the relaxation with the lid held where the
                             // servo had it (true), or under the servo
};

// "" when the rule can be run, else what is wrong (a keyword and its value).
std::string check_rule(const RestRule& rule);

enum class RestPhase { loading = 0, relaxing = 1, rest = 2, time_limit = 3,
                       relax_limit = 4 };

// What the caller does after a decision.
enum class LidAction { none, hold, release };

struct RestMeasures {
  double t_load = 0.0;      // loading time since the protocol began (s)
  double ratio = 0.0;       // unbalanced-force ratio
  double ke = 0.0;          // kinetic energy of translation (J)
  double primary = 0.0;     // primary fraction (%)
  double stress_now = 0.0;  // lid stress of this step (Pa)
  double target = 0.0;      // target stress of this step (Pa)
};

struct RestDecision {
  LidAction lid = LidAction::none;
  int zero = -1;            // hold: the relaxation's kinetic damping interval
  bool swing = false;       // the servo swings: stop with `line` as error
  std::string line;         // what to print ("" for nothing)
  std::string warning;      // a WARNING line to print after it
};

class RestProtocol {
 public:
  explicit RestProtocol(const RestRule& rule, long start_step = 0);

  // Every step of the loading: the lid stress and the target of the step.
  void add_step(long step, double stress, double target);
  // The first step after `step` at which decide() must be called: the end
  // of a block of loading (counted from the start or the last reload), or
  // the relaxation's next check.
  long next_decision(long step) const;
  RestDecision decide(long step, const RestMeasures& m);

  // the energy limit, known once the grains' mass is
  void set_ke_limit(double joules) { rule_.ke_limit = joules; }

  RestPhase phase() const { return phase_; }
  bool ended() const { return phase_ >= RestPhase::rest; }
  long start_step() const { return start_; }
  // steps since the loading began, up to `now` or to the protocol's end
  long steps(long now) const { return (ended() ? end_ : now) - start_; }
  long steps_relaxed() const { return relaxed_; }
  int reloads() const { return reloads_; }
  int blocks() const { return blocks_; }
  // the last whole block of loading: mean stress, rms and spread of the
  // relative error (0 before the first)
  double block_stress() const { return block_mean_; }
  double block_rms() const { return block_rms_; }
  double block_sd() const { return block_sd_; }
  // the lid stress when rest was called (or at the end by a limit)
  double rest_stress() const { return rest_stress_; }

  // the state a checkpoint keeps, and back (the rule is given again)
  std::array<double, 14> state() const;
  void restore(const std::array<double, 14>& s);

 private:
  RestDecision end_of_block(long step, const RestMeasures& m);
  // the block's stress means from its sums, which start again; the new
  // primary fraction kept: returns how far it moved over the last two blocks
  double close_block(double primary);
  std::string lid_stress() const;  // the last block's, for the lines
  // the decisions at the end of a block of loading
  RestDecision servo_swings(long n_load, const RestMeasures& m) const;
  RestDecision rest_by_energy(long step, const RestMeasures& m, double steady);
  RestDecision hand_over(long step, const RestMeasures& m);
  RestDecision loading_time_out(long step, const RestMeasures& m, double steady);
  RestDecision relax_check(long step, const RestMeasures& m);
  RestDecision stop(long step, RestPhase phase, std::string line);

  RestRule rule_;
  RestPhase phase_ = RestPhase::loading;
  long start_;              // step the loading began
  long block_start_;        // step the blocks of loading are counted from:
                            // the start, or the last reload (a whole block
                            // of the servo after it, not the rest of one)
  long relax_start_ = 0;    // step the current relaxation began
  long end_ = 0;            // step the protocol ended
  long relaxed_ = 0;        // steps relaxed before the current relaxation
  int reloads_ = 0;
  int swings_ = 0;
  int blocks_ = 0;          // whole blocks of loading
  double p_[3] = {-100.0, -200.0, -300.0};  // the last primary fractions
  // the current block's sums
  long n_ = 0;
  double s_ = 0.0, e_ = 0.0, e2_ = 0.0;
  double block_mean_ = 0.0, block_rms_ = 0.0, block_sd_ = 0.0;
  double rest_stress_ = 0.0;
};

}  // namespace fabric

#endif
