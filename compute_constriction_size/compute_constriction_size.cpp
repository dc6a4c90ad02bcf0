/* compute constriction/size: LIGGGHTS adapter of the constriction network.
   See compute_constriction_size.h and docs/compute_constriction_size.md. */

#include "compute_constriction_size.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "region.h"
#include "style_args.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {
const int kLocalColumns = 7;  // centre x y z, normal x y z, radius
}  // namespace

ComputeConstrictionSize::ComputeConstrictionSize(LAMMPS *lmp, int iarg,
                                                 int narg, char **arg)
    : Compute(lmp, iarg, narg, arg) {
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "Compute constriction/size requires atom_style granular "
                      "(sphere: radius, rmass)");
  parse(narg - iarg, arg + iarg);
  vector_flag = 1;
  size_vector = fabric::constriction_vector_size(nslices_);
  extvector = 0;
  local_flag = 1;
  size_local_rows = 0;
  size_local_cols = kLocalColumns;
  vector = new double[size_vector]();
  array_local = nullptr;
}

ComputeConstrictionSize::~ComputeConstrictionSize() {
  delete[] vector;
  memory->destroy(array_local);
}

void ComputeConstrictionSize::parse(int narg, char **arg) {
  const StyleArgs args(error, "Compute constriction/size", narg, arg,
                       {"container", "wall_margin", "merge", "tolerance",
                        "loose", "fabric", "control", "control_by", "psd", "csd",
                        "slices"});
  for (int i = 0; i < args.size(); i += 2) {
    const std::string kw = args[i];
    if (kw == "container") {
      region_id_ = args.value(i, "the ID of a region of style block");
    } else if (kw == "wall_margin") {
      options_.wall_margin = args.number(i, "a length >= 0");
      args.require(options_.wall_margin >= 0.0, i, "must not be negative");
    } else if (kw == "merge") {
      options_.merging = args.choice(i, {"coincident", "overlap"}) == 0
                             ? fabric::PoreMerging::coincident
                             : fabric::PoreMerging::overlap;
    } else if (kw == "tolerance") {
      options_.coincident_tolerance = args.number(i, "a share in [0, 0.1]");
      args.require(options_.coincident_tolerance >= 0.0 &&
                       options_.coincident_tolerance <= 0.1,
                   i, "must lie in [0, 0.1]");
    } else if (kw == "loose") {
      loose_group_ = args.value(i, "a group ID");
      const int g = group->find(loose_group_.c_str());
      if (g < 0) args.fail("loose group '" + loose_group_ + "' does not exist");
      loose_bit_ = group->bitmask[g];
    } else if (kw == "fabric") {
      fabric_id_ = args.value(i, "the ID of a compute primary/fabric");
    } else if (kw == "control_by") {
      control_weight_ = args.choice(i, {"number", "area"}) == 0 ? fabric::CsdWeight::number
                                                                 : fabric::CsdWeight::area;
    } else if (kw == "control") {
      control_percent_ = args.number(i, "a percent in [5, 95]");
      args.require(control_percent_ >= 5.0 && control_percent_ <= 95.0, i,
                   "must lie in [5, 95]");
    } else if (kw == "psd") {
      read_criteria(args, i);
    } else if (kw == "csd") {
      csd_file_ = args.value(i, "a file name");
    } else if (kw == "slices") {
      nslices_ = static_cast<int>(args.integer_in(i, 1, 1000));
    } else {
      args.unknown_keyword(i);
    }
  }
}

// The classical criteria of the grading in file arg[i + 1] (entries 52-58).
void ComputeConstrictionSize::read_criteria(const StyleArgs &args, int i) {
  try {
    criteria_ = fabric::grading_criteria(
        fabric::ParticleSizeDistribution::read(args.value(i, "a PSD file")));
  } catch (const std::exception &e) {
    args.fail(e.what());
  }
}

