// Unit tests of the primary fabric core (compute_primary_fabric/fabric_analysis.*)
// on hand-built specimens whose answer is known.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <limits>
#include <random>

#include "fabric_analysis.h"
#include "fabric_outputs.h"
#include "interval_assignment.h"

namespace fabric {
namespace {

using Eigen::Vector3d;
constexpr double kPi = static_cast<double>(EIGEN_PI);

Particle particle(int interval = 0, double mass = 1.0, double radius = 0.5) {
  static long long next_id = 1;
  return {next_id++, radius, mass, interval};
}

ParticleContact contact(int i, int j, double force,
                        Vector3d normal = Vector3d::UnitZ()) {
  return {i, j, force, normal, true};
}

WallContact wall(int i, double force, Vector3d normal = Vector3d::UnitZ()) {
  return {i, force, normal};
}

Options with(LoadThreshold t, Pruning p = Pruning::once) {
  Options o;
  o.threshold = t;
  o.pruning = p;
  return o;
}

const Options kAnyForce = with(LoadThreshold::absolute(0.0));

std::vector<Fraction> fractions(std::initializer_list<int> classes) {
  std::vector<Fraction> f;
  for (int c : classes) f.push_back(c ? Fraction::primary : Fraction::loose);
  return f;
}

// ---------------------------------------------------------------- classification

TEST(Classification, TwoLoadedContactsAreLooseThreeArePrimary) {
  std::vector<ParticleContact> contacts = {contact(0, 1, 1.0),
                                           contact(0, 2, 1.0)};
  Classification two = classify(4, contacts, {}, 0.0, kAnyForce);
  EXPECT_EQ(two.loaded_contacts, (std::vector<int>{2, 1, 1, 0}));
  EXPECT_EQ(two.fraction, fractions({0, 0, 0, 0}));

  contacts.push_back(contact(0, 3, 1.0));
  Classification three = classify(4, contacts, {}, 0.0, kAnyForce);
  EXPECT_EQ(three.loaded_contacts, (std::vector<int>{3, 1, 1, 1}));
  EXPECT_EQ(three.fraction, fractions({1, 0, 0, 0}));
}

TEST(Classification, MinContactsIsTheBoundary) {
  Options four = kAnyForce;
  four.min_contacts = 4;
  const std::vector<WallContact> walls = {wall(0, 1), wall(0, 1), wall(0, 1),
                                          wall(1, 1), wall(1, 1), wall(1, 1),
                                          wall(1, 1)};
  EXPECT_EQ(classify(2, {}, walls, 0.0, four).fraction, fractions({0, 1}));
}

TEST(Classification, WallContactsCountLikeParticleContacts) {
  // 0: one particle and two walls; 1: three walls; 2: two walls and an
  // unloaded third.
  const std::vector<ParticleContact> contacts = {contact(0, 3, 1.0)};
  const std::vector<WallContact> walls = {wall(0, 1.0), wall(0, 1.0),
                                          wall(1, 1.0), wall(1, 1.0),
                                          wall(1, 1.0), wall(2, 1.0),
                                          wall(2, 1.0), wall(2, 0.0)};
  Classification c = classify(4, contacts, walls, 0.0, kAnyForce);
  EXPECT_EQ(c.loaded_contacts, (std::vector<int>{3, 3, 2, 1}));
  EXPECT_EQ(c.fraction, fractions({1, 1, 0, 0}));
}

TEST(Classification, AContactNeedsAPositiveOverlap) {
  // The pair style's test rsq < radsum^2, for walls too: a grain that exactly
  // touches a wall (as the packer leaves it) is no contact.
  EXPECT_TRUE(overlaps(0.999, 1.0));
  EXPECT_FALSE(overlaps(1.0, 1.0));
  EXPECT_FALSE(overlaps(1.001, 1.0));
  EXPECT_FALSE(overlaps(std::nan(""), 1.0));
}

// ---------------------------------------------------------------- threshold

TEST(Threshold, ExactlyAtTheThresholdIsNotLoaded) {
  EXPECT_FALSE(is_loaded(2.0, 2.0));
  EXPECT_TRUE(is_loaded(std::nextafter(2.0, 3.0), 2.0));
  EXPECT_FALSE(is_loaded(0.0, 0.0));
  EXPECT_FALSE(is_loaded(-1.0, 0.0));
}

TEST(Threshold, AbsoluteCountsOnlyForcesAboveF) {
  const std::vector<ParticleContact> contacts = {
      contact(0, 1, 2.0), contact(0, 2, std::nextafter(2.0, 3.0)),
      contact(0, 3, 1.5), contact(0, 4, 7.0)};
  const Options o = with(LoadThreshold::absolute(2.0));
  const Analysis a = analyse(std::vector<Particle>(5, particle()), contacts,
                             {}, 1, o);
  EXPECT_EQ(a.threshold_force, 2.0);
  EXPECT_EQ(a.classification.loaded_contacts,
            (std::vector<int>{2, 0, 1, 0, 1}));
  EXPECT_EQ(a.summary.loaded_particle_contacts, 2.0);
  EXPECT_EQ(a.summary.contacts, 4.0);
}

TEST(Threshold, RelativeRefersToTheMeanOfParticleAndWallContacts) {
  const std::vector<Particle> p(3, particle());
  const std::vector<ParticleContact> contacts = {contact(0, 1, 1.0),
                                                 contact(1, 2, 3.0)};
  const Options half = with(LoadThreshold::relative(0.5));
  // Without walls the mean is 2, the threshold 1: the contact of force 1 sits
  // exactly on it and is not loaded.
  const Analysis no_walls = analyse(p, contacts, {}, 1, half);
  EXPECT_EQ(no_walls.threshold_force, 1.0);
  EXPECT_EQ(no_walls.classification.loaded_contacts,
            (std::vector<int>{0, 1, 1}));
  EXPECT_DOUBLE_EQ(no_walls.summary.mean_normal_force, 2.0);
  EXPECT_DOUBLE_EQ(no_walls.summary.mean_loaded_normal_force, 3.0);

  // Walls of 2 and 6 raise the mean to 3, the threshold to 1.5.
  const Analysis walls =
      analyse(p, contacts, {wall(0, 2.0), wall(2, 6.0)}, 1, half);
  EXPECT_EQ(walls.threshold_force, 1.5);
  EXPECT_EQ(walls.classification.loaded_contacts,
            (std::vector<int>{1, 1, 2}));
  EXPECT_DOUBLE_EQ(walls.summary.mean_normal_force, 3.0);
}

TEST(Threshold, AttractiveForcesAreNeverLoaded) {
  const std::vector<ParticleContact> contacts = {contact(0, 1, -4.0),
                                                 contact(1, 2, 1.0)};
  // Mean -1.5: a relative threshold would be negative; it is clamped to 0.
  const Analysis a = analyse(std::vector<Particle>(3, particle()), contacts,
                             {}, 1, with(LoadThreshold::relative(1.0)));
  EXPECT_EQ(a.threshold_force, 0.0);
  EXPECT_EQ(a.classification.loaded_contacts, (std::vector<int>{0, 1, 1}));
}

TEST(Threshold, RelativeZeroIsThePapersRuleAndTheDefaultIsAThousandth) {
  const std::vector<ParticleContact> contacts = {contact(0, 1, 0.0),
                                                 contact(1, 2, 1e-9),
                                                 contact(2, 3, 1.0)};
  const std::vector<Particle> p(4, particle());
  EXPECT_EQ(analyse(p, contacts, {}, 1, with(LoadThreshold::relative(0.0)))
                .classification.loaded_contacts,
            (std::vector<int>{0, 1, 2, 1}));
  const Options defaults;
  EXPECT_EQ(to_string(defaults.threshold), "relative 0.001");
  EXPECT_EQ(defaults.min_contacts, 3);
  EXPECT_EQ(defaults.pruning, Pruning::once);
  EXPECT_EQ(analyse(p, contacts, {}, 1).classification.loaded_contacts,
            (std::vector<int>{0, 0, 1, 1}));
}

// ---------------------------------------------------------------- pruning

// 0 -- 1 -- 2 -- 3, plus one wall each for 1 and 2 and three for 3: loaded
// contacts 1, 3, 3, 4. Once: only 0 is loose. Iterate: removing 0 leaves 1
// with two, removing 1 leaves 2 with two; 3 keeps three and stays.
struct Chain {
  std::vector<ParticleContact> contacts = {contact(0, 1, 1), contact(1, 2, 1),
                                           contact(2, 3, 1)};
  std::vector<WallContact> walls = {wall(1, 1), wall(2, 1), wall(3, 1),
                                    wall(3, 1), wall(3, 1)};
};

TEST(Pruning, OncePrunesASinglePass) {
  Chain s;
  Classification c = classify(4, s.contacts, s.walls, 0.0, kAnyForce);
  EXPECT_EQ(c.loaded_contacts, (std::vector<int>{1, 3, 3, 4}));
  EXPECT_EQ(c.fraction, fractions({0, 1, 1, 1}));
  EXPECT_EQ(c.iterations, 0);
}

TEST(Pruning, IterateCascadesToAFixedPoint) {
  Chain s;
  Classification c = classify(4, s.contacts, s.walls, 0.0,
                              with(LoadThreshold::absolute(0), Pruning::iterate));
  EXPECT_EQ(c.fraction, fractions({0, 0, 0, 1}));
  EXPECT_EQ(c.iterations, 2);
  EXPECT_TRUE(c.converged);
  // The per-particle counts stay those of all loaded contacts.
  EXPECT_EQ(c.loaded_contacts, (std::vector<int>{1, 3, 3, 4}));
}

TEST(Pruning, IterateStopsAtMaxIterationsAndSaysSo) {
  Chain s;
  Options o = with(LoadThreshold::absolute(0), Pruning::iterate);
  o.max_iterations = 1;
  Classification c = classify(4, s.contacts, s.walls, 0.0, o);
  EXPECT_EQ(c.fraction, fractions({0, 0, 1, 1}));
  EXPECT_EQ(c.iterations, 1);
  EXPECT_FALSE(c.converged);
}

TEST(Pruning, IterateKeepsASelfSupportingCluster) {
  // A tetrahedron (three contacts each) with a pendant particle 4 on 0.
  std::vector<ParticleContact> contacts = {contact(0, 1, 1), contact(0, 2, 1),
                                           contact(0, 3, 1), contact(1, 2, 1),
                                           contact(1, 3, 1), contact(2, 3, 1),
                                           contact(0, 4, 1)};
  Classification c = classify(5, contacts, {}, 0.0,
                              with(LoadThreshold::absolute(0), Pruning::iterate));
  EXPECT_EQ(c.fraction, fractions({1, 1, 1, 1, 0}));
  EXPECT_EQ(c.iterations, 0);
  EXPECT_TRUE(c.converged);
}

TEST(Pruning, IterateNeedsTheCompleteContactList) {
  std::vector<ParticleContact> contacts = {contact(0, 1, 1)};
  contacts[0].complete = false;
  EXPECT_THROW(classify(2, contacts, {}, 0.0,
                        with(LoadThreshold::absolute(0), Pruning::iterate)),
               std::invalid_argument);
  EXPECT_NO_THROW(classify(2, contacts, {}, 0.0, kAnyForce));
}

// An independent synchronous recount, as compute rattlers/atom does it.
std::pair<std::vector<Fraction>, int> recount_until_stable(
    int n, const std::vector<ParticleContact>& contacts,
    const std::vector<WallContact>& walls, double threshold, int min_contacts) {
  std::vector<Fraction> f(n, Fraction::primary);
  for (int pass = 0;; ++pass) {
    std::vector<int> count(n, 0);
    for (const auto& c : contacts)
      if (c.normal_force > threshold && f[c.i] == Fraction::primary &&
          f[c.j] == Fraction::primary) {
        ++count[c.i];
        ++count[c.j];
      }
    for (const auto& w : walls)
      if (w.normal_force > threshold) ++count[w.i];
    bool changed = false;
    for (int p = 0; p < n; ++p)
      if (f[p] == Fraction::primary && count[p] < min_contacts) {
        f[p] = Fraction::loose;
        changed = true;
      }
    if (!changed) return {f, std::max(0, pass - 1)};
  }
}

// A random contact network of n grains: 2n draws of a grain pair (self pairs
// skipped) and n/3 wall contacts, forces uniform in [-0.2, 1) (some
// attractive, some below the tests' threshold 0.1).
struct Network {
  std::vector<ParticleContact> contacts;
  std::vector<WallContact> walls;
};

Network random_network(std::mt19937& rng, int n) {
  std::uniform_int_distribution<int> pick(0, n - 1);
  std::uniform_real_distribution<double> force(-0.2, 1.0);
  Network net;
  for (int k = 0; k < 2 * n; ++k) {
    const int i = pick(rng), j = pick(rng);
    if (i != j) net.contacts.push_back(contact(i, j, force(rng)));
  }
  for (int k = 0; k < n / 3; ++k)
    net.walls.push_back(wall(pick(rng), force(rng)));
  return net;
}

TEST(Pruning, IterateAgreesWithANaiveRecountOnRandomNetworks) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    const int n = 2 + static_cast<int>(rng() % 60);
    const auto [contacts, walls] = random_network(rng, n);
    const auto [expected, passes] =
        recount_until_stable(n, contacts, walls, 0.1, 3);
    Classification c =
        classify(n, contacts, walls, 0.1,
                 with(LoadThreshold::absolute(0.1), Pruning::iterate));
    EXPECT_EQ(c.fraction, expected) << "trial " << trial;
    EXPECT_EQ(c.iterations, passes) << "trial " << trial;
  }
}

