/* fix sequential/pack: LIGGGHTS adapter of the sequential packer.
   See fix_sequential_pack.h and docs/fix_sequential_pack.md. */

#include "fix_sequential_pack.h"

#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <set>
#include <sstream>
#include <stdexcept>

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "memory.h"
#include "min_contacts.h"
#include "modify.h"
#include "neighbor.h"
#include "neighbour_count.h"
#include "pack_outputs.h"
#include "region.h"
#include "style_args.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

// What one particle costs: the packer's data on every rank (measured by
// bench/pack_bench: 150-350 B per sphere of the full packing, which holds
// up to 1.6 times the list) plus a LIGGGHTS granular atom with its
// neighbour and contact-history data on its owning rank (a generous 2 kB).
constexpr double kPackerBytes = 400.0, kAtomBytes = 2048.0;

// The fix LIGGGHTS deleted last (pre_delete), read by the constructor of a
// fix that replaces it under the same ID.
struct Deleted {
  const LAMMPS *lmp = nullptr;
  std::string id;
  bool inserted = false;
};
Deleted last_deleted;

std::string fmt(const char *f, double v) {
  char b[64];
  snprintf(b, sizeof b, f, v);
  return b;
}

}  // namespace

FixSequentialPack::FixSequentialPack(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg),
      psd_(nullptr),
      arrangement_(fabric::Arrangement::discrete),
      porosity_(-1.0),
      density_(2650.0),
      nintervals_(20),
      atom_type_(1),
      seed_(0),
      fill_pores_(true),
      verbose_(true),
      start_(fabric::Start::floor),
      layering_(fabric::PackingSpec().layering),
      vector_(fabric::kPackVectorEntries, 0.0),
      inserted_(0),
      interval_(nullptr),
      nmax_(0) {
  // A fix defined again with an existing ID replaces the old one: LIGGGHTS
  // (Modify::add_fix) calls the old one's pre_delete(), deletes it and leaves
  // its slot NULL while the new one is constructed (Atom::add_callback finds
  // the new fix by that slot). The old fix's state goes with it, so after
  // the packing the new one would pack a second specimen on top of the
  // first: coincident grains, NaN forces. Before it, a new definition simply
  // replaces the settings.
  bool replacing = false;
  for (int i = 0; i < modify->nfix; ++i) replacing |= modify->fix[i] == nullptr;
  const bool packed = replacing && last_deleted.lmp == lmp &&
                      last_deleted.id == id && last_deleted.inserted;
  last_deleted = Deleted();
  if (packed)
    error->all(FLERR, ("Fix sequential/pack: fix ID '" + std::string(id) +
                       "' is defined again after it inserted its specimen; "
                       "the new definition would replace it and pack a "
                       "second specimen on top of the first. Define the fix "
                       "once (it packs once; after read_restart its "
                       "definition restores it), or give another container "
                       "another fix ID").c_str());
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag)
    error->all(FLERR, "Fix sequential/pack requires atom_style granular "
                      "(sphere: radius, rmass, omega)");
  parse(narg, arg);

  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;  // atoms created by other commands get index 0
  peratom_flag = 1;
  size_peratom_cols = 0;
  peratom_freq = 1;
  vector_flag = 1;
  size_vector = fabric::kPackVectorEntries;  // pack_outputs.h
  global_freq = 1;
  extvector = 0;
  grow_arrays(atom->nmax);
  atom->add_callback(0);
  atom->add_callback(1);
}

FixSequentialPack::~FixSequentialPack() {
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
  memory->destroy(interval_);
  delete psd_;
}

void FixSequentialPack::parse(int narg, char **arg) {
  // arg[3..]: the keywords (arg[0..2]: ID, group, style)
  const StyleArgs args(error, "Fix sequential/pack", narg - 3, arg + 3,
                       {"psd", "porosity", "arrangement", "region", "seed",
                        "intervals", "density", "type", "fill_pores", "start",
                        "layering", "verbose"});
  read_keywords(args);
  read_container(args);
  read_psd(args);
  check_memory(args);
  warn_empty_intervals();
}

