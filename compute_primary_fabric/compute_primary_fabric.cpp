/* compute primary/fabric: LIGGGHTS adapter of the fabric core.
   See compute_primary_fabric.h and docs/compute_primary_fabric.md. */

#include "compute_primary_fabric.h"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <numeric>
#include <set>
#include <utility>
#include <stdexcept>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fabric_outputs.h"
#include "fix.h"
#include "fix_contact_property_atom.h"
#include "fix_mesh_surface.h"
#include "fix_wall_gran.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "pair_gran.h"
#include "psd.h"
#include "style_args.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {
// The computes that warned about a non-finite state in this run (once each).
std::set<const ComputePrimaryFabric *> warned_nonfinite;

// Over all ranks: the sum of the counts and the largest of the examples.
std::pair<long long, double> count_and_example(long long count, double example,
                                               MPI_Comm world) {
  long long all = 0;
  MPI_Allreduce(&count, &all, 1, MPI_LONG_LONG, MPI_SUM, world);
  double max = 0.0;
  MPI_Allreduce(&example, &max, 1, MPI_DOUBLE, MPI_MAX, world);
  return {all, max};
}
}  // namespace

ComputePrimaryFabric::ComputePrimaryFabric(LAMMPS *lmp, int iarg, int narg,
                                           char **arg)
    : Compute(lmp, iarg, narg, arg),
      nintervals_(20),
      walls_given_(false),
      pair_(nullptr),
      intervals_ready_(false),
      analysed_step_(-1),
      threshold_force_(0.0),
      iterations_(0),
      nmax_(0),
      peratom_(nullptr),
      loose_(nullptr) {
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "Compute primary/fabric requires atom_style granular "
                      "(sphere: radius, rmass)");
  parse(narg - iarg, arg + iarg);
  try {
    fabric::validate(options_);
  } catch (const std::exception &e) {
    error->all(FLERR, e.what());
  }
  // The pair style must exist now: it creates its contact-force storage in
  // its own init, which runs before ours.
  pair_ = dynamic_cast<PairGran *>(force->pair_match("gran", 0));
  if (!pair_)
    error->all(FLERR, "Compute primary/fabric needs a granular pair style "
                      "(pair_style gran ...) defined before it");
  // Contact forces cost on every step they are stored (docs: Cost); with
  // store_every N only on multiples of N. Two computes asking for
  // different periods get their greatest common divisor.
  long every = store_every_;
  if (pair_->storeContactForces())
    every = std::gcd(every, static_cast<long>(pair_->storeContactForcesEvery()));
  pair_->do_store_contact_forces_every(static_cast<int>(every));

  peratom_flag = 1;
  size_peratom_cols = fabric::kPeratomColumns;
  vector_flag = 1;
  size_vector = fabric::vector_size(options_.direction_bins, nslices_);
  extvector = 0;
  array_flag = 1;
  size_array_rows = nintervals_;
  size_array_cols = fabric::kArrayColumns;
  extarray = 0;
  comm_forward = 1;
  vector = new double[size_vector]();
  memory->create(array, size_array_rows, size_array_cols, "primary/fabric:array");
  for (int r = 0; r < size_array_rows; ++r)
    for (int c = 0; c < size_array_cols; ++c) array[r][c] = 0.0;
}

ComputePrimaryFabric::~ComputePrimaryFabric() {
  warned_nonfinite.erase(this);
  delete[] vector;
  memory->destroy(array);
  memory->destroy(peratom_);
  memory->destroy(loose_);
}

void ComputePrimaryFabric::parse(int narg, char **arg) {
  // arg points at the first keyword (LIGGGHTS passes iarg past the style).
  const StyleArgs args(error, "Compute primary/fabric", narg, arg,
                       {"min_contacts", "force_threshold", "prune",
                        "intervals", "intervals_from", "psd", "walls",
                        "direction_bins", "walls_in_fabric", "max_iterations",
                        "oz_tolerance", "store_every", "weight", "slices"});
  for (int i = 0; i < narg;) i = read_keyword(args, i);
  if (!psd_file_.empty()) read_psd(args);
}