// ---------------------------------------------------------------- specimens

struct Specimen {
  std::vector<Particle> particles;
  std::vector<ParticleContact> contacts;
  std::vector<WallContact> walls;
  std::vector<Vector3d> position;
};

Vector3d random_direction(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return Vector3d(g(rng), g(rng), g(rng)).normalized();
}

// Random particles in 4 intervals with random contacts: forces mostly
// positive, some zero or attractive, normals random.
Specimen random_specimen(unsigned seed, int n, int intervals = 4) {
  std::mt19937 rng(seed);
  Specimen s;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int p = 0; p < n; ++p) {
    const int k = static_cast<int>(rng() % intervals);
    const double r = 0.1 * (k + 1) * (1.0 + 0.1 * unit(rng));
    s.particles.push_back({p + 1, r, r * r * r, k});
    s.position.emplace_back(unit(rng), unit(rng), unit(rng));
  }
  if (n == 0) return s;
  std::exponential_distribution<double> force(1.0);
  for (int k = 0; k < 3 * n; ++k) {
    const int i = static_cast<int>(rng() % n), j = static_cast<int>(rng() % n);
    if (i == j) continue;
    const double f = k % 11 == 0 ? -0.1 : k % 13 == 0 ? 0.0 : force(rng);
    s.contacts.push_back(contact(i, j, f, s.position[j] - s.position[i]));
  }
  for (int k = 0; k < n / 2; ++k)
    s.walls.push_back(wall(static_cast<int>(rng() % n), force(rng),
                           random_direction(rng)));
  return s;
}