void FixSequentialPack::read_keywords(const StyleArgs &args) {
  static const fabric::Start starts[] = {
      fabric::Start::automatic, fabric::Start::floor_ceiling,
      fabric::Start::floor, fabric::Start::centre};
  std::set<std::string> given;
  for (int i = 0; i < args.size(); i += 2) {
    const std::string kw = args[i];
    given.insert(kw);
    if (kw == "psd") {
      psd_file_ = args.value(i, "a sieve-analysis file");
    } else if (kw == "porosity") {
      porosity_ = args.number(i, "a number in (0, 1)");
      args.require(porosity_ > 0.0 && porosity_ < 1.0, i,
                   "must lie strictly between 0 and 1");
    } else if (kw == "arrangement") {
      arrangement_ = args.choice(i, {"discrete", "layerwise"}) == 0
                         ? fabric::Arrangement::discrete
                         : fabric::Arrangement::layerwise;
    } else if (kw == "region") {
      region_id_ = args.value(i, "a region ID");
    } else if (kw == "seed") {
      seed_ = static_cast<int>(
          args.integer_in(i, 1, INT32_MAX, "a positive integer"));
    } else if (kw == "intervals") {
      nintervals_ = static_cast<int>(args.integer_in(i, 1, 100));
    } else if (kw == "density") {
      density_ = args.number(i, "a positive number");
      args.require(density_ > 0.0, i, "must be positive");
    } else if (kw == "type") {
      atom_type_ = static_cast<int>(
          args.integer_in(i, 1, atom->ntypes, "the box's atom types"));
    } else if (kw == "fill_pores") {
      fill_pores_ = args.yes_no(i);
    } else if (kw == "layering") {
      layering_ = args.number(i, "a positive number (share of the list's solid volume)");
      args.require(layering_ > 0.0, i,
                   "must be positive (width of the coarse-to-fine schedule, "
                   "as a share of the list's solid volume)");
    } else if (kw == "start") {
      start_ = starts[args.choice(i, {"auto", "floor_ceiling", "floor",
                                      "centre"})];
    } else if (kw == "verbose") {
      verbose_ = args.yes_no(i);
    } else {
      args.unknown_keyword(i);
    }
  }
  static const char *const required[][2] = {
      {"psd", "psd FILE"}, {"porosity", "porosity P"},
      {"arrangement", "arrangement discrete|layerwise"},
      {"region", "region ID"}, {"seed", "seed N"}};
  for (const auto &r : required)
    if (!given.count(r[0]))
      args.fail("keyword '" + std::string(r[1]) + "' is required");
  if (!given.count("start")) start_ = fabric::default_start(arrangement_);
}

void FixSequentialPack::read_container(const StyleArgs &args) {
  int iregion = domain->find_region(const_cast<char *>(region_id_.c_str()));
  if (iregion < 0) args.fail("region '" + region_id_ + "' does not exist");
  Region *reg = domain->regions[iregion];
  if (strcmp(reg->style, "block") != 0)
    args.fail("region '" + region_id_ + "' is style " + reg->style +
              "; the container must be a block region");
  if (!reg->interior)
    args.fail("region '" + region_id_ + "' must be 'side in'");
  lo_[0] = reg->extent_xlo, hi_[0] = reg->extent_xhi;
  lo_[1] = reg->extent_ylo, hi_[1] = reg->extent_yhi;
  lo_[2] = reg->extent_zlo, hi_[2] = reg->extent_zhi;
  for (int a = 0; a < 3; ++a)
    if (lo_[a] < domain->boxlo[a] - 1e-12 * domain->prd[a] ||
        hi_[a] > domain->boxhi[a] + 1e-12 * domain->prd[a])
      args.fail("region '" + region_id_ +
                "' extends outside the simulation box along " + "xyz"[a] +
                ": " + fmt("%g", lo_[a]) + ".." + fmt("%g", hi_[a]) +
                " vs box " + fmt("%g", domain->boxlo[a]) + ".." +
                fmt("%g", domain->boxhi[a]));
}

