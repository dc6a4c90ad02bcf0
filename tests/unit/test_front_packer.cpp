// Invariants of the front packer (fix_sequential_pack/front_packer.*) on
// specimens of 1,000-100,000 spheres, checked by code that shares nothing
// with the packer (its own cell list).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <ostream>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <unordered_map>

#include "front_packer.h"
#include "psd.h"

using namespace fabric;

namespace {

struct Specimen {
  PackingSpec spec;
  PackingResult result;
  std::vector<SizeInterval> intervals;
  double volume;
};

Specimen make(const std::string& psd_path, double porosity, double side,
              Arrangement a, int intervals = 20, std::uint64_t seed = 1) {
  Specimen s;
  auto psd = ParticleSizeDistribution::read(psd_path);
  s.intervals = psd.equal_mass_intervals(intervals);
  double L = side * s.intervals.back().d_mean;
  s.volume = L * L * L;
  auto list = particle_list(s.intervals, s.volume, porosity);
  s.spec.lo = Vec3(0, 0, 0);
  s.spec.hi = Vec3(L, L, L);
  for (size_t k = 0; k < s.intervals.size(); ++k) {
    s.spec.radius.push_back(0.5 * list.diameter[k]);
    s.spec.count.push_back(list.count[k]);
  }
  s.spec.arrangement = a;
  s.spec.seed = seed;
  s.result = pack(s.spec);
  return s;
}

// Touching and overlapping pairs by an independent cell list: each sphere is
// entered in every cell its bounding box meets (cells sized by the finest).
struct Contacts {
  long overlaps = 0;
  double worst = 0.0;  // largest overlap / smaller radius
  std::vector<std::pair<int, int>> touching;
};
Contacts contacts_of(const PackingResult& r) {
  double rmin = *std::min_element(r.radius.begin(), r.radius.end());
  double h = 4.0 * rmin;
  std::unordered_map<long long, std::vector<int>> cells;
  auto key = [](long long i, long long j, long long k) {
    return (i * 1000003LL + j) * 1000033LL + k;
  };
  for (int i = 0; i < (int)r.centre.size(); ++i) {
    const Vec3& c = r.centre[i];
    double rr = r.radius[i];
    for (long long x = std::floor((c[0] - rr) / h); x <= std::floor((c[0] + rr) / h); ++x)
      for (long long y = std::floor((c[1] - rr) / h); y <= std::floor((c[1] + rr) / h); ++y)
        for (long long z = std::floor((c[2] - rr) / h); z <= std::floor((c[2] + rr) / h); ++z)
          cells[key(x, y, z)].push_back(i);
  }
  std::set<std::pair<int, int>> seen;
  Contacts out;
  for (auto& [k, list] : cells)
    for (size_t a = 0; a < list.size(); ++a)
      for (size_t b = a + 1; b < list.size(); ++b) {
        int i = std::min(list[a], list[b]), j = std::max(list[a], list[b]);
        double gap = (r.centre[i] - r.centre[j]).norm() - r.radius[i] - r.radius[j];
        double rel = -gap / std::min(r.radius[i], r.radius[j]);
        if (rel < -1e-9) continue;
        if (!seen.insert({i, j}).second) continue;
        if (rel > 1e-9) ++out.overlaps;
        out.worst = std::max(out.worst, rel);
        out.touching.push_back({i, j});
      }
  return out;
}

void expect_invariants(const Specimen& s, double porosity, bool expect_porosity,
                       const std::string& what) {
  const PackingResult& r = s.result;
  ASSERT_GT(r.placed(), 500) << what;
  // every sphere inside the container, no overlap with the walls
  for (int i = 0; i < r.placed(); ++i)
    for (int a = 0; a < 3; ++a) {
      double tol = 1e-9 * r.radius[i];
      ASSERT_GE(r.centre[i][a] - r.radius[i], s.spec.lo[a] - tol) << what;
      ASSERT_LE(r.centre[i][a] + r.radius[i], s.spec.hi[a] + tol) << what;
    }
  Contacts c = contacts_of(r);
  EXPECT_EQ(c.overlaps, 0) << what << ": worst overlap " << c.worst;
  // mass share per interval against the PSD's
  std::vector<double> mass(s.intervals.size(), 0.0);
  double total = 0.0;
  for (int i = 0; i < r.placed(); ++i) {
    double v = std::pow(r.radius[i], 3);
    mass[r.size_class[i]] += v;
    total += v;
  }
  if (!expect_porosity) return;  // unplaced spheres shift the shares
  for (size_t k = 0; k < mass.size(); ++k)
    EXPECT_NEAR(mass[k] / total, s.intervals[k].mass_fraction, 0.01)
        << what << " interval " << k + 1;
  double achieved = 1.0 - 4.0 / 3.0 * M_PI * total / s.volume;
  EXPECT_NEAR(achieved, porosity, 0.005) << what;
}

const std::string kPsd = PSD_DIR;
const std::string kData = TEST_DATA_DIR;

}  // namespace