// Reads the keyword at arg[i] and its values; returns the index after them.
int ComputePrimaryFabric::read_keyword(const StyleArgs &args, int i) {
  const std::string kw = args[i];
  if (kw == "min_contacts") {
    options_.min_contacts = static_cast<int>(args.integer_in(i, 1, LONG_MAX));
  } else if (kw == "force_threshold") {
    return read_threshold(args, i);
  } else if (kw == "prune") {
    options_.pruning = args.choice(i, {"once", "iterate"}) == 0
                           ? fabric::Pruning::once
                           : fabric::Pruning::iterate;
  } else if (kw == "intervals") {
    nintervals_ = static_cast<int>(args.integer_in(i, 1, 100));
  } else if (kw == "intervals_from") {
    intervals_from_ = args.value(i, "the ID of a fix that stores each atom's "
                                    "interval index (fix sequential/pack)");
  } else if (kw == "psd") {
    psd_file_ = args.value(i, "a PSD file");
  } else if (kw == "walls") {
    walls_given_ = true;
    while (++i < args.size() && !args.is_keyword(args[i]))
      wall_ids_.push_back(args[i]);
    if (wall_ids_.empty()) args.fail("keyword 'walls' needs at least one fix ID");
    return i;
  } else if (kw == "direction_bins") {
    options_.direction_bins = static_cast<int>(args.integer_in(i, 1, 90));
  } else if (kw == "walls_in_fabric") {
    options_.walls_in_fabric = args.yes_no(i);
  } else if (kw == "oz_tolerance") {
    options_.oz_tolerance = args.number(i, "a share in [0, 1)");
    args.require(options_.oz_tolerance >= 0.0 && options_.oz_tolerance < 1.0,
                 i, "must lie in [0, 1)");
  } else if (kw == "weight") {
    weigh_volume_ = args.choice(i, {"mass", "volume"}) == 1;
  } else if (kw == "slices") {
    nslices_ = static_cast<int>(args.integer_in(i, 1, 1000));
  } else if (kw == "store_every") {
    store_every_ = args.integer_in(i, 1, 1000000000);
  } else if (kw == "max_iterations") {
    options_.max_iterations = static_cast<int>(args.integer_in(i, 1, LONG_MAX));
  } else {
    args.unknown_keyword(i);
  }
  return i + 2;
}

// force_threshold absolute F | relative f
int ComputePrimaryFabric::read_threshold(const StyleArgs &args, int i) {
  const std::string mode = args.value(i, "absolute F or relative f");
  if (mode != "absolute" && mode != "relative")
    args.fail("force_threshold mode '" + mode +
              "' is unknown: use absolute or relative");
  if (i + 2 >= args.size())
    args.fail("force_threshold " + std::string(args[i + 1]) + " needs a value");
  const double v = args.number_of(args[i + 2], "force_threshold");
  if (v < 0.0)
    args.fail("force_threshold " + std::string(args[i + 1]) + " " +
              args[i + 2] + " must not be negative");
  options_.threshold = mode == "absolute" ? fabric::LoadThreshold::absolute(v)
                                          : fabric::LoadThreshold::relative(v);
  return i + 3;
}

// The size intervals from a PSD: its equal-mass intervals' bounds and
// representative diameters.
void ComputePrimaryFabric::read_psd(const StyleArgs &args) {
  try {
    auto psd = fabric::ParticleSizeDistribution::read(psd_file_);
    for (const auto &iv : psd.equal_mass_intervals(nintervals_)) {
      class_diameter_.push_back(iv.d_mean);
      class_lower_.push_back(iv.d_lower);
      class_upper_.push_back(iv.d_upper);
    }
  } catch (const std::exception &e) {
    args.fail(e.what());
  }
  intervals_ready_ = true;
}

