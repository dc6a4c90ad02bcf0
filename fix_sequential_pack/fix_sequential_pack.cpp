/* fix sequential/pack: LIGGGHTS adapter of the sequential packer.
   See fix_sequential_pack.h and docs/fix_sequential_pack.md. */

#include "fix_sequential_pack.h"

#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "region.h"
#include "specimen_measure.h"
#include "sphere_grid.h"

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
      summary_{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
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
  size_vector = 12;
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
  auto fail = [&](const std::string &m) {
    error->all(FLERR, ("Fix sequential/pack: " + m).c_str());
  };
  auto need_value = [&](int i, const char *kw, const char *what) {
    if (i + 1 >= narg)
      fail(std::string("keyword '") + kw + "' needs a value: " + what);
  };
  auto number = [&](const char *s, const char *kw) {
    char *end = nullptr;
    double v = strtod(s, &end);
    if (end == s || *end != '\0' || !std::isfinite(v))
      fail(std::string(kw) + " '" + s + "' is not a number");
    return v;
  };
  auto integer = [&](const char *s, const char *kw) {
    char *end = nullptr;
    long v = strtol(s, &end, 10);
    if (end == s || *end != '\0')
      fail(std::string(kw) + " '" + s + "' is not an integer");
    return v;
  };
  auto yesno = [&](const char *s, const char *kw) {
    if (strcmp(s, "yes") == 0) return true;
    if (strcmp(s, "no") == 0) return false;
    fail(std::string(kw) + " '" + s + "' must be yes or no");
    return false;
  };
  bool have_arrangement = false;
  bool start_given = false;
  long seed = 0;
  for (int i = 3; i < narg; i += 2) {
    const char *kw = arg[i];
    if (strcmp(kw, "psd") == 0) {
      need_value(i, kw, "a sieve-analysis file");
      psd_file_ = arg[i + 1];
    } else if (strcmp(kw, "porosity") == 0) {
      need_value(i, kw, "a number in (0, 1)");
      porosity_ = number(arg[i + 1], kw);
      if (!(porosity_ > 0.0 && porosity_ < 1.0))
        fail("porosity " + std::string(arg[i + 1]) +
             " must lie strictly between 0 and 1");
    } else if (strcmp(kw, "arrangement") == 0) {
      need_value(i, kw, "discrete or layerwise");
      if (strcmp(arg[i + 1], "discrete") == 0)
        arrangement_ = fabric::Arrangement::discrete;
      else if (strcmp(arg[i + 1], "layerwise") == 0)
        arrangement_ = fabric::Arrangement::layerwise;
      else
        fail("arrangement '" + std::string(arg[i + 1]) +
             "' is unknown: use discrete or layerwise");
      have_arrangement = true;
    } else if (strcmp(kw, "region") == 0) {
      need_value(i, kw, "a region ID");
      region_id_ = arg[i + 1];
    } else if (strcmp(kw, "seed") == 0) {
      need_value(i, kw, "a positive integer");
      seed = integer(arg[i + 1], kw);
      if (seed <= 0 || seed > INT32_MAX)
        fail("seed " + std::string(arg[i + 1]) +
             " must be a positive integer (1..2147483647)");
    } else if (strcmp(kw, "intervals") == 0) {
      need_value(i, kw, "an integer in 1..100");
      long n = integer(arg[i + 1], kw);
      if (n < 1 || n > 100)
        fail("intervals " + std::string(arg[i + 1]) + " must lie in 1..100");
      nintervals_ = static_cast<int>(n);
    } else if (strcmp(kw, "density") == 0) {
      need_value(i, kw, "a positive number");
      density_ = number(arg[i + 1], kw);
      if (!(density_ > 0.0))
        fail("density " + std::string(arg[i + 1]) + " must be positive");
    } else if (strcmp(kw, "type") == 0) {
      need_value(i, kw, "an atom type");
      long t = integer(arg[i + 1], kw);
      if (t < 1 || t > atom->ntypes)
        fail("type " + std::string(arg[i + 1]) + " must lie in 1.." +
             std::to_string(atom->ntypes) + " (the box's atom types)");
      atom_type_ = static_cast<int>(t);
    } else if (strcmp(kw, "fill_pores") == 0) {
      need_value(i, kw, "yes or no");
      fill_pores_ = yesno(arg[i + 1], kw);
    } else if (strcmp(kw, "layering") == 0) {
      need_value(i, kw, "a positive number (share of the list's solid volume)");
      layering_ = number(arg[i + 1], kw);
      if (!(layering_ > 0.0))
        fail("layering " + std::string(arg[i + 1]) +
             " must be positive (width of the coarse-to-fine schedule, as a "
             "share of the list's solid volume)");
    } else if (strcmp(kw, "start") == 0) {
      need_value(i, kw, "auto, floor_ceiling, floor or centre");
      if (strcmp(arg[i + 1], "auto") == 0)
        start_ = fabric::Start::automatic;
      else if (strcmp(arg[i + 1], "floor") == 0)
        start_ = fabric::Start::floor;
      else if (strcmp(arg[i + 1], "floor_ceiling") == 0)
        start_ = fabric::Start::floor_ceiling;
      else if (strcmp(arg[i + 1], "centre") == 0)
        start_ = fabric::Start::centre;
      else
        fail("start '" + std::string(arg[i + 1]) +
             "' is unknown: use auto, floor_ceiling, floor or centre");
      start_given = true;
    } else if (strcmp(kw, "verbose") == 0) {
      need_value(i, kw, "yes or no");
      verbose_ = yesno(arg[i + 1], kw);
    } else {
      fail("unknown keyword '" + std::string(kw) +
           "': allowed are psd porosity arrangement region seed intervals "
           "density type fill_pores start layering verbose");
    }
  }
  if (psd_file_.empty()) fail("keyword 'psd FILE' is required");
  if (porosity_ < 0.0) fail("keyword 'porosity P' is required");
  if (!have_arrangement)
    fail("keyword 'arrangement discrete|layerwise' is required");
  if (region_id_.empty()) fail("keyword 'region ID' is required");
  if (seed == 0) fail("keyword 'seed N' is required");
  if (!start_given) start_ = fabric::default_start(arrangement_);
  seed_ = static_cast<int>(seed);

  // The container.
  int iregion = domain->find_region(const_cast<char *>(region_id_.c_str()));
  if (iregion < 0) fail("region '" + region_id_ + "' does not exist");
  Region *reg = domain->regions[iregion];
  if (strcmp(reg->style, "block") != 0)
    fail("region '" + region_id_ + "' is style " + reg->style +
         "; the container must be a block region");
  if (!reg->interior)
    fail("region '" + region_id_ + "' must be 'side in'");
  lo_[0] = reg->extent_xlo, hi_[0] = reg->extent_xhi;
  lo_[1] = reg->extent_ylo, hi_[1] = reg->extent_yhi;
  lo_[2] = reg->extent_zlo, hi_[2] = reg->extent_zhi;
  for (int a = 0; a < 3; ++a)
    if (lo_[a] < domain->boxlo[a] - 1e-12 * domain->prd[a] ||
        hi_[a] > domain->boxhi[a] + 1e-12 * domain->prd[a])
      fail("region '" + region_id_ + "' extends outside the simulation box "
           "along " + "xyz"[a] + ": " + fmt("%g", lo_[a]) + ".." +
           fmt("%g", hi_[a]) + " vs box " + fmt("%g", domain->boxlo[a]) +
           ".." + fmt("%g", domain->boxhi[a]));

  // The PSD and the particle list.
  try {
    psd_ = new fabric::ParticleSizeDistribution(
        fabric::ParticleSizeDistribution::read(psd_file_));
    intervals_ = psd_->equal_mass_intervals(nintervals_);
  } catch (const std::exception &e) {
    fail(e.what());
  }
  double dmax = intervals_.back().d_mean;
  for (int a = 0; a < 3; ++a)
    if (hi_[a] - lo_[a] < dmax)
      fail("container '" + region_id_ + "' is " + fmt("%g", hi_[a] - lo_[a]) +
           " wide along " + "xyz"[a] + ", smaller than the largest particle "
           "(diameter " + fmt("%g", dmax) + " of the coarsest interval)");
  double volume = (hi_[0] - lo_[0]) * (hi_[1] - lo_[1]) * (hi_[2] - lo_[2]);
  list_ = fabric::particle_list(intervals_, volume, porosity_);
  double total = 0.0;
  for (double t : list_.target_count) total += t;
  long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  double memory = pages > 0 && page > 0 ? double(pages) * page : 64e9;
  double need = total * (kPackerBytes * comm->nprocs + kAtomBytes);
  if (total > INT32_MAX / 4 || need > 0.8 * memory)
    fail("the container holds about " + fmt("%.4g", total) +
         " particles at this porosity and PSD, needing about " +
         fmt("%.3g", need / 1073741824.0) + " GiB (" +
         fmt("%.0f", kPackerBytes) + " B per particle on each of the " +
         std::to_string(comm->nprocs) + " MPI rank(s) plus " +
         fmt("%.0f", kAtomBytes) + " B per atom), more than the " +
         fmt("%.3g", memory / 1073741824.0) +
         " GiB here (and at most " + std::to_string(INT32_MAX / 4) +
         " particles): use a smaller region or a coarser PSD");
  if (list_.total() < 3)
    fail("the container holds only " + std::to_string(list_.total()) +
         " particles of this PSD in " + std::to_string(nintervals_) +
         " intervals; at least 3 are needed: use a larger region, a lower "
         "porosity or fewer intervals");
  // Intervals that round to no grain leave their mass share out of the
  // specimen: say which, and how large a container keeps them all.
  std::string empty;
  int nempty = 0;
  double grow = 1.0;  // volume factor that gives every interval 1 grain
  for (size_t k = 0; k < list_.count.size(); ++k)
    if (list_.count[k] == 0) {
      ++nempty;
      if (nempty <= 3) empty += (empty.empty() ? "" : ", ") + std::to_string(k + 1);
      grow = std::max(grow, 0.5 / std::max(list_.target_count[k], 1e-300));
    }
  if (nempty > 0 && comm->me == 0) {
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
  fabric::PackingSpec spec = fabric::packing_spec(
      list_, fabric::Vec3(lo_[0], lo_[1], lo_[2]),
      fabric::Vec3(hi_[0], hi_[1], hi_[2]));
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
  // Atoms already in the container (another packing, or this fix under a
  // new ID after read_restart) are not seen by the packer.
  bigint inside_local = 0, inside = 0;
  for (int i = 0; i < atom->nlocal; ++i) {
    bool in = true;
    for (int a = 0; a < 3; ++a)
      in = in && atom->x[i][a] > lo_[a] && atom->x[i][a] < hi_[a];
    inside_local += in;
  }
  MPI_Allreduce(&inside_local, &inside, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (inside > 0 && comm->me == 0) {
    char w[256];
    snprintf(w, sizeof w,
             "Fix sequential/pack: %lld atoms already lie in container '%s'; "
             "the packing does not see them and will overlap them",
             static_cast<long long>(inside), region_id_.c_str());
    error->warning(FLERR, w);
  }
  message("fix sequential/pack: packing the container full, then choosing " +
          std::to_string(list_.total()) + " particles (" +
          fabric::to_string(arrangement_) + ") from it");
  double t0 = MPI_Wtime();
  fabric::PackingResult res;
  try {
    res = fabric::pack(spec);
  } catch (const std::exception &e) {
    error->all(FLERR, ("Fix sequential/pack: " + std::string(e.what())).c_str());
  }
  double seconds = MPI_Wtime() - t0;

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
  print_summary(res, seconds);
  check_neighbours(res);
}

void FixSequentialPack::check_neighbours(const fabric::PackingResult &res) {
  const long long n = res.placed();
  if (n < 2) return;
  const int one = neighbor->oneatom;
  const double skin = neighbor->skin;
  const double cdf = std::max(1.0, neighbor->contactDistanceFactor);
  double rmax = 0.0, rmin = INFINITY;
  for (double r : res.radius) rmax = std::max(rmax, r), rmin = std::min(rmin, r);
  // LIGGGHTS lists j for grain i when |x_i - x_j| <= (r_i + r_j) cdf + skin
  // (granular_bin_no_newton). A safe bound first: every such neighbour lies
  // wholly inside the ball of radius (2 rmax) cdf + rmax + skin around the
  // coarsest grain and holds at least a finest grain's volume.
  const double reach_max = 2.0 * rmax * cdf + rmax + skin;
  if (std::pow(reach_max / rmin, 3) <= one) return;

  // The count from the specimen, for every grain of at least half the
  // coarsest radius (the count grows with the grain's size). Per grain the
  // gaps are kept to tell which skin the present 'one' allows.
  std::vector<double> class_radius(list_.diameter.size());
  for (size_t k = 0; k < class_radius.size(); ++k)
    class_radius[k] = 0.5 * list_.diameter[k];
  fabric::SphereGrid grid(fabric::Vec3(lo_[0], lo_[1], lo_[2]),
                          fabric::Vec3(hi_[0], hi_[1], hi_[2]), class_radius,
                          std::max<std::size_t>(1u << 16, res.centre.size()));
  for (long long i = 0; i < n; ++i) grid.insert(res.centre[i], res.size_class[i]);
  // With the skin that leaves the list a margin of 1.5 for compaction.
  const long long keep = std::max<long long>(1, static_cast<long long>(one / 1.5));
  long long worst = 0;
  double worst_d = 0.0, skin_ok = INFINITY;
  std::vector<int> near;
  std::vector<double> gap;
  for (long long i = 0; i < n; ++i) {
    const double ri = res.radius[i];
    if (ri < 0.5 * rmax) continue;
    near.clear();
    gap.clear();
    grid.within_gap(res.centre[i], ri,
                    skin + (cdf - 1.0) * (ri + rmax) + 1e-12 * rmax, near);
    for (int j : near) {
      if (j == i) continue;
      const fabric::Vec3 d = grid.centre(j) - res.centre[i];
      // the skin that takes this neighbour into i's list
      gap.push_back(std::sqrt(d.dot(d)) - (ri + grid.radius(j)) * cdf);
    }
    long long count = 0;
    for (double g : gap) count += g <= skin;
    if (count > worst) worst = count, worst_d = 2.0 * ri;
    if (static_cast<long long>(gap.size()) > keep) {
      std::nth_element(gap.begin(), gap.begin() + keep, gap.end());
      skin_ok = std::min(skin_ok, gap[keep]);
    }
  }
  if (worst <= one) return;
  // Suggest a list that holds 1.5 times the count (compaction, rounding),
  // rounded up to hundreds; the page must hold 10 lists (Neighbor::init).
  const long long need = (static_cast<long long>(1.5 * worst) + 99) / 100 * 100;
  const long long page = std::max<long long>(neighbor->pgsize, 10 * need);
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
           worst_d, worst, skin, one, neighbor->pgsize, need, page,
           skin_hint.c_str());
  error->all(FLERR, b);
}

// Below this size assortativity (in the interior) a layer-wise specimen is
// reported as not layered: discrete specimens measure -0.15 to -0.17 there
// (a random packing of the same grains gives the same within 0.025 over the
// container, bench/random_reference).
static constexpr double kLayeredAssortativity = 0.1;

void FixSequentialPack::print_summary(const fabric::PackingResult &res,
                                      double seconds) {
  const size_t n = intervals_.size();
  double vol = (hi_[0] - lo_[0]) * (hi_[1] - lo_[1]) * (hi_[2] - lo_[2]);
  std::vector<double> placed_mass(n, 0.0);
  double placed_vol = 0.0;
  for (long long i = 0; i < res.placed(); ++i) {
    double v = fabric::sphere_volume(2.0 * res.radius[i]);
    placed_vol += v;
    placed_mass[res.size_class[i]] += v;
  }
  // Porosity by volume (exact sphere-box intersection), never by centres:
  // the interior is the container less one coarsest diameter per wall.
  fabric::Box box{fabric::Vec3(lo_[0], lo_[1], lo_[2]),
                  fabric::Vec3(hi_[0], hi_[1], hi_[2])};
  fabric::PackingMeasure measure(res.centre, res.radius, box);
  double layer = intervals_.back().d_mean, interior = NAN, wall = NAN;
  double interior_assortativity = NAN;
  double narrow = std::min({hi_[0] - lo_[0], hi_[1] - lo_[1], hi_[2] - lo_[2]});
  if (layer < 0.5 * narrow) {
    interior = measure.interior_porosity(layer);
    wall = measure.wall_layer_porosity(layer);
    interior_assortativity =
        measure.size_assortativity(measure.interior(layer));
  }
  double achieved = 1.0 - placed_vol / vol;
  long long not_placed = res.unplaced();
  // Contacts before loading, as the paper counts them: touching grains and
  // walls (gap below 1e-9 of the smaller radius), no force involved.
  const std::vector<int> contacts = measure.contact_counts();
  long long few = 0, total_contacts = 0;
  double held_vol = 0.0;  // solid volume of the grains with 3 contacts or more
  for (size_t i = 0; i < contacts.size(); ++i) {
    few += (contacts[i] < 3), total_contacts += contacts[i];
    if (contacts[i] >= 3) held_vol += fabric::sphere_volume(2.0 * res.radius[i]);
  }
  const double few_pct = contacts.empty() ? 0.0 : 100.0 * few / contacts.size();
  const double per_grain = contacts.empty() ? 0.0 : double(total_contacts) / contacts.size();
  summary_[0] = res.placed();
  summary_[1] = list_.total();
  summary_[2] = achieved;
  summary_[3] = interior;
  summary_[4] = wall;
  summary_[5] = seconds;
  summary_[6] = few_pct;
  summary_[7] = per_grain;
  summary_[8] = placed_vol > 0 ? 100.0 * held_vol / placed_vol : 0.0;
  // How the sizes are arranged: like sizes touching (LA) or mixed (DA).
  const double assortativity = measure.size_assortativity();
  summary_[9] = assortativity;
  summary_[10] = measure.radius_distance_spearman();
  summary_[11] = interior_assortativity;
  if (comm->me != 0) return;
  std::ostringstream s;
  s.unsetf(std::ios::fixed);
  s.precision(5);
  s << "fix sequential/pack summary\n"
    << "  PSD " << psd_file_ << ": " << psd_->points().size()
    << " points, d10 = " << psd_->d10() << ", d60 = " << psd_->d60()
    << ", Cu = " << psd_->uniformity_coefficient() << "\n"
    << "  container " << region_id_ << ": volume " << vol << ", arrangement "
    << fabric::to_string(arrangement_) << ", start " << fabric::to_string(start_)
    << (start_ == fabric::Start::automatic
            ? " (" + fabric::to_string(res.start) +
                  (res.unplaced_with_two_fronts > 0
                       ? ": two fronts left " +
                             std::to_string(res.unplaced_with_two_fronts) +
                             " grains unplaced, one front less volume"
                       : std::string()) +
                  ")"
            : std::string())
    << ", seed " << seed_ << ", " << n << " equal-mass intervals\n"
    << "  interval   d_mean       target    count   placed  not_placed  "
       "mass%PSD  mass%placed\n";
  for (size_t k = 0; k < n; ++k) {
    char row[160];
    snprintf(row, sizeof row, "  %8zu %9.4g %12.2f %8lld %8lld %11lld %9.2f %12.2f\n",
             k + 1, intervals_[k].d_mean, list_.target_count[k],
             list_.count[k], res.placed_per_class[k], res.unplaced_per_class[k],
             100.0 * intervals_[k].mass_fraction,
             placed_vol > 0 ? 100.0 * placed_mass[k] / placed_vol : 0.0);
    s << row;
  }
  char b[2048];
  double list_porosity = 1.0 - list_.solid_volume() / vol;
  double natural = 1.0 - res.packed_volume / vol;
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
           "have fewer than 3\n"
           "  structure: size assortativity of touching pairs %s, in the "
           "interior %s (0: contact ends paired at random; a random packing "
           "of a graded soil lies below 0, its fines touching coarse grains, "
           "see bench/random_reference; above that: like sizes together), "
           "Spearman(radius, distance from the centre) %s\n"
           "  time: %.3f s (%.0f particles per second)\n",
           list_.total(), res.placed(), res.placed_in_second_loop, not_placed,
           natural, res.vacancies, porosity_, list_porosity, achieved,
           interior, wall, layer, per_grain, few_pct,
           placed_vol > 0 ? 100.0 - summary_[8] : 0.0,
           (std::isfinite(summary_[9]) ? fmt("%+.3f", summary_[9])
                                       : "none (no touching pairs)").c_str(),
           (std::isfinite(summary_[11]) ? fmt("%+.3f", summary_[11])
                                        : "none").c_str(),
           (std::isfinite(summary_[10]) ? fmt("%+.3f", summary_[10])
                                        : "none (undefined)").c_str(),
           seconds,
           seconds > 0 ? res.placed() / seconds : 0.0);
  s << b;
  message(s.str());
  if (not_placed > 0 && natural > porosity_ - 0.01) {
    // The list does not fit: the target is (nearly) as dense as the
    // container packed full.
    snprintf(b, sizeof b,
             "Fix sequential/pack: %lld of %lld particles not placed (see "
             "not_placed per interval): the container packed full holds "
             "porosity %.4f, too close to the target %.4f to hold the whole "
             "list. Use a porosity of at least %.3f",
             not_placed, list_.total(), natural, porosity_, natural + 0.015);
    error->warning(FLERR, b);
  } else if (not_placed > 0) {
    // There was room, but not for the last coarse grains under the lid.
    std::string which;
    for (size_t k = 0; k < n; ++k)
      if (res.unplaced_per_class[k] > 0)
        which += (which.empty() ? "" : ", ") + std::to_string(k + 1);
    // Rounded as printed, so that the advice agrees with the number shown.
    double edge = std::round(10.0 *
                             std::min({hi_[0] - lo_[0], hi_[1] - lo_[1],
                                       hi_[2] - lo_[2]}) /
                             intervals_.back().d_mean) / 10.0;
    double missing_vol = list_.solid_volume() - placed_vol;
    // Below 6 coarsest diameters the last coarse grains often find no room
    // under the lid; in wider containers a few can still miss it (LA Cu 2.5
    // in 8.7: 1-4 of 76,176 with seeds 1-3, also at porosity 0.355), and no
    // setting is known to place them.
    std::string advice =
        edge < 6.0 ? "use at least 6"
                   : "at least the 6 recommended; another seed or a looser "
                     "target does not reliably place them";
    snprintf(b, sizeof b,
             "Fix sequential/pack: %lld of %lld particles not placed "
             "(%s %s): the container packed full holds porosity %.4f, "
             "room enough for the target %.4f, but these grains came too "
             "late to find a place large enough. They are %.3f %% of the "
             "list's solid volume (porosity %.4f against the list's %.4f). "
             "The container is %.1f coarsest diameters wide: %s",
             not_placed, list_.total(),
             which.find(',') == std::string::npos ? "interval" : "intervals",
             which.c_str(), natural, porosity_,
             100.0 * missing_vol / list_.solid_volume(), achieved,
             list_porosity, edge, advice.c_str());
    error->warning(FLERR, b);
  } else if (std::abs(achieved - porosity_) > 0.005) {
    snprintf(b, sizeof b,
             "Fix sequential/pack: every particle is placed; the porosity "
             "%.4f differs from the target %.4f only because the counts per "
             "interval are rounded (the list's porosity is %.4f): use a "
             "larger container for a closer match",
             achieved, porosity_, list_porosity);
    error->warning(FLERR, b);
  }
  // A layer-wise specimen is judged by its interior: the fine layer the
  // packing grows on its floor raises the value over the container
  // (measured in cubes of 6 coarsest diameters, Cu 2.0-3.5: +0.31 to -0.07
  // over the container, -0.10 to -0.19 in the interior, as discrete).
  if (arrangement_ == fabric::Arrangement::layerwise) {
    const bool inner = std::isfinite(summary_[11]);
    const double a = inner ? summary_[11] : summary_[9];
    if (std::isfinite(a) && a < kLayeredAssortativity) {
      snprintf(b, sizeof b,
               "Fix sequential/pack: the layer-wise specimen is not layered "
               "%s: the size assortativity of the touching pairs %s is "
               "%+.3f, below %.1f, as in discrete specimens (-0.15 to -0.17 "
               "in their interior) and a random packing of the same grains "
               "(bench/random_reference: -0.13 for Cu 2.0, -0.16 for Cu "
               "2.5). %s A layer-wise rule that keeps like sizes together "
               "inside the specimen while placing every grain is not "
               "reached yet: see 'Structure' in the fix's documentation",
               inner ? "in its interior" : "(the container has no interior)",
               inner ? "there" : "over the container", a,
               kLayeredAssortativity,
               inner ? ("Over the whole container it is " +
                        fmt("%+.3f", summary_[9]) +
                        ": like sizes touch mainly in the layer of fine "
                        "grains the packing grows on the floor.")
                           .c_str()
                     : "");
      error->warning(FLERR, b);
    }
  }
}

double FixSequentialPack::compute_vector(int i) { return summary_[i]; }

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