// The PSD, its intervals and the particle list of the container.
void FixSequentialPack::read_psd(const StyleArgs &args) {
  try {
    psd_ = new fabric::ParticleSizeDistribution(
        fabric::ParticleSizeDistribution::read(psd_file_));
    intervals_ = psd_->equal_mass_intervals(nintervals_);
  } catch (const std::exception &e) {
    args.fail(e.what());
  }
  double dmax = intervals_.back().d_mean;
  for (int a = 0; a < 3; ++a)
    if (hi_[a] - lo_[a] < dmax)
      args.fail("container '" + region_id_ + "' is " +
                fmt("%g", hi_[a] - lo_[a]) + " wide along " + "xyz"[a] +
                ", smaller than the largest particle (diameter " +
                fmt("%g", dmax) + " of the coarsest interval)");
  list_ = fabric::particle_list(intervals_, container().volume(), porosity_);
  // the packer starts from a face of three grains
  if (list_.total() < 3)
    args.fail("the container holds only " + std::to_string(list_.total()) +
              " particles of this PSD in " + std::to_string(nintervals_) +
              " intervals; at least 3 are needed: use a larger region, a "
              "lower porosity or fewer intervals");
}

void FixSequentialPack::check_memory(const StyleArgs &args) {
  double total = 0.0;
  for (double t : list_.target_count) total += t;
  long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  double memory = pages > 0 && page > 0 ? double(pages) * page : 64e9;
  double need = total * (kPackerBytes * comm->nprocs + kAtomBytes);
  if (total > INT32_MAX / 4 || need > 0.8 * memory)
    args.fail("the container holds about " + fmt("%.4g", total) +
              " particles at this porosity and PSD, needing about " +
              fmt("%.3g", need / 1073741824.0) + " GiB (" +
              fmt("%.0f", kPackerBytes) + " B per particle on each of the " +
              std::to_string(comm->nprocs) + " MPI rank(s) plus " +
              fmt("%.0f", kAtomBytes) + " B per atom), more than the " +
              fmt("%.3g", memory / 1073741824.0) + " GiB here (and at most " +
              std::to_string(INT32_MAX / 4) +
              " particles): use a smaller region or a coarser PSD");
}

// Intervals that round to no grain leave their mass share out of the
// specimen: say which, and how large a container keeps them all.
void FixSequentialPack::warn_empty_intervals() {
  std::string empty;
  int nempty = 0;
  double grow = 1.0;  // volume factor that gives every interval 1 grain
  for (size_t k = 0; k < list_.count.size(); ++k)
    if (list_.count[k] == 0) {
      ++nempty;
      if (nempty <= 3) empty += (empty.empty() ? "" : ", ") + std::to_string(k + 1);
      grow = std::max(grow, 0.5 / std::max(list_.target_count[k], 1e-300));
    }
  if (nempty == 0 || comm->me != 0) return;
  char w[512];
  snprintf(w, sizeof w,
           "Fix sequential/pack: %d of %d intervals hold no grain in this "
           "container (interval%s %s%s: target counts below 0.5 round to "
           "0), so %.0f %% of the PSD's mass is missing from the specimen. "
           "Use a container at least %.3g times the volume (edges %.3g "
           "times longer) or fewer intervals",
           nempty, nintervals_, nempty > 1 ? "s" : "", empty.c_str(),
           nempty > 3 ? ", ..." : "", 100.0 * nempty / nintervals_, grow,
           std::cbrt(grow));
  error->warning(FLERR, w);
}

fabric::Box FixSequentialPack::container() const {
  return {fabric::Vec3(lo_[0], lo_[1], lo_[2]),
          fabric::Vec3(hi_[0], hi_[1], hi_[2])};
}

