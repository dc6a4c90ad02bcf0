/* fix pore/flow: the seepage force of a pore-scale flow through the group's
   grains (see docs/fix_pore_flow.md). A thin adapter of core/pore_flow.*
   (the pore finite volumes of Chareyre et al. 2012, no LIGGGHTS include).

   Every N steps, and at the setup of every run, the fix gathers the group's
   grains (centre, radius, ID) to every rank in the order of their IDs and
   runs the core's solve there: every rank holds the same solution, whatever
   the number of ranks or the way the atoms are spread over them. Between
   solves each grain keeps the force of the last one, added in post_force
   to the grain wherever it has migrated (found by its ID). */

#ifdef FIX_CLASS

FixStyle(pore/flow,FixPoreFlow)

#else

#ifndef LMP_FIX_PORE_FLOW_H
#define LMP_FIX_PORE_FLOW_H

#include <array>
#include <vector>

#include "fix.h"
#include "pore_flow_outputs.h"

namespace LAMMPS_NS {

class FixPoreFlow : public Fix {
 public:
  FixPoreFlow(class LAMMPS *, int, char **);
  ~FixPoreFlow();
  int setmask();
  void setup(int);
  void post_force(int);
  double compute_vector(int i);
  double memory_usage();

 private:
  void solve();  // gather, solve, keep the forces and the vector
  std::vector<fabric::Sphere> gather();  // the group's grains; sets ids_

  int every_ = 0;                   // steps between two solves
  int axis_ = 2;                    // the flow axis: 0 x, 1 y, 2 z
  int sign_ = 1;                    // 1: the flow runs from lo to hi; -1: hi to lo
  fabric::PoreFlowOptions options_;  // in the core's frame (z the flow axis)
  std::vector<tagint> ids_;          // per grain of the last solve: its ID,
                                     // increasing
  long left_out_ = 0;                // grains past the outflow face at the
                                     // last solve, left out of it
  std::vector<std::array<double, 3>> force_;  // per grain, N, the box's frame
  std::vector<double> pressure_;     // per grain, Pa: the pores around it
  static constexpr int kAtomColumns = 4;  // fx, fy, fz, pressure
  std::array<double, fabric::kPoreFlowEntries> vector_{};
  bigint solved_step_ = -1;
  int nmax_ = 0;                     // rows of array_atom allocated
};

}  // namespace LAMMPS_NS

#endif
#endif