// Target porosities this packer reaches in a container of `side` coarsest
// diameters (docs/fix_sequential_pack.md has the measured ranges).
struct Case {
  std::string psd;
  double porosity, side;
  Arrangement arrangement;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.psd.substr(c.psd.find_last_of('/') + 1) << ", porosity " << c.porosity
      << ", edge " << c.side << " coarsest diameters, " << to_string(c.arrangement);
}

class PackingInvariants : public ::testing::TestWithParam<Case> {};

// Test names such as "cu2_5_discrete" instead of the parameter's bytes.
std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  std::string file = info.param.psd.substr(info.param.psd.find_last_of('/') + 1);
  std::string name = file.substr(0, file.rfind('.')) + "_" +
                     to_string(info.param.arrangement);
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

TEST_P(PackingInvariants, NoOverlapInsideOnTargetPorosityAndMassShares) {
  const Case& c = GetParam();
  Specimen s = make(c.psd, c.porosity, c.side, c.arrangement);
  std::string what = c.psd + " " + to_string(c.arrangement);
  expect_invariants(s, c.porosity, true, what);
}

INSTANTIATE_TEST_SUITE_P(
    ShippedSoils, PackingInvariants,
    ::testing::Values(
        Case{kPsd + "/cu2.0.txt", 0.48, 7, Arrangement::discrete},
        Case{kPsd + "/cu2.5.txt", 0.42, 6, Arrangement::discrete},
        Case{kPsd + "/cu3.0.txt", 0.42, 5, Arrangement::discrete},
        Case{kPsd + "/cu3.5.txt", 0.42, 4, Arrangement::discrete},
        Case{kPsd + "/cu2.0.txt", 0.48, 7, Arrangement::layerwise},
        Case{kPsd + "/cu2.5.txt", 0.45, 6, Arrangement::layerwise},
        Case{kPsd + "/cu3.0.txt", 0.45, 5, Arrangement::layerwise},
        Case{kPsd + "/cu3.5.txt", 0.45, 4, Arrangement::layerwise}),
    case_name);

INSTANTIATE_TEST_SUITE_P(
    HostileSoils, PackingInvariants,
    ::testing::Values(
        Case{kData + "/gap_graded.txt", 0.55, 5, Arrangement::discrete},
        Case{kData + "/gap_graded.txt", 0.45, 5, Arrangement::layerwise},
        Case{kData + "/broad_25.txt", 0.45, 5, Arrangement::discrete},
        Case{kData + "/broad_25.txt", 0.45, 5, Arrangement::layerwise}),
    case_name);