int FixSequentialPack::setmask() { return PRE_EXCHANGE; }

void FixSequentialPack::pre_delete(bool) {
  last_deleted.lmp = lmp;
  last_deleted.id = id;
  last_deleted.inserted = inserted_ != 0;
}

double FixSequentialPack::max_rad(int type) {
  return type == atom_type_ ? 0.5 * intervals_.back().d_mean : 0.0;
}

double FixSequentialPack::min_rad(int type) {
  return type == atom_type_ ? 0.5 * intervals_.front().d_mean : 0.0;
}

void FixSequentialPack::message(const std::string &text) {
  if (comm->me != 0) return;
  if (screen) fprintf(screen, "%s\n", text.c_str());
  if (logfile) fprintf(logfile, "%s\n", text.c_str());
}

void FixSequentialPack::setup_pre_exchange() {
  if (inserted_) return;  // done before, or restored by read_restart
  insert_specimen();
  inserted_ = 1;
  // LIGGGHTS' first setup calls set_arrays() on every atom of a fix it
  // believes just created, which would wipe the indices set above.
  just_created = 0;
}

void FixSequentialPack::insert_specimen() {
  warn_atoms_inside();
  message("fix sequential/pack: packing the container full, then choosing " +
          std::to_string(list_.total()) + " particles (" +
          fabric::to_string(arrangement_) + ") from it");
  double t0 = MPI_Wtime();
  fabric::PackingResult res;
  try {
    res = fabric::pack(packing_spec());
  } catch (const std::exception &e) {
    error->all(FLERR, ("Fix sequential/pack: " + std::string(e.what())).c_str());
  }
  const double seconds = MPI_Wtime() - t0;
  create_atoms(res);
  const fabric::PackReport report =
      fabric::pack_report(res, list_, intervals_, container(), seconds);
  vector_ = fabric::vector_values(report.vector);
  if (comm->me == 0) {
    message(summary_text(report, res));
    for (const std::string &w : fabric::pack_warnings(report, res, list_,
                                                      porosity_, arrangement_))
      error->warning(FLERR, ("Fix sequential/pack: " + w).c_str());
  }
  check_neighbours(res);
}

fabric::PackingSpec FixSequentialPack::packing_spec() {
  fabric::PackingSpec spec =
      fabric::packing_spec(list_, container().lo, container().hi);
  spec.arrangement = arrangement_;
  spec.seed = static_cast<std::uint64_t>(seed_);
  spec.fill_pores = fill_pores_;
  spec.start = start_;
  spec.layering = layering_;
  if (verbose_)
    spec.progress = [this](long long packed, long long total) {
      char b[160];
      snprintf(b, sizeof b,
               "  sequential/pack: %lld grains packed (the list holds %lld)",
               packed, total);
      message(b);
    };
  return spec;
}