void ComputePrimaryFabric::init() {
  if (force->pair != pair_ && force->pair_match("gran", 0) != pair_)
    error->all(FLERR, "Compute primary/fabric: the granular pair style was "
                      "replaced after the compute was defined; define the "
                      "compute again");
  if (force->newton_pair)
    error->all(FLERR, "Compute primary/fabric requires 'newton off' (each "
                      "rank must see both ends of its atoms' contacts)");
  if (!atom->map_style)
    error->all(FLERR, "Compute primary/fabric requires 'atom_modify map "
                      "array' (or hash) to find contact partners by ID");
  if (store_every_ % pair_->storeContactForcesEvery() != 0) {
    char m[256];
    snprintf(m, sizeof m,
             "Compute primary/fabric: the pair style stores contact forces "
             "every %d steps (set by another command), which does not divide "
             "store_every %ld",
             pair_->storeContactForcesEvery(), store_every_);
    error->all(FLERR, m);
  }
  find_walls();
  interval_fix_ = nullptr;
  if (!intervals_from_.empty()) {
    int f = modify->find_fix(const_cast<char *>(intervals_from_.c_str()));
    if (f < 0)
      error->all(FLERR, ("Compute primary/fabric: intervals_from fix ID '" +
                         intervals_from_ + "' does not exist").c_str());
    Fix *fix = modify->fix[f];
    if (!fix->peratom_flag || fix->size_peratom_cols != 0)
      error->all(FLERR, ("Compute primary/fabric: intervals_from fix '" +
                         intervals_from_ + "' (style " + fix->style +
                         ") stores no per-atom vector of interval indices; "
                         "use the ID of a fix sequential/pack").c_str());
    interval_fix_ = fix;
  }
  analysed_step_ = -1;  // a new run: atoms may have moved on this same step
  warned_ = false;
  warned_nonfinite.erase(this);
}

void ComputePrimaryFabric::find_walls() {
  wall_contacts_.clear();
  for (const std::string &id : wall_ids_) {
    int i = modify->find_fix(const_cast<char *>(id.c_str()));
    if (i < 0)
      error->all(FLERR, ("Compute primary/fabric: wall fix ID '" + id +
                         "' does not exist").c_str());
    if (strncmp(modify->fix[i]->style, "wall/gran", 9) != 0)
      error->all(FLERR, ("Compute primary/fabric: fix '" + id + "' is style " +
                         modify->fix[i]->style +
                         ", not a granular wall (wall/gran)").c_str());
  }
  for (int i = 0; i < modify->nfix; ++i) {
    Fix *f = modify->fix[i];
    if (strncmp(f->style, "wall/gran", 9) != 0) continue;
    if (walls_given_ && std::find(wall_ids_.begin(), wall_ids_.end(),
                                  std::string(f->id)) == wall_ids_.end())
      continue;
    FixWallGran *w = static_cast<FixWallGran *>(f);
    // The stress storage keeps, per contact, the force on the particle and
    // the contact vector from the wall to the particle: the true normal.
    if (!w->store_force_contact_stress())
      error->all(FLERR, ("Compute primary/fabric: wall fix '" +
                         std::string(f->id) + "' does not store its contacts "
                         "with their normals: add 'store_force_contact_stress "
                         "yes' to it (or leave it out with the compute's "
                         "'walls' keyword)").c_str());
    if (w->is_mesh_wall()) {
      for (int m = 0; m < w->n_meshes(); ++m) {
        FixContactPropertyAtom *c = w->mesh_list()[m]->meshforceContactStress();
        if (c) wall_contacts_.push_back(c);
      }
    } else {
      std::string cid = std::string("contactforces_stress_") + f->id;
      Fix *c = modify->find_fix_id(const_cast<char *>(cid.c_str()));
      if (c) wall_contacts_.push_back(static_cast<FixContactPropertyAtom *>(c));
    }
  }
}

