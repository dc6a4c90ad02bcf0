// The outputs of fix pore/flow, defined once: the position, name and meaning
// of every entry of its global vector. The fix fills them from this table
// (pore_flow_vector), docs/fix_pore_flow.md quotes it (the scene test
// compares the two) and the Python tools read it from this file
// (tools/outputs.py), as they read fabric_outputs.h.
//
// Format (kept simple for those readers): one X(position, name, "meaning")
// per line; positions count from 1, as f_ID[I] does.
#ifndef FABRIC_PORE_FLOW_OUTPUTS_H
#define FABRIC_PORE_FLOW_OUTPUTS_H

#include <array>

#include "output_table.h"
#include "pore_flow.h"

// The flow axis is the fix's direction (z by default); "lo" and "hi" are
// the box's faces across it.
#define PORE_FLOW_VECTOR_ENTRIES(X)                                            \
  X(1, inflow, "flow rate in through the inflow face, m^3/s")                 \
  X(2, outflow, "flow rate out through the outflow face, m^3/s")              \
  X(3, permeability, "K = Q mu L / (A dp), Q the outflow, m^2")                \
  X(4, fluid_force, "total fluid force on the group's grains along the flow, N") \
  X(5, pressure_drop, "P_in - P_out, Pa")                                      \
  X(6, pores, "pores of the network")                                          \
  X(7, iterations, "conjugate-gradient iterations of the solve")               \
  X(8, solve_step, "the time step of the solve these figures belong to")      \
  X(9, left_out, "grains of the group past the outflow face, left out of the solve")

namespace fabric {

enum class PoreFlowEntry { PORE_FLOW_VECTOR_ENTRIES(FABRIC_OUTPUT_NAME) count };
constexpr int kPoreFlowEntries = static_cast<int>(PoreFlowEntry::count);
constexpr int kPoreFlowPositions[] = {
    PORE_FLOW_VECTOR_ENTRIES(FABRIC_OUTPUT_POSITION)};
static_assert(counts_from_one(kPoreFlowPositions),
              "pore_flow_outputs.h: the positions must count 1, 2, 3 ...");

// The global vector of one solve (in the core's frame, whose z is the flow
// axis), taken at time step `step`, `left_out` grains past the outflow face.
inline std::array<double, kPoreFlowEntries> pore_flow_vector(
    const PoreFlow& flow, const PoreFlowOptions& options, double step,
    long left_out = 0) {
  std::array<double, kPoreFlowEntries> v{};
  const auto set = [&v](PoreFlowEntry e, double x) {
    v[static_cast<int>(e)] = x;
  };
  double force = 0.0;
  for (const Vec3& f : flow.force) force += f.z();
  set(PoreFlowEntry::inflow, flow.inflow);
  set(PoreFlowEntry::outflow, flow.outflow);
  set(PoreFlowEntry::permeability, flow.permeability);
  set(PoreFlowEntry::fluid_force, force);
  set(PoreFlowEntry::pressure_drop,
      options.inflow_pressure - options.outflow_pressure);
  set(PoreFlowEntry::pores, static_cast<double>(flow.pores));
  set(PoreFlowEntry::iterations, flow.iterations);
  set(PoreFlowEntry::solve_step, step);
  set(PoreFlowEntry::left_out, static_cast<double>(left_out));
  return v;
}

}  // namespace fabric

#endif
