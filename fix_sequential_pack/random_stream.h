// Random numbers of the packer: one small generator (struct Random) that
// gives the same stream for a given seed on every platform and rank.
#ifndef FABRIC_RANDOM_STREAM_H
#define FABRIC_RANDOM_STREAM_H

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "geometry.h"

namespace fabric {
namespace detail {

// SplitMix64: tiny, portable and the same on every platform and rank.
struct Random {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  double uniform() { return (next() >> 11) * 0x1.0p-53; }
  Vec3 unit_vector() {
    double z = 2.0 * uniform() - 1.0, phi = 2.0 * M_PI * uniform();
    double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    return Vec3(s * std::cos(phi), s * std::sin(phi), z);
  }
};

}  // namespace detail
}  // namespace fabric

#endif