// Without a PSD the size intervals are the specimen's distinct diameters
// (fix sequential/pack gives one diameter per interval).
void ComputePrimaryFabric::assign_intervals() {
  std::vector<double> mine;
  for (int i = 0; i < atom->nlocal; ++i)
    if (atom->mask[i] & groupbit) mine.push_back(2.0 * atom->radius[i]);
  std::vector<double> uniq = fabric::IntervalAssignment::distinct(mine);
  if (uniq.size() > 1000) uniq.resize(1001);  // more than any interval count
  int n = static_cast<int>(uniq.size());
  std::vector<int> counts(comm->nprocs), displs(comm->nprocs);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  int total = 0;
  for (int p = 0; p < comm->nprocs; ++p) displs[p] = total, total += counts[p];
  if (total == 0) return;  // no particles yet
  std::vector<double> all(total);
  MPI_Allgatherv(uniq.data(), n, MPI_DOUBLE, all.data(), counts.data(),
                 displs.data(), MPI_DOUBLE, world);
  class_diameter_ = fabric::IntervalAssignment::distinct(all);
  if ((int)class_diameter_.size() != nintervals_) {
    char m[512];
    snprintf(m, sizeof m,
             "Compute primary/fabric: the group has %s%d distinct particle "
             "diameters but intervals %d: use intervals %d, or 'psd FILE "
             "intervals N' to class a continuous size distribution",
             class_diameter_.size() > 1000 ? "more than " : "",
             std::min<int>(class_diameter_.size(), 1000), nintervals_,
             std::min<int>(class_diameter_.size(), 100));
    if (class_diameter_.size() > 100)
      snprintf(m, sizeof m,
               "Compute primary/fabric: the group has %s%d distinct particle "
               "diameters, more than 100 intervals can hold: use 'psd FILE "
               "intervals N' to class a continuous size distribution",
               class_diameter_.size() > 1000 ? "more than " : "",
               std::min<int>(class_diameter_.size(), 1000));
    error->all(FLERR, m);
  }
  intervals_ready_ = true;
}

// The size intervals of this evaluation and their representative diameters
// (empty: the measured mean diameter of each interval's particles).
fabric::IntervalAssignment ComputePrimaryFabric::interval_assignment(
    std::vector<double> &representative) {
  representative.clear();
  if (!psd_file_.empty()) {  // a PSD: its intervals' bounds and mean diameters
    representative = class_diameter_;
    return fabric::IntervalAssignment::from_bounds(class_lower_, class_upper_);
  }
  if (interval_fix_) {
    // The fix's own particles say which diameters each interval holds: the
    // fallback for particles without an index takes the interval whose
    // range contains their diameter.
    const double *stored = interval_fix_->vector_atom;
    std::vector<double> lo(nintervals_, INFINITY), hi(nintervals_, -INFINITY);
    for (int i = 0; i < atom->nlocal; ++i) {
      if (!(atom->mask[i] & groupbit) || !stored) continue;
      const double k = stored[i];
      if (k >= 1 && k <= nintervals_ && k == std::floor(k)) {
        const double d = 2.0 * atom->radius[i];
        lo[int(k) - 1] = std::min(lo[int(k) - 1], d);
        hi[int(k) - 1] = std::max(hi[int(k) - 1], d);
      }
    }
    std::vector<double> glo(nintervals_), ghi(nintervals_);
    MPI_Allreduce(lo.data(), glo.data(), nintervals_, MPI_DOUBLE, MPI_MIN,
                  world);
    MPI_Allreduce(hi.data(), ghi.data(), nintervals_, MPI_DOUBLE, MPI_MAX,
                  world);
    return fabric::IntervalAssignment::from_ranges(glo, ghi);
  }
  if (!intervals_ready_) assign_intervals();
  representative = class_diameter_;
  return fabric::IntervalAssignment::from_ranges(class_diameter_,
                                                 class_diameter_);
}

void ComputePrimaryFabric::analyse() {
  if (analysed_step_ == update->ntimestep) return;
  analysed_step_ = update->ntimestep;
  check_stored_step();
  grow_peratom();
  Step step;
  collect_particles(step);
  warn_nonfinite();
  collect_contacts(step);
  try {
    classify(step);
  } catch (const std::exception &e) {
    error->one(FLERR, e.what());
  }
}

void ComputePrimaryFabric::check_stored_step() {
  const int every = pair_->storeContactForcesEvery();
  if (every <= 1 || update->ntimestep % every == 0) return;
  char m[512];
  snprintf(m, sizeof m,
           "Compute primary/fabric: evaluated at step " BIGINT_FORMAT
           ", but the pair style stores contact forces only on multiples "
           "of %d (store_every): evaluate it on those steps (thermo, dump "
           "and fix ave/time every %d, runs of multiples of %d) or use "
           "store_every 1",
           update->ntimestep, every, every, every);
  error->all(FLERR, m);
}