TEST(Sums, IntervalRowsAddUpToTheTotals) {
  const Specimen s = random_specimen(3, 400);
  const Analysis a = analyse(s.particles, s.contacts, s.walls, 4,
                             with(LoadThreshold::relative(0.3)));
  const FabricSummary& t = a.summary;
  ASSERT_GT(t.loose_particles, 0.0);
  ASSERT_GT(t.particles - t.loose_particles, 0.0);

  double particles = 0, mass = 0, primary = 0, loose = 0, contacts = 0,
         force = 0;
  for (const IntervalSummary& row : t.intervals) {
    particles += row.particles;
    mass += row.mass_percent;
    primary += row.primary_mass_percent;
    loose += row.loose_mass_percent;
    EXPECT_NEAR(row.primary_mass_percent + row.loose_mass_percent,
                row.mass_percent, 1e-12);
    EXPECT_NEAR(row.primary_percent_of_interval,
                100.0 * row.primary_mass_percent / row.mass_percent, 1e-12);
    contacts += row.particles * row.loaded_contacts_per_particle;
    force += row.particles * row.loaded_contacts_per_particle *
             row.normal_force_per_loaded_contact;
  }
  EXPECT_EQ(particles, t.particles);
  EXPECT_NEAR(mass, 100.0, 1e-12);
  EXPECT_NEAR(primary, t.primary_percent_by_mass, 1e-12);
  EXPECT_NEAR(loose, 100.0 - t.primary_percent_by_mass, 1e-12);
  // Each loaded particle contact has two ends, a wall contact one.
  EXPECT_NEAR(contacts, t.coordination * t.particles, 1e-9);
  EXPECT_NEAR(contacts,
              2 * t.loaded_particle_contacts + t.loaded_wall_contacts, 1e-9);
  double loaded_force = 0;
  for (const auto& c : s.contacts)
    if (c.normal_force > a.threshold_force) loaded_force += 2 * c.normal_force;
  for (const auto& w : s.walls)
    if (w.normal_force > a.threshold_force) loaded_force += w.normal_force;
  EXPECT_NEAR(force, loaded_force, 1e-9);

  double in_bins = 0;
  for (const DirectionBin& b : t.directions) in_bins += b.contacts;
  EXPECT_EQ(in_bins, t.loaded_particle_contacts);
  EXPECT_EQ(t.loaded_contacts,
            t.loaded_particle_contacts + t.loaded_wall_contacts);
}

TEST(Sums, PrimaryCoordinationAveragesOverPrimaryParticlesOnly) {
  // 0 has three walls and a contact with 1; 1 has nothing else.
  const Analysis a = analyse(
      {particle(), particle()}, {contact(0, 1, 1.0)},
      {wall(0, 1.0), wall(0, 1.0), wall(0, 1.0)}, 1, kAnyForce);
  EXPECT_DOUBLE_EQ(a.summary.coordination, 2.5);
  EXPECT_DOUBLE_EQ(a.summary.primary_coordination, 4.0);
  EXPECT_DOUBLE_EQ(a.summary.loose_percent_by_number, 50.0);
}

// ---------------------------------------------------------------- overlapping zone

// One particle per entry of `classes` (per interval: 1 primary, 0 loose), of
// mass `interval + 1`; primary particles rest on three walls.
Analysis specimen_by_class(const std::vector<std::vector<int>>& classes) {
  std::vector<Particle> particles;
  std::vector<WallContact> walls;
  for (int k = 0; k < static_cast<int>(classes.size()); ++k)
    for (int is_primary : classes[k]) {
      if (is_primary)
        for (int w = 0; w < 3; ++w)
          walls.push_back(wall(static_cast<int>(particles.size()), 1.0));
      particles.push_back(particle(k, k + 1.0, 0.05 * (k + 1)));
    }
  return analyse(particles, {}, walls, static_cast<int>(classes.size()),
                 kAnyForce, {0.1, 0.2, 0.4, 0.8, 1.6});
}

TEST(OverlappingZone, SpansFromFinestPrimaryToCoarsestLoose) {
  const Analysis a =
      specimen_by_class({{0}, {1, 0}, {0, 1}, {1}, {1}});
  const OverlappingZone& oz = a.summary.overlapping_zone;
  EXPECT_EQ(oz.lower_interval, 1);
  EXPECT_EQ(oz.upper_interval, 2);
  EXPECT_EQ(oz.r1, 0.2);
  EXPECT_EQ(oz.r2, 0.4);
  // Masses 1, 2+2, 3+3, 4, 5: the zone holds 10 of 20.
  EXPECT_DOUBLE_EQ(oz.mass_percent, 50.0);
}

TEST(OverlappingZone, OneSharedIntervalIsAnOverlap) {
  const OverlappingZone oz =
      specimen_by_class({{0}, {0}, {0, 1}, {1}, {1}}).summary.overlapping_zone;
  EXPECT_EQ(oz.lower_interval, 2);
  EXPECT_EQ(oz.upper_interval, 2);
  EXPECT_DOUBLE_EQ(oz.mass_percent, 100.0 * 6.0 / 18.0);
}

TEST(OverlappingZone, ASharpDelimitationHasNoZone) {
  const OverlappingZone oz =
      specimen_by_class({{0}, {0}, {1}, {1}, {1}}).summary.overlapping_zone;
  EXPECT_EQ(oz.lower_interval, 2);
  EXPECT_EQ(oz.upper_interval, 1);
  EXPECT_GT(oz.r1, oz.r2);
  EXPECT_EQ(oz.mass_percent, 0.0);
}

TEST(OverlappingZone, UndefinedBoundsWhenOneFractionIsMissing) {
  const OverlappingZone all_loose =
      specimen_by_class({{0}, {0}, {0}, {0}, {0}}).summary.overlapping_zone;
  EXPECT_EQ(all_loose.lower_interval, -1);
  EXPECT_EQ(all_loose.upper_interval, 4);
  EXPECT_EQ(all_loose.r1, 0.0);
  EXPECT_EQ(all_loose.mass_percent, 0.0);
  const OverlappingZone all_primary =
      specimen_by_class({{1}, {1}, {1}, {1}, {1}}).summary.overlapping_zone;
  EXPECT_EQ(all_primary.lower_interval, 0);
  EXPECT_EQ(all_primary.upper_interval, -1);
  EXPECT_EQ(all_primary.mass_percent, 0.0);
}

