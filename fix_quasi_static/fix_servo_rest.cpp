#include "fix_servo_rest.h"

#include <cmath>
#include <cstring>
#include <string>

#include "atom.h"
#include "comm.h"
#include "compute.h"
#include "error.h"
#include "fabric_outputs.h"
#include "fix_quasi_static.h"
#include "input.h"
#include "modify.h"
#include "rest_outputs.h"
#include "style_args.h"
#include "update.h"
#include "variable.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
constexpr int kStateSize = 14;  // RestProtocol::state()

double positive(const StyleArgs &args, int i, const char *what) {
  const double x = args.number(i, what);
  args.require(x > 0, i, "must be positive");
  return x;
}

// A keyword of the protocol's rule at args[i] (docs/fix_servo_rest.md).
void read_rule_keyword(const StyleArgs &args, int i, fabric::RestRule &rule) {
  const std::string kw = args[i];
  if (kw == "every") {
    rule.block = args.integer_in(i, 1, 1000000000, "steps of a block of loading");
  } else if (kw == "check") {
    rule.check = args.integer_in(i, 1, 1000000000, "steps between the relaxation's checks");
  } else if (kw == "stress_tol") {
    rule.stress_tol = positive(args, i, "the rms relative stress error of rest");
  } else if (kw == "load_tol") {
    rule.load_tol = positive(args, i, "the unbalanced-force ratio at which the servo hands over");
  } else if (kw == "rest_tol") {
    rule.rest_tol = args.number(i, "the unbalanced-force ratio of rest, or 0");
    args.require(rule.rest_tol >= 0, i,
                 "must be a positive unbalanced-force ratio (rest by force "
                 "balance), or 0 for the kinetic-energy rule");
  } else if (kw == "pf_tol") {
    rule.pf_tol = positive(args, i, "the primary fraction's steadiness (points)");
  } else if (kw == "t_max") {
    rule.t_max = positive(args, i, "the maximum loading time (s)");
  } else if (kw == "ramp") {
    rule.ramp = args.number(i, "a loading time (s)");
    args.require(rule.ramp >= 0, i, "must be 0 or a loading time (s)");
  } else if (kw == "relax_max") {
    rule.relax_max = args.integer_in(i, 1, 2000000000, "steps of relaxation");
  } else if (kw == "reload_max") {
    rule.reload_max = static_cast<int>(args.integer_in(i, 0, 1000000, "reloads"));
  } else if (kw == "lid") {
    rule.lid_held = args.choice(i, {"servo", "held"}) == 1;
  } else if (kw == "reload_early") {
    rule.reload_early = args.yes_no(i);
  } else if (kw == "relax_zero") {
    rule.relax_zero = static_cast<int>(
        args.integer_in(i, 0, 1000000000, "0: none; N: velocities zeroed every N steps"));
  } else if (kw == "swing_from") {
    rule.swing_from = args.integer_in(i, 0, 2000000000, "steps of loading");
  } else {
    args.unknown_keyword(i);
  }
}
}  // namespace

FixServoRest::FixServoRest(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg) {
  if (narg < 5)
    error->all(FLERR, "Fix servo/rest: give the ID of the servo wall (a fix "
                      "mesh/surface/stress/servo) and of a fix quasi/static, "
                      "then the keywords stress and area");
  lid_id_ = arg[3];
  qs_id_ = arg[4];
  read_keywords(narg - 5, arg + 5);
  protocol_.reset(new fabric::RestProtocol(rule_, update->ntimestep));
  vector_flag = 1;
  size_vector = fabric::kRestEntries;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
}