void ComputePrimaryFabric::grow_peratom() {
  if (atom->nmax <= nmax_) return;
  memory->destroy(peratom_);
  memory->destroy(loose_);
  nmax_ = atom->nmax;
  memory->create(peratom_, nmax_, 3, "primary/fabric:peratom");
  memory->create(loose_, nmax_, "primary/fabric:loose");
  array_atom = peratom_;
}

// The particles of this rank's group and their size intervals.
void ComputePrimaryFabric::collect_particles(Step &step) {
  const int nlocal = atom->nlocal;
  const fabric::IntervalAssignment intervals =
      interval_assignment(step.representative);
  const bool any_atoms = intervals.intervals() > 0;
  const double *stored = interval_fix_ ? interval_fix_->vector_atom : nullptr;
  step.index.assign(nlocal, -1);
  long long outside = 0, bad_index = 0;
  double outside_d = 0.0, bad_value = 0.0;
  for (int i = 0; i < nlocal; ++i) {
    for (int c = 0; c < fabric::kPeratomColumns; ++c) peratom_[i][c] = 0.0;
    if (!(atom->mask[i] & groupbit)) continue;
    const double d = 2.0 * atom->radius[i];
    int k = 0;
    try {
      k = any_atoms ? intervals.of(stored ? stored[i] : 0.0, d) : 0;
    } catch (const std::exception &) {
      ++bad_index;
      bad_value = stored[i];
      continue;
    }
    if (k < 0) {
      ++outside;
      outside_d = d;
      continue;
    }
    step.index[i] = static_cast<int>(step.particles.size());
    step.particles.push_back({static_cast<long long>(atom->tag[i]),
                              atom->radius[i], weight(i), k});
    step.z.push_back(atom->x[i][2]);
  }
  stop_on_bad_index(bad_index, bad_value);
  stop_on_outside(outside, outside_d);
}

// What a grain weighs in the "by mass" outputs: its mass, or with weight
// volume its volume (grains of one material whose masses were scaled to
// lengthen the time step: their real masses go as the volume).
double ComputePrimaryFabric::weight(int i) const {
  if (!weigh_volume_) return atom->rmass[i];
  const double r = atom->radius[i];
  return 4.0 / 3.0 * M_PI * r * r * r;
}

void ComputePrimaryFabric::stop_on_bad_index(long long count, double value) {
  const auto [all, v] = count_and_example(count, value, world);
  if (all == 0) return;
  char m[512];
  snprintf(m, sizeof m,
           "Compute primary/fabric: %lld particles (e.g. index %g) carry an "
           "interval index of fix '%s' that is not an integer in 0..%d: "
           "give the compute the fix's number of intervals (intervals N)",
           all, v, intervals_from_.c_str(), nintervals_);
  error->all(FLERR, m);
}

void ComputePrimaryFabric::stop_on_outside(long long count, double diameter) {
  const auto [all, d] = count_and_example(count, diameter, world);
  if (all == 0) return;
  const std::string of =
      !psd_file_.empty() ? psd_file_
      : interval_fix_    ? "the particles of fix " + intervals_from_ +
                            " (intervals_from)"
                         : "the specimen's sizes";
  char m[512];
  snprintf(m, sizeof m,
           "Compute primary/fabric: %lld particles (e.g. diameter %g) fit no "
           "size interval of %s: the PSD or intervals setting does not "
           "match the specimen",
           all, d, of.c_str());
  error->all(FLERR, m);
}