void ComputeConstrictionSize::init() {
  if (!region_id_.empty()) {
    int r = domain->find_region(const_cast<char *>(region_id_.c_str()));
    if (r < 0)
      error->all(FLERR, ("Compute constriction/size: container region '" +
                         region_id_ + "' does not exist").c_str());
    if (strcmp(domain->regions[r]->style, "block") != 0)
      error->all(FLERR, ("Compute constriction/size: container region '" +
                         region_id_ + "' is style " +
                         domain->regions[r]->style +
                         "; only a block container is supported").c_str());
  }
  fabric_ = nullptr;
  if (!fabric_id_.empty()) {
    int c = modify->find_compute(const_cast<char *>(fabric_id_.c_str()));
    if (c < 0)
      error->all(FLERR, ("Compute constriction/size: fabric compute ID '" +
                         fabric_id_ + "' does not exist").c_str());
    if (strcmp(modify->compute[c]->style, "primary/fabric") != 0)
      error->all(FLERR, ("Compute constriction/size: compute '" + fabric_id_ +
                         "' is style " + modify->compute[c]->style +
                         ", not primary/fabric").c_str());
    fabric_ = modify->compute[c];
  }
  analysed_step_ = -1;  // a new run: atoms may have moved on this same step
}

ComputeConstrictionSize::Grains ComputeConstrictionSize::gather() {
  const int kFields = 7;  // tag, x, y, z, r, mass, 1 skeleton / 0 loose
  std::vector<double> mine;
  for (int i = 0; i < atom->nlocal; ++i) {
    const bool s = skeleton(i);
    if (!s && !loose(i)) continue;
    mine.insert(mine.end(), {double(atom->tag[i]), atom->x[i][0],
                             atom->x[i][1], atom->x[i][2], atom->radius[i],
                             atom->rmass[i], s ? 1.0 : 0.0});
  }
  int n = static_cast<int>(mine.size());
  std::vector<int> counts(comm->nprocs), displs(comm->nprocs);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, world);
  long total = 0;
  for (int p = 0; p < comm->nprocs; ++p) displs[p] = total, total += counts[p];
  std::vector<double> all(comm->me == 0 ? total : 0);
  MPI_Gatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(),
              displs.data(), MPI_DOUBLE, 0, world);
  // In the order of the atom IDs: the same triangulation and sums on any
  // number of ranks.
  std::vector<long> order(all.size() / kFields);
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](long a, long b) {
    return all[a * kFields] < all[b * kFields];
  });
  Grains g;
  for (long k : order) {
    const double *f = &all[k * kFields];
    if (f[6] == 1.0) {
      g.skeleton.push_back({fabric::Vec3(f[1], f[2], f[3]), f[4]});
      g.verdict.pore_forming_mass += f[5];
    } else {
      g.verdict.loose_diameter.push_back(2.0 * f[4]);
      g.verdict.loose_mass.push_back(f[5]);
      g.verdict.loose_z.push_back(f[3]);
    }
  }
  return g;
}