// The keywords after the two fix IDs: the target and the wall here, the
// protocol's rule in read_rule_keyword; then what the keywords need together.
void FixServoRest::read_keywords(int narg, char **arg) {
  StyleArgs args(error, "Fix servo/rest", narg, arg,
                 {"stress", "area", "every", "check", "stress_tol", "load_tol",
                  "rest_tol", "ke_vrms", "pf_tol", "t_max", "ramp", "relax_max",
                  "reload_max", "reload_early", "relax_zero", "swing_from", "lid"});
  bool have_stress = false;
  for (int i = 0; i < args.size(); i += 2) {
    const std::string kw = args[i];
    if (kw == "stress") {
      const char *v = args.value(i, "the target stress of the wall (Pa), a "
                                    "number or v_name of an equal-style variable");
      if (strncmp(v, "v_", 2) == 0) {
        stress_var_ = v + 2;
      } else {
        stress_ = positive(args, i, "the target stress (Pa)");
      }
      have_stress = true;
    } else if (kw == "area") {
      area_ = positive(args, i, "the wall's area (m^2), over which its force is a stress");
    } else if (kw == "ke_vrms") {
      ke_vrms_ = positive(args, i, "the grains' rms speed of rest (m/s)");
    } else {
      read_rule_keyword(args, i, rule_);
    }
  }
  if (!have_stress || area_ <= 0)
    error->all(FLERR, "Fix servo/rest: needs the keywords stress (the target, "
                      "Pa) and area (the wall's, m^2)");
  if (rule_.rest_tol == 0 && ke_vrms_ <= 0)
    error->all(FLERR, "Fix servo/rest: rest_tol 0 (the kinetic-energy rule) "
                      "needs ke_vrms, the grains' rms speed of rest (m/s)");
  const std::string why = fabric::check_rule(rule_);
  if (!why.empty()) error->all(FLERR, ("Fix servo/rest: " + why).c_str());
}

int FixServoRest::setmask() { return END_OF_STEP; }

// The fixes are looked up when a run needs them: write_restart initialises
// every fix after the scene has removed the walls it cannot store.
void FixServoRest::find_fixes() {
  const int l = modify->find_fix(lid_id_.c_str());
  if (l < 0)
    error->all(FLERR, ("Fix servo/rest: servo wall fix ID '" + lid_id_ + "' does not exist").c_str());
  lid_ = modify->fix[l];
  if (strcmp(lid_->style, "mesh/surface/stress/servo") != 0)
    error->all(FLERR, ("Fix servo/rest: fix '" + lid_id_ + "' is a fix " + lid_->style +
                       ", not a fix mesh/surface/stress/servo")
                          .c_str());
  const int q = modify->find_fix(qs_id_.c_str());
  if (q < 0)
    error->all(FLERR, ("Fix servo/rest: fix quasi/static ID '" + qs_id_ + "' does not exist").c_str());
  if (strcmp(modify->fix[q]->style, "quasi/static") != 0)
    error->all(FLERR, ("Fix servo/rest: fix '" + qs_id_ + "' is a fix " + modify->fix[q]->style +
                       ", not a fix quasi/static")
                          .c_str());
  qs_ = static_cast<FixQuasiStatic *>(modify->fix[q]);
  if (!qs_->balance_compute())
    error->all(FLERR, ("Fix servo/rest: fix quasi/static '" + qs_id_ +
                       "' has no balance compute: the ratio needs one")
                          .c_str());
  if (!stress_var_.empty()) {
    stress_ivar_ = input->variable->find(const_cast<char *>(stress_var_.c_str()));
    if (stress_ivar_ < 0 || !input->variable->equalstyle(stress_ivar_))
      error->all(FLERR, ("Fix servo/rest: stress v_" + stress_var_ +
                         " is not an equal-style variable")
                            .c_str());
  }
}

void FixServoRest::init() {
  lid_ = nullptr;
  qs_ = nullptr;
}

// An ended protocol needs no wall: the scene may put a plain one in the
// servo's place for its final state.
void FixServoRest::setup(int) {
  if (protocol_->ended()) return;
  find_fixes();
  // the energy limit 1/2 M v^2 of the group's mass now (a density scaling
  // before the run changes it)
  double m = 0.0, total = 0.0;
  for (int i = 0; i < atom->nlocal; ++i)
    if (atom->mask[i] & groupbit) m += atom->rmass[i];
  MPI_Allreduce(&m, &total, 1, MPI_DOUBLE, MPI_SUM, world);
  protocol_->set_ke_limit(0.5 * total * ke_vrms_ * ke_vrms_);
}

double FixServoRest::target_stress() {
  return stress_ivar_ >= 0 ? input->variable->compute_equal(stress_ivar_) : stress_;
}

// the grains push the wall towards -z: its stress is -F_z / area
double FixServoRest::lid_stress() { return -lid_->compute_vector(2) / area_; }

double FixServoRest::kinetic_energy() {
  double **v = atom->v;
  const double *m = atom->rmass;
  const int *mask = atom->mask;
  double ke = 0.0;
  for (int i = 0; i < atom->nlocal; ++i)
    if (mask[i] & groupbit)
      ke += 0.5 * m[i] * (v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]);
  double total = 0.0;
  MPI_Allreduce(&ke, &total, 1, MPI_DOUBLE, MPI_SUM, world);
  return total;
}