TEST(OverlappingZone, MeasuredDiametersWhenNoneAreGiven) {
  const Analysis a = analyse({particle(0, 1, 0.05), particle(0, 1, 0.15),
                              particle(2, 1, 0.4)},
                             {}, {}, 3, kAnyForce);
  EXPECT_DOUBLE_EQ(a.summary.intervals[0].diameter, 0.2);
  EXPECT_EQ(a.summary.intervals[1].diameter, 0.0);
  EXPECT_DOUBLE_EQ(a.summary.overlapping_zone.r2, 0.8);
  EXPECT_THROW(finalise(a.sums, {0.3, 0.2, 0.8}), std::invalid_argument);
  EXPECT_THROW(finalise(a.sums, {0.3, 0.4}), std::invalid_argument);
}

TEST(OverlappingZone, TheToleranceIgnoresALoneLooseCoarseGrain) {
  // Interval 4 holds ten primary grains and one loose grain (1/11 of its
  // mass): the paper's r2 is interval 4 and its OZ runs from interval 1 to
  // the coarsest; with the default tolerance 0.1 the lone grain is ignored
  // and r2 is interval 1, where half the mass is loose.
  std::vector<int> coarse(10, 1);
  coarse.push_back(0);
  const Analysis a = specimen_by_class({{0}, {0, 1}, {1}, {1}, coarse});
  const OverlappingZone& paper = a.summary.overlapping_zone;
  const OverlappingZone& tolerant = a.summary.overlapping_zone_tolerant;
  EXPECT_EQ(paper.lower_interval, 1);
  EXPECT_EQ(paper.upper_interval, 4);
  // masses 1, 2+2, 3, 4, 11*5: the paper's zone holds 66 of 67
  EXPECT_DOUBLE_EQ(paper.mass_percent, 100.0 * 66.0 / 67.0);
  EXPECT_EQ(tolerant.lower_interval, 1);
  EXPECT_EQ(tolerant.upper_interval, 1);
  EXPECT_EQ(tolerant.r2, 0.2);
  EXPECT_DOUBLE_EQ(tolerant.mass_percent, 100.0 * 4.0 / 67.0);
  // a primary share at or below the tolerance does not set r1 either: one
  // primary grain among eleven loose ones in interval 0
  std::vector<int> fine(11, 0);
  fine.push_back(1);
  const Analysis b = specimen_by_class({fine, {1}, {1}, {1}, {1}});
  EXPECT_EQ(b.summary.overlapping_zone.lower_interval, 0);
  EXPECT_EQ(b.summary.overlapping_zone_tolerant.lower_interval, 1);
}

TEST(OverlappingZone, ToleranceZeroIsThePapersRule) {
  for (const auto& classes : std::vector<std::vector<std::vector<int>>>{
           {{0}, {1, 0}, {0, 1}, {1}, {1}}, {{0}, {0}, {1}, {1}, {1}},
           {{0}, {0}, {0}, {0}, {0}}, {{1}, {1}, {1}, {1}, {1}},
           {{0, 1, 1, 1}, {0}, {1, 0}, {1, 1, 1, 0}, {1}}}) {
    const Analysis a = specimen_by_class(classes);
    const FabricSummary s = finalise(a.sums, {0.1, 0.2, 0.4, 0.8, 1.6}, 0.0);
    EXPECT_EQ(s.overlapping_zone_tolerant.lower_interval, s.overlapping_zone.lower_interval);
    EXPECT_EQ(s.overlapping_zone_tolerant.upper_interval, s.overlapping_zone.upper_interval);
    EXPECT_EQ(s.overlapping_zone_tolerant.mass_percent, s.overlapping_zone.mass_percent);
  }
  EXPECT_THROW(finalise(specimen_by_class({{0}}).sums, {}, 1.0), std::invalid_argument);
  EXPECT_THROW(finalise(specimen_by_class({{0}}).sums, {}, -0.1), std::invalid_argument);
}

// ---------------------------------------------------------------- fabric

TEST(Anisotropy, AxisymmetricDensityGivesItsCoefficient) {
  // E(n) = (1 + a/2 (3 cos^2 - 1)) / (4 pi) has F = diag(1/3 - a/15,
  // 1/3 - a/15, 1/3 + 2a/15): the scalar is a, for either sign.
  for (double a : {0.4, -0.3, 1.2}) {
    const Eigen::Matrix3d F =
        Eigen::Vector3d(1.0 / 3 - a / 15, 1.0 / 3 - a / 15, 1.0 / 3 + 2 * a / 15).asDiagonal();
    EXPECT_NEAR(fabric_anisotropy(F), a, 1e-14) << a;
    // the same variation in the forces over an isotropic fabric is a_n
    const Eigen::Matrix3d iso = Eigen::Matrix3d::Identity() / 3.0;
    EXPECT_NEAR(force_anisotropy(iso, F), a, 1e-14) << a;
    EXPECT_NEAR(force_anisotropy(F, F), 0.0, 1e-14);
  }
  // contacts all along z: 5; all in the xy plane: -2.5; no contacts: 0
  EXPECT_NEAR(fabric_anisotropy(Eigen::Vector3d(0, 0, 1).asDiagonal()), 5.0, 1e-14);
  EXPECT_NEAR(fabric_anisotropy(Eigen::Vector3d(0.5, 0.5, 0).asDiagonal()), -2.5, 1e-14);
  EXPECT_EQ(fabric_anisotropy(Eigen::Matrix3d::Zero()), 0.0);
}

TEST(Anisotropy, SampledContactsMatchTheirDensity) {
  // Contact normals drawn from E(n) with a = 0.6 by rejection; the fabric's
  // scalar recovers a within the sampling error (about 0.02 at 40,000).
  std::mt19937_64 g(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0), w(0.0, 1.0);
  const double a = 0.6;
  std::vector<Particle> particles{particle(), particle()};
  std::vector<ParticleContact> contacts;
  while (contacts.size() < 40000) {
    Vector3d n(u(g), u(g), u(g));
    if (n.norm() > 1.0 || n.norm() < 1e-3) continue;
    n.normalize();
    const double density = 1.0 + 0.5 * a * (3.0 * n.z() * n.z() - 1.0);
    if (w(g) * (1.0 + a) > density) continue;
    contacts.push_back(contact(0, 1, 1.0, n));
  }
  const Analysis r = analyse(particles, contacts, {}, 1, kAnyForce);
  EXPECT_NEAR(r.summary.fabric_anisotropy, a, 0.03);
  EXPECT_NEAR(r.summary.force_anisotropy, 0.0, 1e-12);  // equal forces
}

TEST(FabricTensor, SixAxisContactsAreIsotropic) {
  std::vector<ParticleContact> contacts;
  const Vector3d axes[] = {Vector3d::UnitX(), Vector3d::UnitY(),
                           Vector3d::UnitZ()};
  for (int a = 0; a < 3; ++a) {
    contacts.push_back(contact(0, 1 + 2 * a, a + 1.0, axes[a]));
    contacts.push_back(contact(0, 2 + 2 * a, a + 1.0, -axes[a]));
  }
  const FabricSummary s =
      analyse(std::vector<Particle>(7, particle()), contacts, {}, 1, kAnyForce)
          .summary;
  EXPECT_TRUE(s.fabric_tensor.isApprox(Eigen::Matrix3d::Identity() / 3.0, 1e-15));
  // Forces 1, 2, 3 along x, y, z: the force-weighted tensor follows them.
  EXPECT_TRUE(s.force_fabric_tensor.isApprox(
      Vector3d(1, 2, 3).asDiagonal().toDenseMatrix() / 6.0, 1e-15));
}

