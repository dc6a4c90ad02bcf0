// The constrictions of a packing of spheres: the pore throats that a grain
// must pass to move from one pore to the next (see
// docs/compute_constriction_size.md).
//
// Plain C++ with Eigen, no LIGGGHTS include. The pore space is split by the
// regular (power-weighted) Delaunay triangulation of the sphere centres with
// weights r^2 (core/regular_triangulation.h, the one the pore flow uses); each
// tetrahedron is a pore. Tetrahedra whose weighted circumcentres coincide
// (lattices: the octahedral pore of FCC, the cube of simple cubic) are one
// pore; with PoreMerging::overlap, so are neighbours whose inscribed pore
// spheres overlap. Every triangular face between two different pores gives
// one constriction, the paper's Eq. (2) (fabric::constriction of
// core/trilateration.h): the largest circle in the face plane touching the
// three spheres. Where that circle does not lie inside the triangle (an
// obtuse face: two fine spheres with a coarse one to the side), the face's
// narrowest passage lies on an edge, and its constriction is the largest
// circle centred on an edge that overlaps none of the three; coplanar faces between the same two pores (the
// two halves of a lattice's square face) are one opening, the largest of
// their circles.
#ifndef FABRIC_CONSTRICTION_NETWORK_H
#define FABRIC_CONSTRICTION_NETWORK_H

#include <array>
#include <optional>
#include <vector>

#include "box.h"
#include "trilateration.h"

namespace fabric {

enum class PoreMerging {
  coincident,  // tetrahedra with coincident weighted circumcentres
  overlap      // also neighbours whose inscribed pore spheres overlap
};

struct ConstrictionOptions {
  PoreMerging merging = PoreMerging::coincident;
  // Two circumcentres coincide within this share of the face's largest
  // sphere radius.
  double coincident_tolerance = 1e-6;
  // Faces whose centroid lies closer than this to a container wall are not
  // counted; negative: one coarsest diameter of the spheres.
  double wall_margin = -1.0;
  // The container; empty: the bounding box of the spheres.
  std::optional<Box> container;
};

struct ConstrictionDisc {
  Vec3 centre;
  Vec3 normal;  // unit normal of the face
  double radius;
  // Eq. (2) has no circle inside the triangle (an obtuse face): the largest
  // empty circle centred on one of the face's edges instead.
  bool on_edge = false;
  // Centroid of the face the circle lies in (of the face whose circle
  // represents a coplanar opening): where compute constriction/size's
  // keyword slices places the constriction.
  Vec3 face_centroid = Vec3::Zero();
};

struct ConstrictionNetwork {
  std::vector<ConstrictionDisc> discs;  // counted, away from the walls
  long spheres = 0;        // input spheres
  long hidden = 0;         // spheres the regular triangulation hides
  long cells = 0;          // finite tetrahedra
  long pores = 0;          // after merging
  long wall_excluded = 0;  // faces between pores within the wall margin
  long on_edge = 0;        // counted discs on an edge (see ConstrictionDisc)
  long unsolved = 0;       // faces away from the walls without any circle
  double wall_margin = 0.0;
  Box container;
  // Largest diameter that a path of pores from the floor to the lid never
  // narrows below; 0 if no path. The path starts in a pore behind a bottom
  // face of the convex hull (outward normal within 45 degrees of -z), ends
  // behind a top face, and passes faces between pores away from the side
  // walls (x, y; by the wall margin); a face without an Eq. (2) circle is
  // closed.
  double percolation_diameter = 0.0;
};

// Throws std::invalid_argument for fewer than 4 spheres, a non-finite or
// non-positive radius, or bad options.
ConstrictionNetwork constriction_network(const std::vector<Sphere>& spheres,
                                         const ConstrictionOptions& options);

// Inscribed pore sphere of a tetrahedron of four spheres: the sphere that
// touches all four from outside (|x - c_i| = r_i + rho). Empty when there is
// none with rho > 0.
std::optional<Sphere> inscribed_pore_sphere(const std::array<Sphere, 4>& s);

// How the discs count in a percentile of the CSD: one each, by their area
// (diameter^2, Indraratna et al.'s controlling constriction), or by
// diameter^3 (as a PSD is by mass).
enum class CsdWeight { number, area, cubic };

// Diameters below which `percent` of the discs lie: by number linear between
// order statistics; weighted, the smallest diameter at which the cumulative
// share reaches it. `percents` in (0, 100). Empty discs: NaN.
std::vector<double> csd_percentiles(const std::vector<ConstrictionDisc>& discs,
                                    const std::vector<double>& percents,
                                    CsdWeight weight);
// ... true: CsdWeight::cubic, false: CsdWeight::number
std::vector<double> csd_percentiles(const std::vector<ConstrictionDisc>& discs,
                                    const std::vector<double>& percents,
                                    bool cubic_weight);

// Cumulative CSD: sorted diameters with the percent finer by number, by
// area and by diameter^3 at each.
struct CsdPoint {
  double diameter, percent_number, percent_cubic, percent_area;
};
std::vector<CsdPoint> cumulative_csd(const std::vector<ConstrictionDisc>& discs);

}  // namespace fabric

#endif