// A state with NaN or inf positions or forces (e.g. coincident particles)
// classifies as loose everywhere: say so instead of a silent "all loose".
void ComputePrimaryFabric::warn_nonfinite() {
  long long nonfinite = 0;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & groupbit)) continue;
    bool ok = true;
    for (int a = 0; a < 3; ++a)
      ok = ok && std::isfinite(atom->x[i][a]) && std::isfinite(atom->f[i][a]);
    nonfinite += !ok;
  }
  long long all = 0;
  MPI_Allreduce(&nonfinite, &all, 1, MPI_LONG_LONG, MPI_SUM, world);
  if (all == 0 || warned_nonfinite.count(this)) return;
  warned_nonfinite.insert(this);
  if (comm->me != 0) return;
  char m[512];
  snprintf(m, sizeof m,
           "Compute primary/fabric: %lld particles of the group have "
           "non-finite (NaN or inf) positions or forces at step " BIGINT_FORMAT
           " (coincident particles, e.g. a specimen inserted twice?); "
           "the classification of this state is meaningless",
           all, update->ntimestep);
  error->warning(FLERR, m);
}

// Each owned particle's contact ends: both ends of every contact live on
// the ranks that own them (newton off), so each end is passed as a half.
// One definition of the normal force for particles and walls alike
// (fabric::normal_force): the force on the particle projected onto the
// contact normal from the partner to the particle.
void ComputePrimaryFabric::collect_contacts(Step &step) {
  FixContactPropertyAtom *cf = pair_->fix_contact_forces();
  if (!cf)
    error->all(FLERR, "Compute primary/fabric: the pair style stores no "
                      "contact forces (is the compute defined after the "
                      "pair style?)");
  double **x = atom->x;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (step.index[i] < 0) continue;
    for (int k = 0; k < cf->n_partner(i); ++k) {
      int j = atom->map(cf->partner(i, k));
      if (j < 0) continue;  // not within reach: no longer in contact
      j = domain->closest_image(i, j);  // the image across a periodic side
      const double *F = cf->contacthistory(i, k);
      const Eigen::Vector3d j_to_i(x[i][0] - x[j][0], x[i][1] - x[j][1],
                                   x[i][2] - x[j][2]);
      if (!(j_to_i.norm() > 0.0)) continue;
      step.contacts.push_back(fabric::particle_contact(
          step.index[i], -1, Eigen::Vector3d(F[0], F[1], F[2]), j_to_i,
          false));
      step.partner.push_back(j);
    }
    // The wall's stress storage: fx fy fz, then the contact vector from the
    // wall's contact point to the particle's centre (deltax..deltaz), whose
    // length is the radius less the overlap. A particle that exactly touches
    // the wall (zero overlap, zero force) is stored too; it is no contact, as
    // for two particles (fabric::overlaps).
    for (FixContactPropertyAtom *w : wall_contacts_)
      for (int k = 0; k < w->n_partner(i); ++k) {
        const double *F = w->contacthistory(i, k);
        const Eigen::Vector3d wall_to_i(F[3], F[4], F[5]);
        if (!fabric::overlaps(wall_to_i.norm(), atom->radius[i])) continue;
        step.walls.push_back(fabric::wall_contact(
            step.index[i], Eigen::Vector3d(F[0], F[1], F[2]), wall_to_i));
      }
  }
}