TEST(FabricTensor, ContactsAlongZGiveZZOnly) {
  const std::vector<ParticleContact> contacts = {
      contact(0, 1, 1.0, Vector3d(0, 0, 2.5)),
      contact(1, 2, 4.0, Vector3d(0, 0, -0.1))};
  const FabricSummary s =
      analyse(std::vector<Particle>(3, particle()), contacts, {}, 1, kAnyForce)
          .summary;
  const Eigen::Matrix3d zz = Vector3d(0, 0, 1).asDiagonal();
  EXPECT_TRUE(s.fabric_tensor.isApprox(zz, 1e-15));
  EXPECT_TRUE(s.force_fabric_tensor.isApprox(zz, 1e-15));
}

TEST(FabricTensor, TraceIsOneAndOnlyLoadedContactsCount) {
  Specimen s = random_specimen(11, 200);
  const Analysis a = analyse(s.particles, s.contacts, s.walls, 4,
                             with(LoadThreshold::relative(1.0)));
  EXPECT_NEAR(a.summary.fabric_tensor.trace(), 1.0, 1e-12);
  EXPECT_NEAR(a.summary.force_fabric_tensor.trace(), 1.0, 1e-12);
  EXPECT_TRUE(a.summary.fabric_tensor.isApprox(
      a.summary.fabric_tensor.transpose()));
  // Adding an unloaded horizontal contact changes nothing.
  s.contacts.push_back(contact(0, 1, 0.0, Vector3d::UnitX()));
  const Analysis b = analyse(s.particles, s.contacts, s.walls, 4,
                             with(LoadThreshold::relative(1.0)));
  EXPECT_TRUE(a.summary.fabric_tensor.isApprox(b.summary.fabric_tensor, 1e-14));
}

TEST(FabricTensor, WallsEnterOnlyWhenAsked) {
  const std::vector<ParticleContact> contacts = {
      contact(0, 1, 1.0, Vector3d::UnitZ())};
  const std::vector<WallContact> walls = {wall(0, 1.0, Vector3d::UnitX())};
  const std::vector<Particle> p(2, particle());
  Options o = kAnyForce;
  EXPECT_TRUE(analyse(p, contacts, walls, 1, o)
                  .summary.fabric_tensor.isApprox(
                      Eigen::Matrix3d(Vector3d(0, 0, 1).asDiagonal())));
  o.walls_in_fabric = true;
  EXPECT_TRUE(analyse(p, contacts, walls, 1, o)
                  .summary.fabric_tensor.isApprox(
                      Eigen::Matrix3d(Vector3d(0.5, 0, 0.5).asDiagonal())));
}

Vector3d at_polar_angle(double degrees) {
  const double t = degrees * kPi / 180.0;
  return Vector3d(std::sin(t), 0.0, std::cos(t));
}

TEST(DirectionHistogram, BinsByAngleFromZRegardlessOfSign) {
  Options o = kAnyForce;
  o.direction_bins = 3;  // 0-30, 30-60, 60-90 degrees
  const std::vector<ParticleContact> contacts = {
      contact(0, 1, 1.0, at_polar_angle(0)),
      contact(0, 1, 3.0, at_polar_angle(170)),   // 10 degrees from -z
      contact(0, 1, 2.0, at_polar_angle(45)),
      contact(0, 1, 4.0, at_polar_angle(80)),
      contact(0, 1, 8.0, at_polar_angle(90)),    // the last bin includes 90
      contact(0, 1, 5.0, -at_polar_angle(100)),  // 80 degrees
      contact(0, 1, 0.0, at_polar_angle(45))};   // not loaded
  const FabricSummary s =
      analyse(std::vector<Particle>(2, particle()), contacts, {}, 1, o).summary;
  ASSERT_EQ(s.directions.size(), 3u);
  EXPECT_EQ(s.directions[0].contacts, 2.0);
  EXPECT_EQ(s.directions[1].contacts, 1.0);
  EXPECT_EQ(s.directions[2].contacts, 3.0);
  EXPECT_DOUBLE_EQ(s.directions[0].mean_normal_force, 2.0);
  EXPECT_DOUBLE_EQ(s.directions[1].mean_normal_force, 2.0);
  EXPECT_DOUBLE_EQ(s.directions[2].mean_normal_force, 17.0 / 3.0);
  EXPECT_DOUBLE_EQ(s.directions[2].contact_fraction, 0.5);
  EXPECT_DOUBLE_EQ(s.directions[1].theta_lo, 30.0);
  EXPECT_DOUBLE_EQ(s.directions[1].theta_hi, 60.0);
}

TEST(DirectionHistogram, AnIsotropicFabricIsFlatPerSolidAngle) {
  // Fibonacci lattice: nearly uniform directions on the sphere.
  std::vector<ParticleContact> contacts;
  const int n = 20000;
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < n; ++k) {
    const double z = 1.0 - (k + 0.5) * 2.0 / n;
    const double r = std::sqrt(1.0 - z * z);
    contacts.push_back(contact(
        0, 1, 1.0, Vector3d(r * std::cos(golden * k), r * std::sin(golden * k), z)));
  }
  const FabricSummary s =
      analyse(std::vector<Particle>(2, particle()), contacts, {}, 1, kAnyForce)
          .summary;
  for (const DirectionBin& b : s.directions)
    EXPECT_NEAR(b.density_vs_isotropic, 1.0, 0.01) << b.theta_lo;
  EXPECT_TRUE(s.fabric_tensor.isApprox(Eigen::Matrix3d::Identity() / 3.0, 1e-3));
}

// ---------------------------------------------------------------- MPI additivity

// Splits a specimen between two "ranks" by position, the way LIGGGHTS with
// newton off lists them: a contact across the cut is on both ranks, each time
// with the local particle as i and complete = false.
std::array<Specimen, 2> split(const Specimen& s) {
  std::array<Specimen, 2> rank;
  std::vector<int> owner(s.particles.size()), local(s.particles.size());
  for (std::size_t p = 0; p < s.particles.size(); ++p) {
    owner[p] = s.position[p].x() < 0.5 ? 0 : 1;
    local[p] = static_cast<int>(rank[owner[p]].particles.size());
    rank[owner[p]].particles.push_back(s.particles[p]);
    rank[owner[p]].position.push_back(s.position[p]);
  }
  for (const ParticleContact& c : s.contacts) {
    if (owner[c.i] == owner[c.j]) {
      rank[owner[c.i]].contacts.push_back(
          contact(local[c.i], local[c.j], c.normal_force, c.normal));
    } else {
      rank[owner[c.i]].contacts.push_back(
          {local[c.i], -1, c.normal_force, c.normal, false});
      rank[owner[c.j]].contacts.push_back(
          {local[c.j], -1, c.normal_force, -c.normal, false});
    }
  }
  for (const WallContact& w : s.walls)
    rank[owner[w.i]].walls.push_back({local[w.i], w.normal_force, w.normal});
  return rank;
}