void FixServoRest::say(const std::string &line) {
  if (line.empty() || comm->me != 0) return;
  if (screen) fprintf(screen, "%s\n", line.c_str());
  if (logfile) fprintf(logfile, "%s\n", line.c_str());
}

void FixServoRest::end_of_step() {
  if (protocol_->ended()) return;
  const long step = static_cast<long>(update->ntimestep);
  const double stress = lid_stress(), target = target_stress();
  if (!(target > 0.0) || !std::isfinite(target))
    error->all(FLERR, ("Fix servo/rest: the target stress v_" + stress_var_ + " is " +
                       std::to_string(target) + " Pa at step " + std::to_string(step) +
                       ": it must stay positive")
                          .c_str());
  protocol_->add_step(step, stress, target);
  if (step != protocol_->next_decision(step - 1)) return;
  fabric::RestMeasures m;
  m.t_load = (step - protocol_->start_step()) * update->dt;
  m.ratio = qs_->compute_scalar();
  m.ke = kinetic_energy();
  m.primary = qs_->balance_compute()->vector[static_cast<int>(
      fabric::VectorEntry::primary_percent_by_mass)];
  m.stress_now = stress;
  m.target = target;
  const fabric::RestDecision d = protocol_->decide(step, m);
  if (d.swing)
    error->all(FLERR, ("Fix servo/rest: " + d.line +
                       ": the servo is unstable for grains this heavy or this "
                       "light; lower the servo's kp or vel_max, or raise the "
                       "stress over a loading time (ramp)")
                          .c_str());
  if (d.lid != fabric::LidAction::none && rule_.lid_held) {
    char word[] = "servo/integrate";
    char start[] = "start", stop[] = "stop";
    char *a[2] = {word, d.lid == fabric::LidAction::hold ? stop : start};
    lid_->modify_param(2, a);
  }
  // the relaxation's kinetic damping; the loading's own comes back with
  // the servo
  if (d.lid == fabric::LidAction::hold) {
    load_zero_ = qs_->zero_every();
    qs_->set_zero_every(d.zero);
  } else if (d.lid == fabric::LidAction::release) {
    qs_->set_zero_every(load_zero_);
  }
  say(d.line);
  say(d.warning);
}

double FixServoRest::compute_vector(int i) {
  using fabric::RestEntry;
  const long step = static_cast<long>(update->ntimestep);
  const fabric::RestProtocol &p = *protocol_;
  switch (static_cast<RestEntry>(i)) {
    case RestEntry::phase: return static_cast<double>(p.phase());
    case RestEntry::next_run: return p.ended() ? 0.0 : static_cast<double>(p.next_decision(step) - step);
    case RestEntry::steps: return static_cast<double>(p.steps(step));
    case RestEntry::steps_relaxed: return static_cast<double>(p.steps_relaxed());
    case RestEntry::reloads: return p.reloads();
    case RestEntry::blocks: return p.blocks();
    case RestEntry::block_stress: return p.block_stress();
    case RestEntry::block_error_rms: return p.block_rms();
    case RestEntry::block_error_sd: return p.block_sd();
    case RestEntry::rest_stress: return p.rest_stress();
    case RestEntry::ended: return p.ended() ? 1.0 : 0.0;
    default: return 0.0;
  }
}

// The state is preceded by its length, so that a checkpoint of another
// layout (an older plugin's 13 entries, whose first is the phase 0-4) is an
// error, not a state read past its end.
void FixServoRest::write_restart(FILE *fp) {
  if (comm->me != 0) return;
  const std::array<double, kStateSize> s = protocol_->state();
  const double n = kStateSize;
  const int size = (kStateSize + 1) * sizeof(double);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(&n, sizeof(double), 1, fp);
  fwrite(s.data(), sizeof(double), kStateSize, fp);
}

void FixServoRest::restart(char *buf) {
  double n;
  memcpy(&n, buf, sizeof(double));
  if (n != kStateSize)
    error->all(FLERR, ("Fix servo/rest: the restart file holds a protocol state of another "
                       "layout (first entry " + std::to_string(n) + ", this plugin writes " +
                       std::to_string(kStateSize) + " entries): it was written by another "
                       "version of the plugin; run the job again from its start").c_str());
  std::array<double, kStateSize> s;
  memcpy(s.data(), buf + sizeof(double), sizeof(double) * kStateSize);
  protocol_->restore(s);
}