// Atoms already in the container (another packing, or this fix under a new
// ID after read_restart) are not seen by the packer.
void FixSequentialPack::warn_atoms_inside() {
  bigint inside_local = 0, inside = 0;
  for (int i = 0; i < atom->nlocal; ++i) {
    bool in = true;
    for (int a = 0; a < 3; ++a)
      in = in && atom->x[i][a] > lo_[a] && atom->x[i][a] < hi_[a];
    inside_local += in;
  }
  MPI_Allreduce(&inside_local, &inside, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (inside == 0 || comm->me != 0) return;
  char w[256];
  snprintf(w, sizeof w,
           "Fix sequential/pack: %lld atoms already lie in container '%s'; "
           "the packing does not see them and will overlap them",
           static_cast<long long>(inside), region_id_.c_str());
  error->warning(FLERR, w);
}

// Each rank creates the placed spheres inside its subdomain.
void FixSequentialPack::create_atoms(const fabric::PackingResult &res) {
  // Tags follow the placement order after the largest existing tag, so every
  // rank count gives each sphere the same ID.
  tagint maxtag_local = 0, maxtag = 0;
  for (int i = 0; i < atom->nlocal; ++i)
    maxtag_local = std::max(maxtag_local, atom->tag[i]);
  MPI_Allreduce(&maxtag_local, &maxtag, 1, MPI_LMP_TAGINT, MPI_MAX, world);

  for (int j = 0; j < modify->nfix; ++j)
    if (modify->fix[j]->create_attribute) modify->fix[j]->pre_set_arrays();
  bigint mine = 0;
  for (long long i = 0; i < res.placed(); ++i) {
    double x[3] = {res.centre[i][0], res.centre[i][1], res.centre[i][2]};
    if (!domain->is_in_subdomain(x)) continue;
    atom->avec->create_atom(atom_type_, x);
    int m = atom->nlocal - 1;
    atom->tag[m] = maxtag + static_cast<tagint>(i) + 1;
    atom->mask[m] = 1 | groupbit;
    atom->v[m][0] = atom->v[m][1] = atom->v[m][2] = 0.0;
    atom->omega[m][0] = atom->omega[m][1] = atom->omega[m][2] = 0.0;
    double r = res.radius[i];
    atom->radius[m] = r;
    atom->density[m] = density_;
    atom->rmass[m] = fabric::sphere_volume(2.0 * r) * density_;
    for (int j = 0; j < modify->nfix; ++j)
      if (modify->fix[j]->create_attribute) modify->fix[j]->set_arrays(m);
    interval_[m] = res.size_class[i] + 1;
    ++mine;
  }
  bigint all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (all != res.placed())
    error->all(FLERR, ("Fix sequential/pack: " + std::to_string(all) +
                       " of " + std::to_string(res.placed()) +
                       " particles landed in a subdomain; the container "
                       "must lie inside the simulation box").c_str());
  atom->natoms += all;
  if (atom->map_style) {
    atom->nghost = 0;
    atom->map_init();
    atom->map_set();
  }
}

void FixSequentialPack::check_neighbours(const fabric::PackingResult &res) {
  const int one = neighbor->oneatom;
  const double skin = neighbor->skin;
  const double cdf = std::max(1.0, neighbor->contactDistanceFactor);
  if (fabric::neighbours_surely_fit(res.radius, skin, cdf, one)) return;
  // Per grain also the skin that leaves the list a margin of 1.5 for
  // compaction with the present 'one'.
  const long long keep = std::max<long long>(1, static_cast<long long>(one / 1.5));
  const fabric::NeighbourCount count = fabric::count_neighbours(
      res, list_.diameter, container(), skin, cdf, keep);
  if (count.most <= one) return;
  // Suggest a list that holds 1.5 times the count (compaction, rounding),
  // rounded up to hundreds; the page must hold 10 lists (Neighbor::init).
  const long long need = (static_cast<long long>(1.5 * count.most) + 99) / 100 * 100;
  const long long page = std::max<long long>(neighbor->pgsize, 10 * need);
  const double skin_ok = count.skin_for_keep;
  std::string skin_hint;
  if (std::isfinite(skin_ok) && skin_ok > 0.0 && skin_ok < skin)
    skin_hint = ", or keep 'one " + std::to_string(one) +
                "' with a smaller skin: 'neighbor " +
                fmt("%.2g", 0.99 * skin_ok) + " bin' or less";
  char b[1024];
  snprintf(b, sizeof b,
           "Fix sequential/pack: a grain of diameter %g has %lld neighbours "
           "within its radius + theirs + the neighbor skin %g, more than "
           "LIGGGHTS' neighbour list holds per grain (neigh_modify one %d, "
           "page %d); the run would stop with 'Neighbor list overflow'. Add "
           "'neigh_modify one %lld page %lld' before the run%s",
           count.diameter, count.most, skin, one, neighbor->pgsize, need, page,
           skin_hint.c_str());
  error->all(FLERR, b);
}

// The summary on the screen and in the log: the settings, per interval
// what was asked and placed, then the figures of the specimen.
std::string FixSequentialPack::summary_text(const fabric::PackReport &report,
                                            const fabric::PackingResult &res) {
  std::ostringstream s;
  s.unsetf(std::ios::fixed);
  s.precision(5);
  std::string start = fabric::to_string(start_);
  if (start_ == fabric::Start::automatic)
    start += " (" + fabric::to_string(res.start) +
             (res.unplaced_with_two_fronts > 0
                  ? ": two fronts left " +
                        std::to_string(res.unplaced_with_two_fronts) +
                        " grains unplaced, one front less volume"
                  : std::string()) +
             ")";
  s << "fix sequential/pack summary\n"
    << "  PSD " << psd_file_ << ": " << psd_->points().size()
    << " points, d10 = " << psd_->d10() << ", d60 = " << psd_->d60()
    << ", Cu = " << psd_->uniformity_coefficient() << "\n"
    << "  container " << region_id_ << ": volume " << report.container_volume
    << ", arrangement " << fabric::to_string(arrangement_) << ", start "
    << start << ", seed " << seed_ << ", " << intervals_.size()
    << " equal-mass intervals\n"
    << "  interval   d_mean       target    count   placed  not_placed  "
       "mass%PSD  mass%placed\n";
  for (size_t k = 0; k < intervals_.size(); ++k) {
    char row[160];
    snprintf(row, sizeof row, "  %8zu %9.4g %12.2f %8lld %8lld %11lld %9.2f %12.2f\n",
             k + 1, intervals_[k].d_mean, list_.target_count[k],
             list_.count[k], res.placed_per_class[k], res.unplaced_per_class[k],
             100.0 * intervals_[k].mass_fraction,
             report.placed_mass_percent[k]);
    s << row;
  }
  return s.str() + summary_figures(report, res);
}

std::string FixSequentialPack::summary_figures(
    const fabric::PackReport &report, const fabric::PackingResult &res) {
  const fabric::PackVector &v = report.vector;
  auto signed_or = [](double x, const char *none) {
    return std::isfinite(x) ? fmt("%+.3f", x) : std::string(none);
  };
  char b[2048];
  snprintf(b, sizeof b,
           "  particles: %lld in the list, %lld placed (%lld of them into "
           "vacancies by the second loop), %lld not placed\n"
           "  the container packed full holds porosity %.4f; %lld vacancies "
           "(grain-sized holes) bring it to the target\n"
           "  porosity by volume: target %.4f, list %.4f (counts rounded), "
           "achieved %.4f over the container, %.4f in the interior, %.4f in "
           "the wall layer (%.4g, one coarsest diameter, per wall)\n"
           "  contacts before loading (grains and walls touching, no force): "
           "%.3f per grain; %.2f %% of the grains (%.2f %% of the mass) "
           "have fewer than %d\n"
           "  structure: size assortativity of touching pairs %s, in the "
           "interior %s (0: contact ends paired at random; a random packing "
           "of a graded soil lies below 0, its fines touching coarse grains, "
           "see bench/random_reference; above that: like sizes together), "
           "Spearman(radius, distance from the centre) %s\n"
           "  time: %.3f s (%.0f particles per second)\n",
           list_.total(), res.placed(), res.placed_in_second_loop,
           report.not_placed, report.packed_full_porosity, res.vacancies,
           porosity_, report.list_porosity, v.porosity, v.interior_porosity,
           v.wall_layer_porosity, report.wall_layer, v.contacts_per_grain,
           v.few_contacts_percent,
           report.placed_volume > 0 ? 100.0 - v.held_mass_percent : 0.0,
           fabric::kMinContacts,
           signed_or(v.size_assortativity, "none (no touching pairs)").c_str(),
           signed_or(v.interior_size_assortativity, "none").c_str(),
           signed_or(v.radius_distance_spearman, "none (undefined)").c_str(),
           v.seconds, v.seconds > 0 ? res.placed() / v.seconds : 0.0);
  return b + profile_figures(v);
}

std::string FixSequentialPack::profile_figures(const fabric::PackVector &v) {
  std::string p, d;
  for (int l = 0; l < fabric::kProfileLayers; ++l)
    p += fmt(" %.3f", v.profile.porosity[l]),
        d += fmt(" %.2f", v.profile.mean_diameter[l]);
  return "  by height (" + std::to_string(fabric::kProfileLayers) +
         " equal layers, floor first, by volume): porosity" + p +
         "; mass-weighted mean diameter / d_N" + d + "\n" +
         "  mean local Cu / Cu (27 sub-cubes): " +
         (std::isfinite(v.local_cu_ratio) ? fmt("%.3f", v.local_cu_ratio)
                                          : std::string("none")) +
         " (1: mixed; below 1: like sizes together)\n";
}

double FixSequentialPack::compute_vector(int i) { return vector_[i]; }

/* ---- per-atom interval index ---------------------------------------- */

void FixSequentialPack::grow_arrays(int nmax) {
  memory->grow(interval_, nmax, "sequential/pack:interval");
  for (int i = nmax_; i < nmax; ++i) interval_[i] = 0.0;
  nmax_ = nmax;
  vector_atom = interval_;
}

void FixSequentialPack::copy_arrays(int i, int j, int) {
  interval_[j] = interval_[i];
}

void FixSequentialPack::set_arrays(int i) { interval_[i] = 0.0; }

int FixSequentialPack::pack_exchange(int i, double *buf) {
  buf[0] = interval_[i];
  return 1;
}

int FixSequentialPack::unpack_exchange(int nlocal, double *buf) {
  interval_[nlocal] = buf[0];
  return 1;
}

int FixSequentialPack::pack_restart(int i, double *buf) {
  buf[0] = 2;
  buf[1] = interval_[i];
  return 2;
}

void FixSequentialPack::unpack_restart(int nlocal, int nth) {
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; ++i) m += static_cast<int>(extra[nlocal][m]);
  interval_[nlocal] = extra[nlocal][m + 1];
}