std::vector<double> numbers(const FabricSummary& s) {
  std::vector<double> v = {s.particles, s.loose_particles,
                           s.loose_percent_by_number, s.primary_percent_by_mass,
                           s.coordination, s.primary_coordination, s.contacts,
                           s.loaded_contacts, s.loaded_particle_contacts,
                           s.loaded_wall_contacts, s.mean_normal_force,
                           s.mean_loaded_normal_force,
                           double(s.overlapping_zone.lower_interval),
                           double(s.overlapping_zone.upper_interval),
                           s.overlapping_zone.r1, s.overlapping_zone.r2,
                           s.overlapping_zone.mass_percent};
  v.insert(v.end(), s.fabric_tensor.data(), s.fabric_tensor.data() + 9);
  v.insert(v.end(), s.force_fabric_tensor.data(),
           s.force_fabric_tensor.data() + 9);
  for (const IntervalSummary& r : s.intervals)
    v.insert(v.end(), {r.diameter, r.measured_diameter, r.particles,
                       r.mass_percent, r.primary_mass_percent,
                       r.loose_mass_percent, r.primary_percent_of_interval,
                       r.loaded_contacts_per_particle,
                       r.normal_force_per_loaded_contact});
  for (const DirectionBin& b : s.directions)
    v.insert(v.end(), {b.theta_lo, b.theta_hi, b.contacts, b.contact_fraction,
                       b.density_vs_isotropic, b.mean_normal_force});
  return v;
}

TEST(Additivity, TwoRanksReduceToTheOneRankResult) {
  const Specimen s = random_specimen(5, 300);
  const Options o = with(LoadThreshold::relative(0.5));
  const std::vector<double> diameters = {0.2, 0.4, 0.6, 0.8};
  const Analysis one = analyse(s.particles, s.contacts, s.walls, 4, o, diameters);

  const std::array<Specimen, 2> rank = split(s);
  ASSERT_GT(rank[0].particles.size(), 0u);
  ASSERT_GT(rank[1].particles.size(), 0u);
  // Step 1 and its reduction.
  NormalForceSums forces;
  for (const Specimen& r : rank) {
    const NormalForceSums mine = normal_force_sums(r.contacts, r.walls);
    for (std::size_t k = 0; k < forces.values.size(); ++k)
      forces.values[k] += mine.values[k];
  }
  const double threshold = o.threshold.force(forces.mean());
  // Equal up to the order of summation.
  EXPECT_NEAR(threshold, one.threshold_force, 1e-14);
  // Steps 2-3 per rank, then an MPI_SUM over the raw arrays.
  FabricSums reduced(4, o.direction_bins);
  for (const Specimen& r : rank) {
    const int n = static_cast<int>(r.particles.size());
    const Classification c = classify(n, r.contacts, r.walls, threshold, o);
    FabricSums mine =
        accumulate(r.particles, r.contacts, r.walls, c, threshold, 4, o);
    ASSERT_EQ(mine.size(), reduced.size());
    for (int k = 0; k < mine.size(); ++k) reduced.data()[k] += mine.data()[k];
  }
  const std::vector<double> expected = numbers(one.summary);
  const std::vector<double> got = numbers(finalise(reduced, diameters));
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t k = 0; k < got.size(); ++k)
    EXPECT_NEAR(got[k], expected[k], 1e-12 * (1.0 + std::abs(expected[k])))
        << "entry " << k;
}

TEST(Additivity, SumsAddWithPlusEqualsAndRejectOtherLayouts) {
  FabricSums a(2, 3), b(2, 3), c(3, 3);
  a.at(1, FabricSums::Interval::primary_mass) = 1.5;
  b.at(1, FabricSums::Interval::primary_mass) = 2.0;
  b[FabricSums::Contact::contacts] = 4.0;
  a += b;
  EXPECT_EQ(a.at(1, FabricSums::Interval::primary_mass), 3.5);
  EXPECT_EQ(a[FabricSums::Contact::contacts], 4.0);
  EXPECT_THROW(a += c, std::invalid_argument);
}

// ---------------------------------------------------------------- edge cases

void expect_all_finite(const FabricSummary& s) {
  for (double x : numbers(s)) EXPECT_TRUE(std::isfinite(x));
}

TEST(EdgeCases, NoParticlesAndNoContactsGiveZeros) {
  const Analysis a = analyse({}, {}, {}, 3);
  expect_all_finite(a.summary);
  EXPECT_EQ(a.summary.particles, 0.0);
  EXPECT_EQ(a.summary.loose_percent_by_number, 0.0);
  EXPECT_EQ(a.summary.primary_percent_by_mass, 0.0);
  EXPECT_EQ(a.summary.mean_normal_force, 0.0);
  EXPECT_TRUE(a.summary.fabric_tensor.isZero());
  EXPECT_EQ(a.summary.overlapping_zone.lower_interval, -1);
  EXPECT_EQ(a.summary.overlapping_zone.upper_interval, -1);
  EXPECT_EQ(a.summary.intervals.size(), 3u);
}

TEST(EdgeCases, ParticlesWithoutContactsAreAllLoose) {
  const Analysis a = analyse({particle(0), particle(1)}, {}, {}, 2);
  expect_all_finite(a.summary);
  EXPECT_EQ(a.summary.loose_percent_by_number, 100.0);
  EXPECT_EQ(a.summary.coordination, 0.0);
  EXPECT_EQ(a.summary.primary_coordination, 0.0);
  EXPECT_TRUE(a.summary.force_fabric_tensor.isZero());
}

TEST(EdgeCases, RandomSpecimensNeverProduceNaN) {
  for (unsigned seed = 0; seed < 40; ++seed) {
    const Specimen s = random_specimen(seed, static_cast<int>(seed % 9) * 7);
    for (Pruning p : {Pruning::once, Pruning::iterate}) {
      Options o = with(LoadThreshold::relative(seed % 3 * 0.5), p);
      o.direction_bins = 1 + static_cast<int>(seed % 12);
      const Analysis a = analyse(s.particles, s.contacts, s.walls, 4, o);
      expect_all_finite(a.summary);
    }
  }
}

TEST(Validation, RejectsWhatCannotBeAnalysed) {
  const std::vector<Particle> two(2, particle());
  auto run = [&](std::vector<ParticleContact> c, std::vector<WallContact> w,
                 Options o = kAnyForce) { return analyse(two, c, w, 1, o); };
  EXPECT_THROW(run({contact(0, 2, 1)}, {}), std::invalid_argument);
  EXPECT_THROW(run({contact(1, 1, 1)}, {}), std::invalid_argument);
  EXPECT_THROW(run({contact(0, 1, 1, Vector3d::Zero())}, {}),
               std::invalid_argument);
  EXPECT_THROW(run({contact(0, 1, std::numeric_limits<double>::quiet_NaN())}, {}),
               std::invalid_argument);
  EXPECT_THROW(run({}, {wall(-1, 1)}), std::invalid_argument);
  EXPECT_THROW(analyse({particle(1)}, {}, {}, 1), std::invalid_argument);
  Options bad = kAnyForce;
  bad.min_contacts = 0;
  EXPECT_THROW(run({}, {}, bad), std::invalid_argument);
  EXPECT_THROW(run({}, {}, with(LoadThreshold::absolute(-1))),
               std::invalid_argument);
  bad = kAnyForce;
  bad.direction_bins = 0;
  EXPECT_THROW(run({}, {}, bad), std::invalid_argument);
  bad = kAnyForce;
  bad.walls_in_fabric = true;
  EXPECT_THROW(run({}, {wall(0, 1, Vector3d::Zero())}, bad),
               std::invalid_argument);
  EXPECT_NO_THROW(run({}, {wall(0, 1, Vector3d::Zero())}));
}


