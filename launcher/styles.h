// The styles this project adds to LIGGGHTS, by name. The launcher registers
// them; users with their own LIGGGHTS build copy the style sources into its
// src/ instead (their FixStyle/ComputeStyle/CommandStyle blocks do the same
// there).
#ifndef FABRIC_STYLES_H
#define FABRIC_STYLES_H

#include <string>
#include <utility>
#include <vector>

#include "command_error.h"
#include "command_psd_info.h"
#include "compute_constriction_size.h"
#include "compute_primary_fabric.h"
#include "fix_pore_flow.h"
#include "fix_quasi_static.h"
#include "fix_servo_rest.h"
#include "fix_sequential_pack.h"

namespace fabric_styles {

template <class T>
LAMMPS_NS::Fix *make_fix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg) {
  return new T(lmp, narg, arg);
}
template <class T>
LAMMPS_NS::Compute *make_compute(LAMMPS_NS::LAMMPS *lmp, int iarg, int narg,
                                 char **arg) {
  return new T(lmp, iarg, narg, arg);  // LIGGGHTS computes take iarg too
}

template <class T>
void run_command(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg) {
  T cmd(lmp);  // as LIGGGHTS' Input::command_creator does
  cmd.command(narg, arg);
}

using CommandCreator = void (*)(LAMMPS_NS::LAMMPS *, int, char **);
using FixCreator = LAMMPS_NS::Fix *(*)(LAMMPS_NS::LAMMPS *, int, char **);
using ComputeCreator =
    LAMMPS_NS::Compute *(*)(LAMMPS_NS::LAMMPS *, int, int, char **);

inline std::vector<std::pair<std::string, FixCreator>> fixes() {
  return {{"sequential/pack", &make_fix<LAMMPS_NS::FixSequentialPack>},
          {"quasi/static", &make_fix<LAMMPS_NS::FixQuasiStatic>},
          {"servo/rest", &make_fix<LAMMPS_NS::FixServoRest>},
          {"pore/flow", &make_fix<LAMMPS_NS::FixPoreFlow>}};
}

inline std::vector<std::pair<std::string, ComputeCreator>> computes() {
  return {{"primary/fabric",
           &make_compute<LAMMPS_NS::ComputePrimaryFabric>},
          {"constriction/size",
           &make_compute<LAMMPS_NS::ComputeConstrictionSize>}};
}

inline std::vector<std::pair<std::string, CommandCreator>> commands() {
  return {{"error", &run_command<LAMMPS_NS::CommandError>},
          {"psd_info", &run_command<LAMMPS_NS::CommandPsdInfo>}};
}

}  // namespace fabric_styles

#endif
