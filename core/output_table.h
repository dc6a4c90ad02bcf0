// What the output tables of our styles share (fabric_outputs.h,
// pack_outputs.h): each is an X-macro of X(position, name, "meaning") lines;
// these turn a table into an enum of its names and check that its
// positions count 1, 2, 3 ... in order (c_ID[I] and f_ID[I] count from 1).
#ifndef FABRIC_OUTPUT_TABLE_H
#define FABRIC_OUTPUT_TABLE_H

#include <cstddef>

#define FABRIC_OUTPUT_NAME(position, name, meaning) name,
#define FABRIC_OUTPUT_POSITION(position, name, meaning) position,

namespace fabric {

// true when positions[i] == i + 1 for every i
template <std::size_t N>
constexpr bool counts_from_one(const int (&positions)[N]) {
  for (std::size_t i = 0; i < N; ++i)
    if (positions[i] != static_cast<int>(i) + 1) return false;
  return true;
}

}  // namespace fabric

#endif