// ---------------------------------------------------------------- one normal force

TEST(NormalForce, IsTheForceProjectedOnTheNormalFromPartnerToParticle) {
  // Pushed away from the partner below: compressive, positive.
  EXPECT_DOUBLE_EQ(normal_force(Vector3d(0, 0, 5), Vector3d(0, 0, 2)), 5.0);
  // The normal's length does not matter, its direction does.
  EXPECT_DOUBLE_EQ(normal_force(Vector3d(3, 0, 4), Vector3d(0, 0, 1e-6)), 4.0);
  // Pulled towards the partner (a damping force at the end of a collision).
  EXPECT_DOUBLE_EQ(normal_force(Vector3d(0, 0, -1), Vector3d(0, 0, 1)), -1.0);
  EXPECT_TRUE(std::isnan(normal_force(Vector3d(1, 0, 0), Vector3d::Zero())));
}

TEST(NormalForce, WallAndParticleContactsShareOneDefinition) {
  // A large tangential force with a slightly attractive normal part: |F| is
  // far above any threshold, F.n is not. Both kinds of contact agree.
  const Vector3d force(30.0, 0.0, -0.5), normal(0.0, 0.0, 0.002);
  const WallContact w = wall_contact(0, force, normal);
  const ParticleContact p = particle_contact(0, 1, force, normal, true);
  EXPECT_DOUBLE_EQ(w.normal_force, -0.5);
  EXPECT_DOUBLE_EQ(p.normal_force, -0.5);
  EXPECT_FALSE(is_loaded(force, normal, 0.0));
  const Classification c = classify(2, {p}, {w, w, w}, 0.0, kAnyForce);
  EXPECT_EQ(c.loaded_contacts, (std::vector<int>{0, 0}));
  // The true normal, not the force direction, enters the fabric tensor.
  Options o = kAnyForce;
  o.walls_in_fabric = true;
  const WallContact lid = wall_contact(0, Vector3d(3, 0, 4), Vector3d(0, 0, 1));
  EXPECT_DOUBLE_EQ(lid.normal_force, 4.0);
  const Analysis a = analyse({particle()}, {}, {lid}, 1, o);
  EXPECT_DOUBLE_EQ(a.summary.fabric_tensor(2, 2), 1.0);
  EXPECT_DOUBLE_EQ(a.summary.fabric_tensor(0, 0), 0.0);
  // The particle contact's branch vector points from i to j.
  EXPECT_DOUBLE_EQ(p.normal.dot(normal), -normal.squaredNorm());
}

TEST(NormalForce, AZeroNormalIsRejected) {
  const WallContact w = wall_contact(0, Vector3d(1, 0, 0), Vector3d::Zero());
  EXPECT_THROW(classify(1, {}, {w}, 0.0, kAnyForce), std::invalid_argument);
}

// ---------------------------------------------------------------- prune across ranks

// A reusable barrier for the threads that play MPI ranks below.
class Barrier {
 public:
  explicit Barrier(int n) : n_(n) {}
  void wait() {
    std::unique_lock<std::mutex> lock(m_);
    const int generation = generation_;
    if (++waiting_ == n_) {
      waiting_ = 0;
      ++generation_;
      cv_.notify_all();
    } else {
      cv_.wait(lock, [&] { return generation != generation_; });
    }
  }

 private:
  std::mutex m_;
  std::condition_variable cv_;
  int n_, waiting_ = 0, generation_ = 0;
};

// The particles of `s` dealt to `ranks` ranks (p % ranks); a contact between
// two ranks is listed on both as an incomplete half, with the partner's
// global index kept for the exchange. Each rank classifies in its own
// thread with a PartnerExchange over shared memory; the classes put back
// together must equal the one-rank result.
struct RankData {
  std::vector<int> global;  // local -> global particle index
  std::vector<ParticleContact> contacts;
  std::vector<int> partner;  // global index of each contact's partner
  std::vector<WallContact> walls;
};

Classification classify_on_ranks(int n, const std::vector<ParticleContact>& all,
                                 const std::vector<WallContact>& all_walls,
                                 double threshold, const Options& o, int ranks,
                                 std::vector<Classification>& per_rank,
                                 std::vector<RankData>& data) {
  data.assign(ranks, RankData());
  std::vector<int> local(n);
  for (int p = 0; p < n; ++p) {
    local[p] = static_cast<int>(data[p % ranks].global.size());
    data[p % ranks].global.push_back(p);
  }
  for (const ParticleContact& c : all) {
    // Every end as a half, also when both ends are on one rank (as the
    // compute passes them); the exchange tells each about its partner.
    for (int end = 0; end < 2; ++end) {
      const int me = end == 0 ? c.i : c.j, other = end == 0 ? c.j : c.i;
      RankData& r = data[me % ranks];
      r.contacts.push_back({local[me], -1, c.normal_force, c.normal, false});
      r.partner.push_back(other);
    }
  }
  for (const WallContact& w : all_walls)
    data[w.i % ranks].walls.push_back({local[w.i], w.normal_force, w.normal});

  std::vector<char> board(n, 0);  // global loose flags, the "ghosts"
  std::vector<long long> counts(ranks, 0);
  Barrier barrier(ranks);
  per_rank.assign(ranks, Classification());
  std::vector<std::thread> threads;
  for (int r = 0; r < ranks; ++r)
    threads.emplace_back([&, r] {
      const RankData& d = data[r];
      PartnerExchange x;
      x.partners_loose = [&](const std::vector<Fraction>& f,
                             std::vector<char>& partner_loose) {
        for (std::size_t p = 0; p < d.global.size(); ++p)
          board[d.global[p]] = f[p] == Fraction::loose;
        barrier.wait();
        for (std::size_t k = 0; k < d.contacts.size(); ++k)
          partner_loose[k] = board[d.partner[k]];
        barrier.wait();
      };
      x.global_sum = [&](long long mine) {
        counts[r] = mine;
        barrier.wait();
        long long sum = 0;
        for (long long v : counts) sum += v;
        barrier.wait();
        return sum;
      };
      per_rank[r] = classify(static_cast<int>(d.global.size()), d.contacts,
                             d.walls, threshold, o, &x);
    });
  for (std::thread& t : threads) t.join();
  Classification joined;
  joined.fraction.resize(n);
  joined.loaded_contacts.resize(n);
  joined.iterations = per_rank[0].iterations;
  joined.converged = per_rank[0].converged;
  for (int r = 0; r < ranks; ++r)
    for (std::size_t p = 0; p < data[r].global.size(); ++p) {
      joined.fraction[data[r].global[p]] = per_rank[r].fraction[p];
      joined.loaded_contacts[data[r].global[p]] =
          per_rank[r].loaded_contacts[p];
    }
  return joined;
}

TEST(PruningAcrossRanks, OneLoopGivesTheOneRankResultOnAnyNumberOfRanks) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 3 + static_cast<int>(rng() % 50);
    const auto [contacts, walls] = random_network(rng, n);
    Options o = with(LoadThreshold::absolute(0.1), Pruning::iterate);
    o.max_iterations = 1 + trial % 4;  // sometimes stops early
    const Classification one = classify(n, contacts, walls, 0.1, o);
    for (int ranks : {1, 2, 3}) {
      std::vector<Classification> per_rank;
      std::vector<RankData> data;
      const Classification got = classify_on_ranks(n, contacts, walls, 0.1, o,
                                                   ranks, per_rank, data);
      EXPECT_EQ(got.fraction, one.fraction) << "trial " << trial << ", " << ranks;
      EXPECT_EQ(got.loaded_contacts, one.loaded_contacts) << "trial " << trial;
      for (const Classification& c : per_rank) {
        EXPECT_EQ(c.iterations, one.iterations) << "trial " << trial;
        EXPECT_EQ(c.converged, one.converged) << "trial " << trial;
      }
    }
  }
}