// The threshold force, the classification (the core's prune loop; the
// partners' classes cross the ranks by forward communication, each pass's
// count by a reduction), the sums and the per-atom values.
void ComputePrimaryFabric::classify(const Step &step) {
  auto local = fabric::normal_force_sums(step.contacts, step.walls);
  fabric::NormalForceSums global;
  MPI_Allreduce(local.values.data(), global.values.data(), 2, MPI_DOUBLE,
                MPI_SUM, world);
  threshold_force_ = options_.threshold.force(global.mean());

  fabric::PartnerExchange exchange;
  exchange.partners_loose = [&](const std::vector<fabric::Fraction> &f,
                                std::vector<char> &partner_loose) {
    for (int i = 0; i < atom->nlocal + atom->nghost; ++i) loose_[i] = 0.0;
    for (int i = 0; i < atom->nlocal; ++i)
      if (step.index[i] >= 0 && f[step.index[i]] == fabric::Fraction::loose)
        loose_[i] = 1.0;
    comm->forward_comm_compute(this);
    for (size_t c = 0; c < step.partner.size(); ++c)
      partner_loose[c] = loose_[step.partner[c]] != 0.0;
  };
  exchange.global_sum = [&](long long n) {
    long long all = 0;
    MPI_Allreduce(&n, &all, 1, MPI_LONG_LONG, MPI_SUM, world);
    return all;
  };
  const fabric::Classification cls = fabric::classify(
      static_cast<int>(step.particles.size()), step.contacts, step.walls,
      threshold_force_, options_, &exchange);
  iterations_ = cls.iterations;
  if (!cls.converged) {
    if (comm->me == 0 && !warned_)
      error->warning(FLERR, "Compute primary/fabric: prune iterate did "
                            "not converge within max_iterations");
    warned_ = true;
  }

  fabric::FabricSums sums =
      fabric::accumulate(step.particles, step.contacts, step.walls, cls,
                         threshold_force_, nintervals_, options_);
  fabric::FabricSums total(nintervals_, options_.direction_bins);
  MPI_Allreduce(sums.data(), total.data(), sums.size(), MPI_DOUBLE, MPI_SUM,
                world);
  summary_ = fabric::finalise(total, step.representative, options_.oz_tolerance);
  if (nslices_ > 0) slice(step, cls);

  for (int i = 0; i < atom->nlocal; ++i) {
    if (step.index[i] < 0) continue;
    const int p = step.index[i];
    using fabric::PeratomColumn;
    double *row = peratom_[i];
    row[fabric::peratom_column(PeratomColumn::loaded_contacts)] = cls.loaded_contacts[p];
    row[fabric::peratom_column(PeratomColumn::primary)] =
        cls.fraction[p] == fabric::Fraction::primary ? 1.0 : 0.0;
    row[fabric::peratom_column(PeratomColumn::interval)] = step.particles[p].interval + 1;
  }
}

// The figures of each height slice (keyword slices): the grains' extent
// along z over all ranks, then each rank's sums of its grains, reduced.
void ComputePrimaryFabric::slice(const Step &step,
                                 const fabric::Classification &cls) {
  const fabric::HeightExtent mine = fabric::height_extent(step.particles, step.z);
  fabric::HeightExtent all{};
  MPI_Allreduce(&mine.bottom, &all.bottom, 1, MPI_DOUBLE, MPI_MIN, world);
  MPI_Allreduce(&mine.top, &all.top, 1, MPI_DOUBLE, MPI_MAX, world);
  const fabric::HeightSlices slices(all, nslices_);
  fabric::SliceSums sums = fabric::accumulate_slices(
      step.particles, step.z, step.contacts, step.walls, cls, threshold_force_,
      slices, options_);
  fabric::SliceSums total(nslices_);
  MPI_Allreduce(sums.data(), total.data(), sums.size(), MPI_DOUBLE, MPI_SUM,
                world);
  slices_ = fabric::finalise_slices(total, slices);
}

void ComputePrimaryFabric::compute_peratom() {
  invoked_peratom = update->ntimestep;
  analyse();
}

void ComputePrimaryFabric::compute_vector() {
  invoked_vector = update->ntimestep;
  analyse();
  // Layout: fabric_outputs.h.
  const std::vector<double> v = fabric::global_vector(
      summary_, threshold_force_, iterations_, options_.direction_bins,
      slices_);
  std::copy(v.begin(), v.end(), vector);
}

void ComputePrimaryFabric::compute_array() {
  invoked_array = update->ntimestep;
  analyse();
  // Layout: fabric_outputs.h.
  for (int k = 0; k < nintervals_; ++k) {
    fabric::IntervalSummary r;
    if (k < (int)summary_.intervals.size()) r = summary_.intervals[k];
    const auto row = fabric::interval_row(r);
    std::copy(row.begin(), row.end(), array[k]);
  }
}

int ComputePrimaryFabric::pack_comm(int n, int *list, double *buf, int, int *) {
  for (int i = 0; i < n; ++i) buf[i] = loose_[list[i]];
  return 1;  // values per atom: this Comm multiplies by the atom count
}

void ComputePrimaryFabric::unpack_comm(int n, int first, double *buf) {
  for (int i = 0; i < n; ++i) loose_[first + i] = buf[i];
}

double ComputePrimaryFabric::memory_usage() {
  return static_cast<double>(nmax_) * 4 * sizeof(double);
}
