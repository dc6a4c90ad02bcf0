// Union-find (disjoint sets) over 0..n-1, with path halving; the root of a
// set is its smallest member, so numbering sets by their first member does
// not depend on the order of the joins. The constrictions and the pore flow
// join the cells of the regular triangulation into pores with it.
#ifndef FABRIC_UNION_FIND_H
#define FABRIC_UNION_FIND_H

#include <algorithm>
#include <numeric>
#include <vector>

namespace fabric {

struct UnionFind {
  std::vector<long> parent;
  explicit UnionFind(long n) : parent(n) {
    std::iota(parent.begin(), parent.end(), 0L);
  }
  long find(long a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void join(long a, long b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace fabric

#endif
