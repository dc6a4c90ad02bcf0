// The sequential packer (paper, sections 2.2-2.3, Fig. 4), built so that a
// specimen reaches its target porosity with every grain of the PSD placed:
// a discrete one uniformly, from the floor (or the centre) to the walls, a
// layer-wise one layered by height, its porosity following the local
// grading.
//
// Plain C++, no LIGGGHTS include. A grain is placed on a *site*: a triple of
// supports that it touches, each support a sphere already placed or a
// container wall, solved in closed form:
//   three spheres            Eq. (1), trilateration (falls back to Figs. 7-8
//                            when the grain is too small to touch all three)
//   two spheres and a wall   Eq. (1) with the wall for one sphere
//   one sphere and two walls the sphere touching an edge of the container
//   three walls              a corner (the first grains of a floor start)
// Every placed sphere opens sites with the pairs of spheres (and walls) that
// lie within a small gap of it, on both sides of each triple; sites are taken
// nearest the floor or the ceiling first (start floor_ceiling: two flat
// fronts meeting at mid-height), lowest first (start floor: one front rising
// from the floor) or nearest the container centre first (start centre: the
// paper's growth from a first face at the centre). Taking the nearest site
// first is Bennett's (1972) rule, which packs densely and without a
// gradient, so no pocket is left empty behind the front.
//
// A site that cannot take the grain offered (it would overlap a sphere or
// cross a wall) is not closed: it is kept for the sizes smaller than that
// grain, so fines fill the pockets the coarse grains leave. Grains come in a
// random sequence drawn by number from decks (the particle list, shuffled);
// a drawn grain waits for the next site that fits it, so coarse grains are
// not replaced by fines on the spot. Both arrangement rules place a drawn
// grain on the lowest (nearest) site that fits it; they differ in the draw
// (and in which face spheres a Fig. 8 grain touches, and the default
// start), all in the Rule classes of arrangement_rule.cpp, the one place:
//   discrete  (DA): sizes drawn by number, in random order: fines end up
//                   between coarse grains, a homogeneous mixture;
//   layerwise (LA): a graded bed, the sediment of a soil dumped from a
//                   truck: the draw follows the particle list from the
//                   coarsest to the finest ("the larger and heavier
//                   particles are dropped down first ... the fine particles
//                   take more time to settle down", the paper's step 7 "by
//                   descending order of size"), so like sizes lie together
//                   and the local grading is narrower than the global one.
//                   With one front from the floor the specimen is layered
//                   by height: coarse at the floor, fine under the lid.
// The container is packed full, denser than most targets. Per size class,
// the list's count of the spheres placed are the specimen; the others are
// vacancies, grain-sized holes chosen cell by cell so that every part of the
// container is left as close to the target porosity as its packing allows
// (a layer-wise specimen's fine top packs looser than the target even
// full, and its coarse floor is left denser to make up for it). A class
// that the full packing holds too few of has its missing grains put into
// vacancies of their size or the next larger (the second loop).
#ifndef FABRIC_FRONT_PACKER_H
#define FABRIC_FRONT_PACKER_H

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "psd.h"
#include "trilateration.h"

namespace fabric {

enum class Arrangement { discrete, layerwise };
std::string to_string(Arrangement a);

// Where the packing starts and which site is taken first.
//   floor          one flat front rising from the floor (the ceiling is met
//                  last: its last gap, thinner than a coarse grain, fills
//                  with fines)
//   floor_ceiling  two flat fronts, up from the floor and down from the
//                  ceiling, meeting at mid-height: both end walls are
//                  packed like the side walls (DA's default)
//   centre         the paper's growth from a first face at the centre
//   automatic      floor_ceiling; if that leaves grains of the list
//                  unplaced, floor as well, and the one that leaves less
//                  solid volume unplaced (ties: floor_ceiling). Two fronts
//                  meeting can leave no room for the last coarse grains of
//                  a gap-graded soil, where one front places them.
enum class Start { floor, centre, floor_ceiling, automatic };
std::string to_string(Start s);
// The default start of a rule, from the measured specimens
// (docs/fix_sequential_pack.md): DA automatic, LA floor (a graded bed is
// one sediment, from the floor up).
Start default_start(Arrangement a);

// How a sphere came to its place.
enum class Placement : uint8_t {
  first_face = 0,     // one of the three spheres of the first face (centre)
  trilateration = 1,  // Eq. (1): touches three spheres
  constriction = 2,   // Fig. 7: centre of the constriction (Eq. 2)
  touch_two = 3,      // Fig. 8: in the face plane, touching two face spheres
  wall = 4,           // touches two spheres and a wall
  edge = 5,           // touches one sphere and two walls
  corner = 6,         // touches three walls
  vacancy = 7,        // second loop: put into a vacancy of its size
};
constexpr int kPlacementKinds = 8;
std::string to_string(Placement p);

// The default width of LA's draw schedule (PackingSpec::layering); see
// results/layerwise/README.md for what it gives on the shipped soils.
constexpr double kDefaultLayering = 0.025;

struct PackingSpec {
  Vec3 lo, hi;                      // the container, an axis-aligned box
  std::vector<double> radius;       // per size class
  std::vector<long long> count;     // spheres to place per size class
  Arrangement arrangement = Arrangement::discrete;
  Start start = Start::floor;  // packing_spec() leaves it; see default_start()
  std::uint64_t seed = 1;
  // The second loop: missing grains go into vacancies.
  bool fill_pores = true;
  // LA: how sharply the draw follows the list from coarse to fine, as a
  // share of the list's solid volume: with t the solid volume placed so far
  // (as a share of the list's) and t_k the middle of size k's share in the
  // list ordered coarse first, size k is drawn with weight (left in the
  // deck) * exp(-(t - t_k)^2 / (2 w^2)). Smaller: sharper layers (each
  // height holds a narrower grading); large (>= 1): nearly DA's mixture.
  double layering = kDefaultLayering;
  double equilateral_tolerance = 0.1;  // Fig. 7, see nearly_equilateral()
  double overlap_tolerance = 1e-10;    // relative to the smaller radius
  // Called now and then with (placed, total) for progress output.
  std::function<void(long long, long long)> progress;
};

struct PackingResult {
  std::vector<Vec3> centre;
  std::vector<double> radius;
  std::vector<int> size_class;
  std::vector<Placement> placement;
  std::vector<long long> placed_per_class;
  std::vector<long long> unplaced_per_class;  // found no site and no vacancy
  long long placed_by[kPlacementKinds] = {};
  long long placed_in_second_loop = 0;  // into vacancies
  long long vacancies = 0;              // vacancies left empty at the end
  double vacancy_volume = 0.0;          // their volume
  double packed_volume = 0.0;  // of the full packing, vacancies included
  long long sites = 0;       // sites opened in all
  long long attempts = 0;    // grains offered to a site
  std::size_t peak_bytes = 0;  // the packer's own data at its largest
  Start start = Start::floor;  // the start packed with (never automatic)
  // Start::automatic: grains two fronts left unplaced when one front was
  // taken instead (else 0).
  long long unplaced_with_two_fronts = 0;
  long long placed() const { return static_cast<long long>(centre.size()); }
  long long unplaced() const;
};

// The spec for a particle list in the box [lo, hi]: one size class per
// interval (radius half its diameter, its rounded count); the rest default.
PackingSpec packing_spec(const ParticleList& list, const Vec3& lo,
                         const Vec3& hi);

// Throws std::invalid_argument when the spec is unusable (no spheres,
// negative counts or radii, a container that cannot hold the largest grain).
PackingResult pack(const PackingSpec& spec);

}  // namespace fabric

#endif
