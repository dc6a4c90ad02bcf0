/* compute constriction/size: the constriction size distribution (CSD) of
   the grains of a group (the whole specimen or its primary fabric) and the
   share of a loose group that fits through it (see
   docs/compute_constriction_size.md). A thin adapter: the triangulation and
   the constrictions live in constriction_network.*, the global vector's
   entries in constriction_outputs.* (no LIGGGHTS include); this class gathers the group's grains to rank 0, which triangulates, and
   broadcasts the result. */

#ifdef COMPUTE_CLASS

ComputeStyle(constriction/size,ComputeConstrictionSize)

#else

#ifndef LMP_COMPUTE_CONSTRICTION_SIZE_H
#define LMP_COMPUTE_CONSTRICTION_SIZE_H

#include <string>
#include <vector>

#include "compute.h"
#include "constriction_outputs.h"

namespace LAMMPS_NS {

class ComputeConstrictionSize : public Compute {
 public:
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
    fabric::VerdictGrains verdict;
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
  fabric::GradingCriteria criteria_;  // of keyword psd (0 without)
  class Compute *fabric_ = nullptr;  // compute primary/fabric (keyword fabric)
  int loose_bit_ = 0;
  int nslices_ = 0;  // height slices (keyword slices), 0 without
  double control_percent_ = 35.0;
  fabric::CsdWeight control_weight_ = fabric::CsdWeight::number;
  bigint analysed_step_ = -1;
  int nrows_ = 0;  // local rows held
};

}  // namespace LAMMPS_NS

#endif
#endif
