// Measuring a sphere packing by volume: porosity of boxes, of sub-cubes and
// of the wall layer, size segregation, contacts and grading.
//
// Plain C++ with Eigen, no LIGGGHTS include. Porosities come from the exact
// volume of each sphere inside a box, not from counting centres: a specimen
// of a few thousand grains has too few grains per sub-cube for the
// centre-counting error (about one grain per face) to be negligible.
//
// Neighbour and region searches use one uniform grid whose cell holds, on
// average, one sphere; each sphere is entered in every cell its bounding box
// meets. With radius ratios up to 25 a grid sized by the largest sphere
// would put thousands of fine spheres in a cell; this one costs a coarse
// sphere (d/h)^3 entries, which sums to O(N) because the spheres' volumes
// sum to less than the grid's. A pair (or a sphere and a region) is handled
// only in the cell that holds the lower corner of the two boxes'
// intersection, so nothing is counted twice.
#ifndef FABRIC_SPECIMEN_MEASURE_H
#define FABRIC_SPECIMEN_MEASURE_H

#include <array>
#include <utility>
#include <vector>

#include "box.h"
#include "trilateration.h"

namespace fabric {

// The layers of the profile by height that a specimen's summary reports
// (PackingMeasure::layer_profile), floor first: the one number that sizes
// fix sequential/pack's profile, its vector entries and its page's table
// (pack_outputs.h; tools/outputs.py reads it from here).
constexpr int kProfileLayers = 6;

// Volume of the part of the sphere (c, r) inside the box: closed form when
// at most one face cuts the sphere, else the closed-form disc-rectangle area
// integrated adaptively along the box's thinnest axis. Exact to about 1e-13
// of the sphere's volume, and about 1e-12 of its own for thin slabs.
double sphere_box_volume(const Vec3& c, double r, const Box& b);

// Area of the part of the disc of radius `R` centred at the origin inside
// the rectangle [x0, x1] x [y0, y1] (closed form).
double disc_rectangle_area(double R, double x0, double x1, double y0,
                           double y1);

struct RegionPorosity {
  double porosity;
  double solid_volume;   // of the spheres, inside the region
  double region_volume;
  // Mass-weighted mean diameter of the solid in the region: each sphere's
  // diameter weighted by its volume inside (NaN if the region holds none).
  double mean_diameter;
};

class PackingMeasure {
 public:
  PackingMeasure(const std::vector<Vec3>& centre,
                 const std::vector<double>& radius, const Box& container);

  RegionPorosity measure(const Box& region) const;
  double porosity(const Box& region) const { return measure(region).porosity; }
  // The container split n x n x n, x fastest: index i + n (j + n k).
  std::vector<double> subcube_porosity(int n = 3) const;
  // Interior: the container shrunk by `layer` on every side; wall layer:
  // the container minus the interior. Throws std::invalid_argument unless
  // 0 <= layer < half the container's smallest edge.
  Box interior(double layer) const;
  double interior_porosity(double layer) const;
  double wall_layer_porosity(double layer) const;

  // Spearman rank correlation of radius with the distance of the centre
  // from the container's centre (ties: average ranks); NaN if undefined.
  double radius_distance_spearman() const;

  // Pairs (i < j, sorted) with gap |ci - cj| - ri - rj < tol min(ri, rj).
  std::vector<std::pair<int, int>> touching_pairs(double tol = 1e-9) const;
  // Contacts of each sphere: its touching pairs (as above) plus the
  // container's faces within the same gap (centre closer to the face than
  // r + tol r). The paper counts these before loading ("all particles have
  // contacts with at least three other particles and/or the container").
  std::vector<int> contact_counts(double tol = 1e-9) const;
  // Newman's assortativity of ln r over the touching pairs (each pair in
  // both orders); NaN without pairs or without spread.
  double size_assortativity(double tol = 1e-9) const;
  // The same over the touching pairs whose two centres lie in `region`
  // (closed box), e.g. the interior: a layer of like sizes on one wall
  // (layer-wise packing grows a fine one on its floor) raises the value
  // over the container without any layering inside.
  double size_assortativity(const Box& region, double tol = 1e-9) const;

  // Uniformity coefficient d60/d10 by volume of the spheres whose centre
  // lies in `region` (closed box). The grading curve is the cumulative
  // volume fraction P_k of the spheres sorted by diameter, through the
  // points (d_k, P_k), linear in between; below P_1 it is d_1. NaN if
  // fewer than 2 spheres.
  double local_cu(const Box& region) const;
  double cu() const;
  // Mean local grading over global: the container split n x n x n, the
  // grains assigned to the sub-cube of their centre (half-open cells, the
  // last closed), the mean of local_cu over the sub-cubes holding at least
  // `min_grains` grains, over cu(). 1 for a mixture, below 1 where like
  // sizes lie together. NaN if no sub-cube holds enough grains.
  double mean_local_cu_ratio(int n = 3, int min_grains = 50) const;

  // The container cut into `layers` slabs of equal thickness along `axis`
  // (2: by height, floor first), each measured by volume (porosity and
  // mass-weighted mean diameter from the exact sphere-slab volumes, never
  // by centres). Throws std::invalid_argument unless layers >= 1 and
  // 0 <= axis <= 2.
  std::vector<RegionPorosity> layer_profile(int layers, int axis = 2) const;

  // Largest (ri + rj - |ci - cj|) / min(ri, rj) over all pairs; 0 if no
  // pair overlaps.
  double worst_overlap() const;
  // True if every sphere lies inside the container to within tol r.
  bool all_inside(double tol = 1e-9) const;

  int size() const { return static_cast<int>(r_.size()); }

 private:
  // Spheres of radius r (1 + inflate) entered in every cell they meet.
  struct Bins {
    Vec3 origin = Vec3::Zero();
    double h = 1.0;
    std::array<long, 3> n{{1, 1, 1}};
    double inflate = 0.0;
    std::vector<long> start;  // CSR: cell c holds item[start[c] .. start[c+1])
    std::vector<int> item;
    std::array<long, 3> cell(const Vec3& p) const;
    long index(const std::array<long, 3>& k) const {
      return k[0] + n[0] * (k[1] + n[1] * k[2]);
    }
  };
  Bins bin(double inflate) const;
  template <class F>
  void for_each_pair(const Bins& b, F&& f) const;
  double cu_of(const std::vector<int>& ids) const;
  // The touching pairs for `tol`, searched once and kept: the summary asks
  // for contact counts and the assortativity of the same pairs.
  const std::vector<std::pair<int, int>>& pairs(double tol) const;

  std::vector<Vec3> c_;
  std::vector<double> r_;
  Box box_;
  Bins bins_;  // inflate 0, for region queries
  mutable double pairs_tol_ = -1.0;  // the tol of pairs_ (-1: none yet)
  mutable std::vector<std::pair<int, int>> pairs_;
};

}  // namespace fabric

#endif
