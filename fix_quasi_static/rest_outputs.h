// The outputs of fix servo/rest, defined once: the position, name and
// meaning of every entry of its global vector. The fix fills them from this
// table, docs/fix_servo_rest.md quotes it and the Python tools read it from
// this file (tools/outputs.py), as they read fabric_outputs.h.
//
// Format (kept simple for those readers): one X(position, name, "meaning")
// per line; positions count from 1, as f_ID[I] does.
#ifndef FABRIC_REST_OUTPUTS_H
#define FABRIC_REST_OUTPUTS_H

#include "output_table.h"

#define SERVO_REST_VECTOR_ENTRIES(X)                                           \
  X(1, phase, "0 loading, 1 relaxing, 2 at rest, 3 maximum loading time, 4 maximum relaxation") \
  X(2, next_run, "steps from now to the fix's next decision: the length of the next run") \
  X(3, steps, "steps since the loading began")                                \
  X(4, steps_relaxed, "steps of relaxation")                \
  X(5, reloads, "the servo taken up again after a relaxation")                \
  X(6, blocks, "whole blocks of loading in this job")                         \
  X(7, block_stress, "the last whole block's mean lid stress, Pa")            \
  X(8, block_error_rms, "rms of that block's relative stress error")          \
  X(9, block_error_sd, "spread of that block's error about its mean")         \
  X(10, rest_stress, "the lid stress when the run ended (at rest or a limit), Pa") \
  X(11, ended, "1 when the protocol has ended, else 0")

namespace fabric {

enum class RestEntry { SERVO_REST_VECTOR_ENTRIES(FABRIC_OUTPUT_NAME) count };
constexpr int kRestEntries = static_cast<int>(RestEntry::count);
constexpr int kRestPositions[] = {SERVO_REST_VECTOR_ENTRIES(FABRIC_OUTPUT_POSITION)};
static_assert(counts_from_one(kRestPositions),
              "rest_outputs.h: the positions must count 1, 2, 3 ...");

}  // namespace fabric

#endif
