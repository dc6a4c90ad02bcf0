/* compute primary/fabric: which particles carry the load (the primary
   fabric) and which lie loose, after Galindo-Torres & Scheuermann (see
   docs/compute_primary_fabric.md). A thin adapter: the classification and
   all sums live in fabric_analysis.* (no LIGGGHTS include); this class
   collects each owned particle's contacts from the granular pair style and
   the granular walls, feeds them to the core and reduces the sums with MPI. */

#ifdef COMPUTE_CLASS

ComputeStyle(primary/fabric,ComputePrimaryFabric)

#else

#ifndef LMP_COMPUTE_PRIMARY_FABRIC_H
#define LMP_COMPUTE_PRIMARY_FABRIC_H

#include <string>
#include <vector>

#include "compute.h"
#include "fabric_analysis.h"
#include "height_slices.h"
#include "interval_assignment.h"

namespace LAMMPS_NS {

class ComputePrimaryFabric : public Compute {
 public:
  ComputePrimaryFabric(class LAMMPS *, int, int, char **);
  ~ComputePrimaryFabric();
  void init();
  void compute_peratom();
  void compute_vector();
  void compute_array();
  int pack_comm(int, int *, double *, int, int *);
  void unpack_comm(int, int, double *);
  double memory_usage();

 private:
  void parse(int narg, char **arg);
  int read_keyword(const class StyleArgs &, int i);
  int read_threshold(const class StyleArgs &, int i);
  void read_psd(const class StyleArgs &);
  void find_walls();
  // The particles and contact ends of this rank in one evaluation.
  struct Step {
    std::vector<int> index;  // per local atom: its particle, -1 none
    std::vector<fabric::Particle> particles;
    std::vector<double> z;   // each particle's height (its centre's z)
    std::vector<fabric::ParticleContact> contacts;
    std::vector<int> partner;  // local or ghost index of each contact's partner
    std::vector<fabric::WallContact> walls;
    std::vector<double> representative;  // diameters (empty: measured)
  };
  void analyse();      // once per step: classification and sums
  void check_stored_step();
  void grow_peratom();
  void collect_particles(Step &);
  void stop_on_bad_index(long long count, double value);
  double weight(int i) const;
  void stop_on_outside(long long count, double diameter);
  void warn_nonfinite();
  void collect_contacts(Step &);
  void classify(const Step &);
  void slice(const Step &, const fabric::Classification &);
  void assign_intervals();
  fabric::IntervalAssignment interval_assignment(
      std::vector<double> &representative);

  fabric::Options options_;
  int nintervals_;
  std::string psd_file_;
  std::string intervals_from_;  // fix storing each atom's interval index
  class Fix *interval_fix_ = nullptr;
  std::vector<std::string> wall_ids_;  // empty: every granular wall
  bool walls_given_;
  // The pair style stores contact forces only on steps that are multiples
  // of this (keyword store_every; 1: every step).
  long store_every_ = 1;

  class PairGran *pair_;
  std::vector<class FixContactPropertyAtom *> wall_contacts_;
  std::vector<double> class_diameter_;  // representative, finest first
  std::vector<double> class_lower_, class_upper_;  // PSD bounds (psd mode)
  bool intervals_ready_;

  bigint analysed_step_;
  fabric::FabricSummary summary_;
  int nslices_ = 0;  // keyword slices: height slices reported (0: none)
  std::vector<fabric::SliceSummary> slices_;
  double threshold_force_;
  bool weigh_volume_ = false;  // weight volume: "by mass" weighs volumes
  int iterations_;
  bool warned_ = false;

  int nmax_;
  double **peratom_;  // loaded contacts, class, interval
  double *loose_;     // for the forward communication in prune iterate
};

}  // namespace LAMMPS_NS

#endif
#endif