void ComputeConstrictionSize::analyse() {
  if (analysed_step_ == update->ntimestep) return;
  analysed_step_ = update->ntimestep;
  update_classes();
  bigint mine = 0, ngrains = 0;
  for (int i = 0; i < atom->nlocal; ++i) mine += skeleton(i);
  MPI_Allreduce(&mine, &ngrains, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (ngrains < 4) {
    char m[256];
    snprintf(m, sizeof m, "Compute constriction/size: %s of group '%s' has "
             BIGINT_FORMAT " grains; a constriction network needs at least 4",
             fabric_ ? "the primary fabric" : "the group",
             group->names[igroup], ngrains);
    error->all(FLERR, m);
  }
  if (!region_id_.empty()) {
    Region *r = domain->regions[domain->find_region(
        const_cast<char *>(region_id_.c_str()))];
    options_.container = fabric::Box{
        fabric::Vec3(r->extent_xlo, r->extent_ylo, r->extent_zlo),
        fabric::Vec3(r->extent_xhi, r->extent_yhi, r->extent_zhi)};
  }
  Grains grains = gather();
  fabric::ConstrictionNetwork net;
  char message[512] = "";
  if (comm->me == 0) {
    try {
      net = fabric::constriction_network(grains.skeleton, options_);
      fill_vector(net, grains);
    } catch (const std::exception &e) {
      snprintf(message, sizeof message, "Compute constriction/size: %s",
               e.what());
    }
  }
  MPI_Bcast(message, sizeof message, MPI_CHAR, 0, world);
  if (message[0]) error->all(FLERR, message);
  grains = Grains();
  MPI_Bcast(vector, size_vector, MPI_DOUBLE, 0, world);
  fill_local(net);
  if (comm->me == 0) write_csd(net);
}

void ComputeConstrictionSize::fill_vector(const fabric::ConstrictionNetwork &net,
                                          const Grains &g) {
  std::vector<fabric::ConstrictionSlice> slices;
  if (nslices_ > 0)
    slices = fabric::constriction_slices(net, g.skeleton, g.verdict, nslices_,
                                         control_percent_, control_weight_);
  const std::vector<double> v = fabric::constriction_vector(
      net, control_percent_, control_weight_, g.verdict, criteria_, slices);
  std::copy(v.begin(), v.end(), vector);
  char m[512];
  if (net.hidden > 0) {
    snprintf(m, sizeof m, "Compute constriction/size: %ld of %ld grains "
             "overlap their neighbours so much that the regular "
             "triangulation hides them; they are left out of the pores",
             net.hidden, net.spheres);
    error->warning(FLERR, m);
  }
  if (net.discs.empty()) {
    snprintf(m, sizeof m, "Compute constriction/size: no constriction lies "
             "farther than the wall margin %g from the container walls; the "
             "diameters are NaN", net.wall_margin);
    error->warning(FLERR, m);
  }
}

void ComputeConstrictionSize::fill_local(const fabric::ConstrictionNetwork &net) {
  memory->destroy(array_local);
  nrows_ = static_cast<int>(net.discs.size());  // rank 0 holds them all
  size_local_rows = nrows_;
  if (nrows_ == 0) return;
  memory->create(array_local, nrows_, kLocalColumns,
                 "constriction/size:array_local");
  for (int r = 0; r < nrows_; ++r) {
    const auto &d = net.discs[r];
    for (int k = 0; k < 3; ++k) {
      array_local[r][k] = d.centre[k];
      array_local[r][3 + k] = d.normal[k];
    }
    array_local[r][6] = d.radius;
  }
}

void ComputeConstrictionSize::write_csd(const fabric::ConstrictionNetwork &net) {
  if (csd_file_.empty()) return;
  FILE *f = fopen(csd_file_.c_str(), "w");
  if (!f) {
    error->warning(FLERR, ("Compute constriction/size: cannot write csd file '" +
                           csd_file_ + "'").c_str());
    return;
  }
  fprintf(f, "# compute %s constriction/size, group %s, step " BIGINT_FORMAT
          ": %zu constrictions\n# diameter percent_finer_by_number "
          "percent_finer_by_diameter_cubed\n",
          id, group->names[igroup], update->ntimestep, net.discs.size());
  for (const auto &p : fabric::cumulative_csd(net.discs))
    fprintf(f, "%.9g %.6f %.6f\n", p.diameter, p.percent_number,
            p.percent_cubic);
  fclose(f);
}

void ComputeConstrictionSize::update_classes() {
  if (fabric_ && fabric_->invoked_peratom != update->ntimestep)
    fabric_->compute_peratom();  // it records the step itself
}

bool ComputeConstrictionSize::skeleton(int i) const {
  if (!(atom->mask[i] & groupbit)) return false;
  return !fabric_ || fabric_->array_atom[i][1] == 1.0;
}

bool ComputeConstrictionSize::loose(int i) const {
  if (loose_bit_) return atom->mask[i] & loose_bit_;
  return fabric_ && (atom->mask[i] & groupbit) &&
         fabric_->array_atom[i][1] == 0.0;
}

void ComputeConstrictionSize::compute_vector() {
  invoked_vector = update->ntimestep;
  analyse();
}

void ComputeConstrictionSize::compute_local() {
  invoked_local = update->ntimestep;
  analyse();
}

double ComputeConstrictionSize::memory_usage() {
  return static_cast<double>(nrows_) * kLocalColumns * sizeof(double);
}
