#include "fix_quasi_static.h"

#include <cmath>
#include <cstring>

#include "atom.h"
#include "compute.h"
#include "error.h"
#include "fabric_outputs.h"
#include "modify.h"
#include "quasi_static.h"
#include "style_args.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
// Per-atom column of compute primary/fabric with each grain's loaded
// contacts (fabric_outputs.h), counted from 0.
constexpr int kLoadedContactsColumn =
    fabric::peratom_column(fabric::PeratomColumn::loaded_contacts);

int zero_interval(const StyleArgs &args, int i) {
  return static_cast<int>(args.integer_in(
      i, 0, 1000000000,
      "0: no kinetic damping; N: every grain's velocity set to zero every N "
      "steps"));
}
}  // namespace

FixQuasiStatic::FixQuasiStatic(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg), alpha_(0.7) {
  StyleArgs args(error, "Fix quasi/static", narg - 3, arg + 3,
                 {"damping", "zero", "balance"});
  for (int i = 0; i < args.size(); i += 2) {
    const std::string kw = args[i];
    if (kw == "damping") {
      alpha_ = args.number(i, "the local damping coefficient, 0 <= alpha < 1");
      args.require(fabric::valid_local_damping(alpha_), i,
                   "must lie in 0 <= alpha < 1 (0: no damping; PFC's "
                   "default 0.7; 1 would cancel every force along the motion)");
    } else if (kw == "zero") {
      zero_every_ = zero_interval(args, i);
    } else if (kw == "balance") {
      fabric_id_ = args.value(i, "the ID of a compute primary/fabric, whose "
                                 "loaded contacts and mean normal force the "
                                 "unbalanced-force ratio uses");
    } else {
      args.unknown_keyword(i);
    }
  }
  if (!atom->sphere_flag)
    error->all(FLERR, "Fix quasi/static: needs atom_style granular (spheres "
                      "with radius, mass, omega and torque)");
  scalar_flag = 1;
  vector_flag = 1;
  size_vector = 4;
  global_freq = 1;
  extscalar = 0;
  extvector = 0;
}

int FixQuasiStatic::setmask() { return PRE_FINAL_INTEGRATE | END_OF_STEP; }

// fix_modify ID zero N: the kinetic damping's interval changed between runs
// (the scene's hold zeroes where its loading did not).
int FixQuasiStatic::modify_param(int narg, char **arg) {
  if (narg < 1 || strcmp(arg[0], "zero") != 0) return 0;
  StyleArgs args(error, "Fix_modify quasi/static", narg < 2 ? narg : 2, arg,
                 {"zero"});
  zero_every_ = zero_interval(args, 0);
  return 2;
}

void FixQuasiStatic::init() {
  fabric_ = nullptr;
  if (fabric_id_.empty()) return;
  const int c = modify->find_compute(fabric_id_.c_str());
  if (c < 0)
    error->all(FLERR, ("Fix quasi/static: balance compute ID '" + fabric_id_ +
                       "' does not exist")
                          .c_str());
  fabric_ = modify->compute[c];
  if (strcmp(fabric_->style, "primary/fabric") != 0)
    error->all(FLERR, ("Fix quasi/static: balance compute '" + fabric_id_ +
                       "' is a compute " + fabric_->style +
                       ", not a compute primary/fabric")
                          .c_str());
}

void FixQuasiStatic::setup(int) {
  // the forces of the setup step, before any damping, count for a ratio
  // asked for at this step
  pre_final_integrate();
}

void FixQuasiStatic::pre_final_integrate() {
  double **f = atom->f, **v = atom->v;
  double **torque = atom->torque, **omega = atom->omega;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  resultant_.assign(nlocal, 0.0);
  resultant_step_ = update->ntimestep;
  for (int i = 0; i < nlocal; ++i) {
    if (!(mask[i] & groupbit)) continue;
    resultant_[i] = std::sqrt(f[i][0] * f[i][0] + f[i][1] * f[i][1] +
                              f[i][2] * f[i][2]);
    if (alpha_ == 0.0) continue;
    fabric::damp_locally(f[i], v[i], alpha_);
    fabric::damp_locally(torque[i], omega[i], alpha_);
  }
}

// Kinetic damping (dynamic relaxation): every grain of the group starts the
// next step at rest. Between two zeroings the grains move under the
// unbalanced forces alone, so the packing creeps towards force balance
// without the kinetic energy that would carry it past.
void FixQuasiStatic::end_of_step() {
  if (zero_every_ == 0 || update->ntimestep % zero_every_ != 0) return;
  double **v = atom->v, **omega = atom->omega;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(mask[i] & groupbit)) continue;
    for (int k = 0; k < 3; ++k) v[i][k] = omega[i][k] = 0.0;
  }
}

void FixQuasiStatic::balance() {
  if (balanced_step_ == update->ntimestep) return;
  if (!fabric_)
    error->all(FLERR, "Fix quasi/static: the unbalanced-force ratio needs "
                      "the keyword balance with a compute primary/fabric");
  if (resultant_step_ != update->ntimestep)
    error->all(FLERR, "Fix quasi/static: the unbalanced-force ratio is asked "
                      "for at a step whose forces the fix has not seen (before "
                      "the first run, or between runs)");
  if (fabric_->invoked_peratom != update->ntimestep) fabric_->compute_peratom();
  if (fabric_->invoked_vector != update->ntimestep) fabric_->compute_vector();
  balanced_step_ = update->ntimestep;
  fabric::ForceBalance local;
  double **loaded = fabric_->array_atom;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(mask[i] & groupbit) || !(mask[i] & fabric_->groupbit)) continue;
    if (loaded[i][kLoadedContactsColumn] < 1.0) continue;
    local.resultant_sum += resultant_[i];
    local.grains += 1.0;
  }
  std::array<double, 4> sums = local.sums(), total{};
  MPI_Allreduce(sums.data(), total.data(), 4, MPI_DOUBLE, MPI_SUM, world);
  // the contacts: their count and mean normal force, as the compute has them
  const auto entry = [&](fabric::VectorEntry e) {
    return fabric_->vector[static_cast<int>(e)];
  };
  total[3] = entry(fabric::VectorEntry::contacts);
  total[2] = entry(fabric::VectorEntry::mean_normal_force) * total[3];
  const fabric::ForceBalance b = fabric::ForceBalance::from_sums(total);
  values_[0] = b.ratio();
  values_[1] = b.grains > 0 ? b.resultant_sum / b.grains : 0.0;
  values_[2] = b.contacts > 0 ? b.contact_sum / b.contacts : 0.0;
  values_[3] = b.grains;
}

double FixQuasiStatic::compute_scalar() {
  balance();
  return values_[0];
}

double FixQuasiStatic::compute_vector(int i) {
  balance();
  return values_[i];
}