double FixSequentialPack::memory_usage() {
  return atom->nmax * sizeof(double);
}

// The restart holds the inserted flag and the settings the specimen was
// packed with, so a redefinition with other settings is told apart.
void FixSequentialPack::write_restart(FILE *fp) {
  double list[5] = {static_cast<double>(inserted_), porosity_,
                    arrangement_ == fabric::Arrangement::discrete ? 0.0 : 1.0,
                    static_cast<double>(seed_), static_cast<double>(nintervals_)};
  if (comm->me == 0) {
    int size = sizeof(list);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list, sizeof(double), 5, fp);
  }
}

void FixSequentialPack::restart(char *buf) {
  const double *list = reinterpret_cast<double *>(buf);
  inserted_ = static_cast<int>(list[0]);
  if (!inserted_ || comm->me != 0) return;
  fabric::Arrangement was = list[2] == 0.0 ? fabric::Arrangement::discrete
                                           : fabric::Arrangement::layerwise;
  if (list[1] != porosity_ || was != arrangement_ || list[3] != seed_ ||
      list[4] != nintervals_) {
    char w[512];
    snprintf(w, sizeof w,
             "Fix sequential/pack: the specimen restored from the restart "
             "file was packed with porosity %g, arrangement %s, seed %.0f, "
             "%.0f intervals; this definition says porosity %g, arrangement "
             "%s, seed %d, %d intervals. The restored specimen is kept (no "
             "new packing)",
             list[1], fabric::to_string(was).c_str(), list[3], list[4],
             porosity_, fabric::to_string(arrangement_).c_str(), seed_,
             nintervals_);
    error->warning(FLERR, w);
  }
}
