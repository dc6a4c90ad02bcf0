// The sequential front packer of the paper (section 2.2, Fig. 4).
//
// Plain C++, no LIGGGHTS include. The largest sphere and two companions form
// the first face at the container centre. Faces are oriented triangles of
// sphere centres whose right-hand normal points to their open side; they are
// taken in turn, the one nearest the container centre first, so the front
// grows as a compact ball out to the walls. A sphere is attached to a face by
// trilateration (Eq. 1) or, when it is too small for Eq. 1, by the fallbacks
// of Figs. 7-8; if it overlaps no sphere and no wall the face closes, the
// sphere is used and its three new faces open. On overlap the arrangement
// rule decides (the one place where the two rules differ: next_candidate):
//   layerwise (LA): spheres are used strictly largest first and the face
//                   closes for that size, so like sizes end up together;
//   discrete  (DA): spheres come in a random sequence drawn by the volume
//                   left per size (weighted towards coarse sizes); on overlap
//                   the smaller sizes are tried on the same face before it
//                   closes, so fine spheres fill the gaps between coarse ones.
// Both rules spend their retries (DA: smaller sizes; LA: reopening closed
// faces near the front) only while the placed volume is behind the target
// solid fraction of the container volume the front has swept: this keeps the
// specimen at its target density from the centre out to the walls. A sphere
// whose Eq. (1) position crosses a wall is moved to touch the wall and two of
// the face spheres.
// It ends when all spheres are used or all faces closed. For DA an optional
// second loop (pore filling, the paper's ref. [32]) revisits the faces that
// closed without a sphere, with the spheres that are left.
#ifndef FABRIC_FRONT_PACKER_H
#define FABRIC_FRONT_PACKER_H

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "trilateration.h"

namespace fabric {

enum class Arrangement { discrete, layerwise };
std::string to_string(Arrangement a);

// How a sphere came to its place.
enum class Placement : uint8_t {
  first_face = 0,     // one of the three spheres of the first face
  trilateration = 1,  // Eq. (1): touches the three face spheres
  constriction = 2,   // Fig. 7: centre of the constriction (Eq. 2)
  touch_two = 3,      // Fig. 8: in the face plane, touching two face spheres
  wall = 4,           // Eq. (1) with a wall for one face sphere
};
constexpr int kPlacementKinds = 5;

struct PackingSpec {
  Vec3 lo, hi;                      // the container, an axis-aligned box
  std::vector<double> radius;       // per size class
  std::vector<long long> count;     // spheres to place per size class
  Arrangement arrangement = Arrangement::discrete;
  std::uint64_t seed = 1;           // orientation and companions of face 1
  bool fill_pores = true;           // the second loop (DA only)
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
  std::vector<long long> skipped_per_class;  // LA: set aside, unplaced
  long long placed_by[kPlacementKinds] = {};
  long long placed_in_second_loop = 0;
  long long faces = 0;       // faces opened in all
  long long attempts = 0;    // placement attempts (one per face and size)
  std::size_t peak_bytes = 0;  // the packer's own data at its largest
  long long placed() const { return static_cast<long long>(centre.size()); }
};

// Throws std::invalid_argument when the spec is unusable (no spheres,
// negative counts or radii, a container that cannot hold the first face).
PackingResult pack(const PackingSpec& spec);

}  // namespace fabric

#endif