// Where the target is out of reach the packer still never overlaps and
// reports what it could not place.
TEST(FrontPacker, UnreachablePorosityStillGivesAValidSpecimen) {
  Specimen s = make(kPsd + "/cu2.5.txt", 0.30, 5, Arrangement::layerwise);
  expect_invariants(s, 0.30, false, "cu2.5 LA at 0.30");
  long long left = 0;
  for (size_t k = 0; k < s.spec.count.size(); ++k)
    left += s.spec.count[k] - s.result.placed_per_class[k];
  EXPECT_GT(left, 0);
  EXPECT_EQ(s.result.placed() + left,
            std::accumulate(s.spec.count.begin(), s.spec.count.end(), 0LL));
}

TEST(FrontPacker, SameSeedSameSpecimenOtherSeedOtherSpecimen) {
  Specimen a = make(kPsd + "/cu2.5.txt", 0.42, 4, Arrangement::discrete, 20, 5);
  Specimen b = make(kPsd + "/cu2.5.txt", 0.42, 4, Arrangement::discrete, 20, 5);
  Specimen c = make(kPsd + "/cu2.5.txt", 0.42, 4, Arrangement::discrete, 20, 6);
  ASSERT_EQ(a.result.placed(), b.result.placed());
  for (int i = 0; i < a.result.placed(); ++i)
    ASSERT_EQ(a.result.centre[i], b.result.centre[i]);
  EXPECT_NE(a.result.centre[5], c.result.centre[5]);
}

// The two rules really differ: LA puts like sizes together (sizes fall off
// from the centre, touching neighbours have similar sizes), DA mixes them.
TEST(FrontPacker, LayerwisePlacesLikeSizesTogetherDiscreteMixes) {
  std::map<std::string, double> corr, ratio;
  for (Arrangement a : {Arrangement::discrete, Arrangement::layerwise}) {
    Specimen s = make(kPsd + "/cu2.5.txt", 0.45, 6, a);
    const PackingResult& r = s.result;
    Vec3 centre = 0.5 * (s.spec.lo + s.spec.hi);
    // Pearson correlation of radius with distance from the centre
    double n = r.placed(), sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    for (int i = 0; i < r.placed(); ++i) {
      double x = (r.centre[i] - centre).norm(), y = r.radius[i];
      sx += x, sy += y, sxx += x * x, syy += y * y, sxy += x * y;
    }
    corr[to_string(a)] = (sxy - sx * sy / n) /
        std::sqrt((sxx - sx * sx / n) * (syy - sy * sy / n));
    // mean size ratio (larger / smaller) of touching neighbours
    Contacts c = contacts_of(r);
    double sum = 0;
    for (auto [i, j] : c.touching)
      sum += std::max(r.radius[i], r.radius[j]) / std::min(r.radius[i], r.radius[j]);
    ratio[to_string(a)] = sum / c.touching.size();
  }
  std::printf("radius-distance correlation: DA %.3f, LA %.3f\n", corr["discrete"],
              corr["layerwise"]);
  std::printf("mean size ratio of touching neighbours: DA %.3f, LA %.3f\n",
              ratio["discrete"], ratio["layerwise"]);
  EXPECT_LT(corr["layerwise"], -0.5);
  EXPECT_GT(corr["discrete"], -0.2);
  EXPECT_LT(ratio["layerwise"], ratio["discrete"] - 0.1);
}

TEST(FrontPacker, RejectsUnusableSpecs) {
  PackingSpec s;
  s.lo = Vec3(0, 0, 0);
  s.hi = Vec3(1, 1, 1);
  s.radius = {0.1};
  s.count = {2};
  EXPECT_THROW(pack(s), std::invalid_argument);  // fewer than 3 spheres
  s.count = {10};
  s.radius = {-0.1};
  EXPECT_THROW(pack(s), std::invalid_argument);
  s.radius = {0.6};  // the first face cannot fit
  EXPECT_THROW(pack(s), std::invalid_argument);
  s.radius = {0.1, 0.2};
  EXPECT_THROW(pack(s), std::invalid_argument);  // counts do not match
}
