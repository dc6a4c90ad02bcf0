// Unit tests of the neighbour-list count (fix_sequential_pack/
// neighbour_count.*) on a lattice whose neighbours are known.
#include <gtest/gtest.h>

#include <cmath>

#include "neighbour_count.h"

using fabric::Vec3;

namespace {

// 3 x 3 x 3 unit spheres on a simple cubic lattice of spacing 2 in the box
// [0, 6]^3: the centre grain touches 6, has 12 at a gap of 2 sqrt 2 - 2 and
// 8 at 2 sqrt 3 - 2.
fabric::PackingResult lattice() {
  fabric::PackingResult res;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      for (int z = 0; z < 3; ++z) {
        res.centre.push_back(Vec3(1 + 2 * x, 1 + 2 * y, 1 + 2 * z));
        res.radius.push_back(1.0);
        res.size_class.push_back(0);
      }
  return res;
}

const fabric::Box kBox{Vec3(0, 0, 0), Vec3(6, 6, 6)};

}  // namespace

TEST(NeighbourCount, TouchingNeighboursWithASmallSkin) {
  const auto c = fabric::count_neighbours(lattice(), {2.0}, kBox, 0.1, 1.0, 100);
  EXPECT_EQ(c.most, 6);
  EXPECT_EQ(c.diameter, 2.0);
  EXPECT_TRUE(std::isinf(c.skin_for_keep));  // no grain lists more than 100
}

TEST(NeighbourCount, TheSkinTakesInTheDiagonals) {
  const double diagonal = 2.0 * std::sqrt(2.0) - 2.0;
  const auto c = fabric::count_neighbours(lattice(), {2.0}, kBox, 1.0, 1.0, 6);
  EXPECT_EQ(c.most, 18);  // the centre: 6 touching + 12 diagonals
  // to keep every list at 6 or fewer the skin must stay below the diagonals
  EXPECT_NEAR(c.skin_for_keep, diagonal, 1e-12);
}

TEST(NeighbourCount, ContactDistanceFactorWidensTheReach) {
  // cdf 1.5: (1 + 1) 1.5 = 3 > 2 sqrt 2, so the diagonals are listed
  // without any skin
  const auto c = fabric::count_neighbours(lattice(), {2.0}, kBox, 0.0, 1.5, 100);
  EXPECT_EQ(c.most, 18);
}

TEST(NeighbourCount, SafeBound) {
  // equal radii 1, skin 0.1: reach 3.1, (3.1)^3 = 29.79 finest grains
  const std::vector<double> r(10, 1.0);
  EXPECT_TRUE(fabric::neighbours_surely_fit(r, 0.1, 1.0, 30));
  EXPECT_FALSE(fabric::neighbours_surely_fit(r, 0.1, 1.0, 29));
  EXPECT_TRUE(fabric::neighbours_surely_fit({1.0}, 0.1, 1.0, 0));
}
