// The packer's sites and their heap: a site is a place for a grain, three
// supports (placed spheres or container walls) and one of the two mirror
// solutions; the heap hands out the lowest (nearest) site first.
#ifndef FABRIC_SITE_HEAP_H
#define FABRIC_SITE_HEAP_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace fabric {
namespace detail {

// A support of a site: a placed sphere (index >= 0) or a wall (< 0): wall
// -1 - (2 axis + side), side 0 the low wall of that axis, 1 the high one.
inline bool is_wall(int s) { return s < 0; }
inline int wall_code(int axis, int side) { return -1 - (2 * axis + side); }
inline int wall_axis(int w) { return (-1 - w) / 2; }
inline int wall_side(int w) { return (-1 - w) % 2; }

// A place for a grain: its three supports (spheres first, then walls) and
// which of the two mirror solutions. Ordered by key (height or distance from
// the centre), then by the order sites were opened.
struct Site {
  double key;
  std::uint32_t order;
  std::int32_t s[3];
  std::int8_t mirror;  // +1: the positive solution, -1: the negative one
  // The sphere that kept the last grain offered here out (-1: none yet):
  // tested first when the site is offered a smaller grain, which it blocks
  // too more often than not (the answer is the same, only found sooner).
  std::int32_t blocker;
};
static_assert(sizeof(Site) == 32, "a site is kept in 32 bytes");

// A heap of sites with four children per node: half the levels of a binary
// heap, and a node's children share two cache lines (measured: about 5-10 %
// less CPU time for the whole packing than std::push_heap / pop_heap;
// buckets of key, each a heap, were not faster). (key, order) is unique, so
// the sites come out in the same order from any exact heap: the same
// specimen.
// Keys are heights above a wall or distances from the centre of spheres
// inside the container: positive and finite, so their bit patterns order as
// the numbers do, and the comparison needs no branch (a mispredicted branch
// per child was most of the cost of taking the top).
inline std::uint64_t key_bits(const Site& s) {
  std::uint64_t b;
  std::memcpy(&b, &s.key, sizeof b);
  return b;
}
inline bool earlier(const Site& a, const Site& b) {
  const std::uint64_t ka = key_bits(a), kb = key_bits(b);
  return (ka < kb) | ((ka == kb) & (a.order < b.order));
}
inline void heap_push(std::vector<Site>& h, const Site& s) {
  std::size_t i = h.size();
  h.push_back(s);
  while (i > 0) {
    std::size_t parent = (i - 1) / 4;
    if (!earlier(s, h[parent])) break;
    h[i] = h[parent];
    i = parent;
  }
  h[i] = s;
}
inline Site heap_pop(std::vector<Site>& h) {
  Site top = h.front(), last = h.back();
  h.pop_back();
  const std::size_t n = h.size();
  if (n == 0) return top;
  std::size_t i = 0;
  for (;;) {
    std::size_t first = 4 * i + 1;
    if (first >= n) break;
    std::size_t best = first, end = std::min(first + 4, n);
    for (std::size_t c = first + 1; c < end; ++c)
      best = earlier(h[c], h[best]) ? c : best;
    if (!earlier(h[best], last)) break;
    h[i] = h[best];
    i = best;
  }
  h[i] = last;
  return top;
}

}  // namespace detail
}  // namespace fabric

#endif
