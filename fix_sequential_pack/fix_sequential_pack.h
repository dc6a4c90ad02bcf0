/* fix sequential/pack: a specimen from a PSD and a target porosity by the
   sequential trilateration packing of Galindo-Torres & Scheuermann (see
   docs/fix_sequential_pack.md). A thin adapter: the algorithms live in
   psd.*, trilateration.*, sphere_grid.*, front_packer.* and its outputs in
   pack_outputs.* (no LIGGGHTS include); this class parses the command, runs
   the packer once at setup on every rank (so every rank count gives the
   same specimen), and creates on each rank the atoms inside its subdomain. */

#ifdef FIX_CLASS

FixStyle(sequential/pack,FixSequentialPack)

#else

#ifndef LMP_FIX_SEQUENTIAL_PACK_H
#define LMP_FIX_SEQUENTIAL_PACK_H

#include <string>
#include <vector>

#include "fix.h"
#include "front_packer.h"
#include "pack_outputs.h"
#include "psd.h"

namespace LAMMPS_NS {

class FixSequentialPack : public Fix {
 public:
  FixSequentialPack(class LAMMPS *, int, char **);
  ~FixSequentialPack();
  int setmask();
  void setup_pre_exchange();
  void pre_exchange() {}
  // Called by LIGGGHTS before it deletes the fix (unfix, or a new fix with
  // the same ID): records whether the specimen was inserted.
  void pre_delete(bool unfixflag);

  // largest radius this fix inserts, so pair gran sizes its cut-off before
  // the atoms exist
  double max_rad(int type);
  double min_rad(int type);
  // the atom type it inserts, for LIGGGHTS' material-property checks
  int min_type() { return atom_type_; }
  int max_type() { return atom_type_; }

  // per-atom interval index (f_ID), carried with the atoms
  void grow_arrays(int);
  void copy_arrays(int, int, int);
  void set_arrays(int);
  int pack_exchange(int, double *);
  int unpack_exchange(int, double *);
  int pack_restart(int, double *);
  void unpack_restart(int, int);
  int size_restart(int) { return 2; }
  int maxsize_restart() { return 2; }
  double memory_usage();
  double compute_vector(int i);

  // global state: whether the specimen was inserted (no re-insertion after
  // read_restart)
  void write_restart(FILE *);
  void restart(char *);

 private:
  void parse(int narg, char **arg);
  void read_keywords(const class StyleArgs &);
  void read_container(const class StyleArgs &);
  void read_psd(const class StyleArgs &);
  void check_memory(const class StyleArgs &);
  void warn_empty_intervals();
  fabric::Box container() const;

  void insert_specimen();
  fabric::PackingSpec packing_spec();
  void warn_atoms_inside();
  void create_atoms(const fabric::PackingResult &);
  std::string summary_text(const fabric::PackReport &,
                           const fabric::PackingResult &);
  std::string summary_figures(const fabric::PackReport &,
                              const fabric::PackingResult &);
  std::string profile_figures(const fabric::PackVector &);
  // Stops the run when the specimen's coarse grains have more neighbours
  // (within their radius + a neighbour's radius + the neighbor skin) than
  // LIGGGHTS' neighbour list holds per atom (neigh_modify one).
  void check_neighbours(const fabric::PackingResult &);
  void message(const std::string &text);

  std::string psd_file_, region_id_;
  fabric::ParticleSizeDistribution *psd_;
  std::vector<fabric::SizeInterval> intervals_;
  fabric::ParticleList list_;
  fabric::Arrangement arrangement_;
  double porosity_, density_;
  int nintervals_, atom_type_, seed_;
  bool fill_pores_, verbose_;
  fabric::Start start_;
  double layering_;
  std::vector<double> vector_;  // the global vector, laid out by pack_outputs.h
  double lo_[3], hi_[3];
  int inserted_;
  double *interval_;  // per atom: interval index 1..N, 0 = not from this fix
  int nmax_;          // length of interval_
};

}  // namespace LAMMPS_NS

#endif
#endif
