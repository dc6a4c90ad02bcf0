/* compute constriction/size: the constriction size distribution (CSD) of
   the grains of a group (the whole specimen or its primary fabric) and the
   share of a loose group that fits through it (see
   docs/compute_constriction_size.md). A thin adapter: the triangulation and
   the constrictions live in constriction_network.* (no LIGGGHTS include);
   this class gathers the group's grains to rank 0, which triangulates, and
   broadcasts the result. */

#ifdef COMPUTE_CLASS

ComputeStyle(constriction/size,ComputeConstrictionSize)

#else

#ifndef LMP_COMPUTE_CONSTRICTION_SIZE_H
#define LMP_COMPUTE_CONSTRICTION_SIZE_H

#include <string>
#include <vector>

#include "compute.h"
#include "constriction_network.h"

namespace LAMMPS_NS {

class ComputeConstrictionSize : public Compute {
 public:
  // Global vector: 1 the number of constrictions, 2..20 D_c5..D_c95 by
  // number, 21..39 the same weighted by D_c^3, then these (1-based).
  enum {
    kPercolation = 40, kControl, kLooseFinerControl, kLooseFinerPercolation,
    kLooseMassPercent, kPores, kGrains, kHidden, kWallExcluded, kOnEdge,
    kUnsolved, kWallMargin,
    // The classical criteria of the PSD of keyword psd (0 without).
    kKezdi, kKenneyLau, kBurenkovaH1, kBurenkovaH2, kBurenkovaStable,
    kWanFell, kVectorSize = kWanFell
  };

  ComputeConstrictionSize(class LAMMPS *, int, int, char **);
  ~ComputeConstrictionSize();
  void init();
  void compute_vector();
  void compute_local();
  double memory_usage();

 private:
  void parse(int narg, char **arg);
  void read_criteria(const class StyleArgs &args, int i);
  void analyse();  // once per step
  // The pore-forming grains, and the loose grains' diameters and masses, on
  // rank 0 in the order of the atom IDs (empty elsewhere).
  struct Grains {
    std::vector<fabric::Sphere> skeleton;
    std::vector<double> skeleton_mass, loose_diameter, loose_mass;
  };
  Grains gather();
  void fill_vector(const fabric::ConstrictionNetwork &net, const Grains &g);
  void fill_local(const fabric::ConstrictionNetwork &net);
  void write_csd(const fabric::ConstrictionNetwork &net);
  void update_classes();       // the fabric compute's classes, current
  bool skeleton(int i) const;  // atom i forms the pores
  bool loose(int i) const;     // atom i enters the verdict as loose


  fabric::ConstrictionOptions options_;
  std::string region_id_, loose_group_, csd_file_, fabric_id_;
  double criteria_[6] = {0, 0, 0, 0, 0, 0};  // of keyword psd
  class Compute *fabric_ = nullptr;  // compute primary/fabric (keyword fabric)
  int loose_bit_ = 0;
  double control_percent_ = 35.0;
  bigint analysed_step_ = -1;
  int nrows_ = 0;  // local rows held
};

}  // namespace LAMMPS_NS

#endif
#endif