TEST(PruningAcrossRanks, ConvergedWhenTheLastAllowedPassFindsTheLastLooseOnes) {
  // The dangling pair of the scene test: A on a wall with B resting on it,
  // Z = 2. Once: B loose; pass 1 removes A. A further pass finds nothing, so
  // max_iterations 1 is enough: converged, 1 pass, on one rank or two.
  const std::vector<ParticleContact> contacts = {contact(0, 1, 1.0)};
  const std::vector<WallContact> walls = {wall(0, 1.0)};
  Options o = with(LoadThreshold::absolute(0), Pruning::iterate);
  o.min_contacts = 2;
  o.max_iterations = 1;
  const Classification one = classify(2, contacts, walls, 0.0, o);
  EXPECT_EQ(one.fraction, fractions({0, 0}));
  EXPECT_EQ(one.iterations, 1);
  EXPECT_TRUE(one.converged);
  std::vector<Classification> per_rank;
  std::vector<RankData> data;
  const Classification two =
      classify_on_ranks(2, contacts, walls, 0.0, o, 2, per_rank, data);
  EXPECT_EQ(two.fraction, one.fraction);
  EXPECT_EQ(per_rank[0].iterations, 1);
  EXPECT_TRUE(per_rank[0].converged);
  EXPECT_TRUE(per_rank[1].converged);
}

TEST(PruningAcrossRanks, AnExchangeNeedsBothFunctions) {
  PartnerExchange half;
  half.global_sum = [](long long v) { return v; };
  EXPECT_THROW(classify(1, {}, {}, 0.0,
                        with(LoadThreshold::absolute(0), Pruning::iterate),
                        &half),
               std::invalid_argument);
}

// ---------------------------------------------------------------- size intervals

TEST(IntervalAssignment, TheFixIndexDecidesAndZeroFallsBackToTheDiameter) {
  // Rounding emptied interval 2 (no particle has its diameter), but the fix
  // still says which interval every particle of its own is in.
  const auto a = IntervalAssignment::from_ranges(
      {1.0, INFINITY, 3.0}, {1.0, -INFINITY, 3.2});
  EXPECT_EQ(a.intervals(), 3);
  EXPECT_EQ(a.of(1.0, 1.0), 0);
  EXPECT_EQ(a.of(3.0, 3.1), 2);
  EXPECT_EQ(a.of(2.0, 5.0), 1);  // the index wins over the diameter
  // Index 0: an atom the fix did not create, placed by its diameter.
  EXPECT_EQ(a.of(0.0, 3.1), 2);
  EXPECT_EQ(a.of(0.0, 1.0 * (1 + 1e-10)), 0);
  EXPECT_EQ(a.of(0.0, 2.0), -1);  // the empty interval takes nothing
  EXPECT_EQ(a.of(0.0, 3.3), -1);
  for (double bad : {4.0, -1.0, 1.5, std::nan("")})
    EXPECT_THROW(a.of(bad, 1.0), std::invalid_argument) << bad;
}

TEST(IntervalAssignment, DistinctDiametersAreOneIntervalEach) {
  const std::vector<double> d = IntervalAssignment::distinct(
      {0.3, 0.1, 0.2, 0.1 * (1 + 1e-12), 0.3});
  EXPECT_EQ(d, (std::vector<double>{0.1, 0.2, 0.3}));
  const auto a = IntervalAssignment::from_ranges(d, d);
  EXPECT_EQ(a.of_diameter(0.2), 1);
  EXPECT_EQ(a.of_diameter(0.25), -1);
  EXPECT_EQ(a.of(0.0, 0.3), 2);
}

TEST(IntervalAssignment, PsdBoundsGiveABoundToTheFinerInterval) {
  const auto a = IntervalAssignment::from_bounds({1.0, 2.0, 4.0}, {2.0, 4.0, 8.0});
  EXPECT_EQ(a.of_diameter(1.5), 0);
  EXPECT_EQ(a.of_diameter(2.0), 0);
  EXPECT_EQ(a.of_diameter(2.0 * (1 + 1e-9)), 1);
  EXPECT_EQ(a.of_diameter(8.0 * (1 + 1e-7)), 2);
  EXPECT_EQ(a.of_diameter(8.1), -1);
  EXPECT_EQ(a.of_diameter(0.9), -1);
  EXPECT_EQ(a.of(3.0, 1.5), 2);  // a stored index still decides
  EXPECT_THROW(IntervalAssignment::from_bounds({1.0, 2.0}, {2.0}),
               std::invalid_argument);
}

// ---------------------------------------------------------------- output layout

TEST(Outputs, EveryVectorEntryAndArrayColumnIsWhereTheTableSaysByName) {
  FabricSummary s;
  s.particles = 1; s.loose_particles = 2; s.loose_percent_by_number = 3;
  s.primary_percent_by_mass = 4; s.coordination = 5;
  s.primary_coordination = 6;
  s.overlapping_zone.r1 = 2 * 7.0; s.overlapping_zone.r2 = 2 * 8.0;
  s.overlapping_zone.mass_percent = 9; s.contacts = 10;
  s.loaded_contacts = 11; s.mean_normal_force = 12;
  s.fabric_tensor << 15, 18, 19, 18, 16, 20, 19, 20, 17;
  s.force_fabric_tensor << 21, 24, 25, 24, 22, 26, 25, 26, 23;
  s.fabric_anisotropy = 27; s.force_anisotropy = 28;
  s.overlapping_zone_tolerant.r1 = 2 * 29.0; s.overlapping_zone_tolerant.r2 = 2 * 30.0;
  s.overlapping_zone_tolerant.mass_percent = 31;
  DirectionBin b0, b1;
  b0.contact_fraction = 32; b0.mean_normal_force = 33;
  b1.contact_fraction = 34; b1.mean_normal_force = 35;
  s.directions = {b0, b1};
  const std::vector<double> v = global_vector(s, 13, 14, 2);
  ASSERT_EQ(static_cast<int>(v.size()), vector_size(2));
  ASSERT_EQ(v.size(), 35u);
  for (int e = 0; e < 35; ++e) EXPECT_EQ(v[e], e + 1.0) << "entry " << e + 1;
  EXPECT_EQ(v[static_cast<int>(VectorEntry::threshold_force)], 13.0);

  IntervalSummary r;
  r.diameter = 1; r.mass_percent = 2; r.primary_percent_of_interval = 3;
  r.loose_mass_percent = 4; r.loaded_contacts_per_particle = 5;
  r.normal_force_per_loaded_contact = 6; r.primary_mass_percent = 7;
  r.particles = 8; r.measured_diameter = 99;
  const auto row = interval_row(r);
  for (int c = 0; c < kArrayColumns; ++c) EXPECT_EQ(row[c], c + 1.0) << c;
}

}  // namespace
}  // namespace fabric
