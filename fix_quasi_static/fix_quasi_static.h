/* fix quasi/static: the mechanics of a quasi-static load (see
   docs/fix_quasi_static.md). Cundall's local non-viscous damping on the
   forces and torques of the group's grains, and the unbalanced-force ratio
   that calls rest by force balance. A thin adapter: both live in
   core/quasi_static.* (no LIGGGHTS include). The damping acts in
   pre_final_integrate, after every force of the step (pair, walls and any
   fix's post_force), so the fix may be defined anywhere in the script; the
   kinetic damping (keyword zero) at the end of a step whose number is a
   multiple of its interval. */

#ifdef FIX_CLASS

FixStyle(quasi/static,FixQuasiStatic)

#else

#ifndef LMP_FIX_QUASI_STATIC_H
#define LMP_FIX_QUASI_STATIC_H

#include <string>
#include <vector>

#include "fix.h"

namespace LAMMPS_NS {

class FixQuasiStatic : public Fix {
 public:
  FixQuasiStatic(class LAMMPS *, int, char **);
  int setmask();
  void init();
  void setup(int);
  void pre_final_integrate();
  void end_of_step();
  int modify_param(int narg, char **arg);
  double compute_scalar();
  double compute_vector(int i);

  // for fix servo/rest, which runs the protocol on this fix's mechanics
  class Compute *balance_compute() const { return fabric_; }
  int zero_every() const { return zero_every_; }
  void set_zero_every(int n) { zero_every_ = n; }

 private:
  void balance();  // the ratio and its parts, once per step

  double alpha_;              // local damping coefficient, 0 <= alpha < 1
  int zero_every_ = 0;        // kinetic damping: velocities zeroed every
                              // this many steps; 0: never
  std::string fabric_id_;     // compute primary/fabric for the ratio
  class Compute *fabric_ = nullptr;
  std::vector<double> resultant_;  // per local atom: |F| before the damping
  bigint resultant_step_ = -1;     // the step resultant_ belongs to
  bigint balanced_step_ = -1;
  double values_[4] = {0.0, 0.0, 0.0, 0.0};
};

}  // namespace LAMMPS_NS

#endif
#endif
