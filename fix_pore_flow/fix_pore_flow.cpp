#include "fix_pore_flow.h"

#include <algorithm>
#include <climits>
#include <exception>
#include <numeric>
#include <regex>
#include <string>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"
#include "style_args.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

// The core solves along z, from lo to hi. The fix's flow axis a is turned
// onto z by the cyclic permutation core[k] = box[(a + 1 + k) mod 3] (the
// identity for z); a flow against the axis (direction -x, -y, -z) by a half
// turn about the core's y axis after it, (x, y, z) -> (-x, y, -z). Both keep
// the frame right-handed, and the half turn is its own inverse.
fabric::Vec3 to_core(const double *p, int axis, int sign) {
  return {sign * p[(axis + 1) % 3], p[(axis + 2) % 3], sign * p[axis]};
}

std::array<double, 3> from_core(const fabric::Vec3 &v, int axis, int sign) {
  const fabric::Vec3 u{sign * v[0], v[1], sign * v[2]};
  std::array<double, 3> p{};
  for (int k = 0; k < 3; ++k) p[(axis + 1 + k) % 3] = u[k];
  return p;
}

// The n numbers after keyword arg[i]; `names` names them in the errors.
std::vector<double> numbers_after(const StyleArgs &args, int i, int n,
                                  const std::vector<std::string> &names) {
  std::string list;
  for (const std::string &s : names) list += " " + s;
  if (i + n >= args.size())
    args.fail("keyword '" + std::string(args[i]) + "' needs " +
              std::to_string(n) + " values:" + list);
  std::vector<double> v(n);
  for (int k = 0; k < n; ++k)
    v[k] = args.number_of(args[i + 1 + k],
                          std::string(args[i]) + " " + names[k]);
  return v;
}

fabric::Box read_box(const StyleArgs &args, int i) {
  const std::vector<double> v = numbers_after(
      args, i, 6, {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi"});
  fabric::Box box;
  for (int a = 0; a < 3; ++a) {
    if (!(v[2 * a] < v[2 * a + 1]))
      args.fail(std::string("box ") + "xyz"[a] + " from " + args[i + 1 + 2 * a] +
                " to " + args[i + 2 + 2 * a] + ": lo must be below hi");
    box.lo[a] = v[2 * a];
    box.hi[a] = v[2 * a + 1];
  }
  return box;
}

}  // namespace

FixPoreFlow::FixPoreFlow(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg) {
  StyleArgs args(error, "Fix pore/flow", narg - 3, arg + 3,
                 {"every", "box", "pressure", "viscosity", "direction"});
  bool have_box = false, have_pressure = false;
  fabric::Box box;
  for (int i = 0; i < args.size();) {
    const std::string kw = args[i];
    if (kw == "every") {
      const long every =
          args.integer_in(i, 1, LONG_MAX, "steps between two solves");
      args.require(every <= INT_MAX, i, "is too large (at most 2147483647)");
      every_ = static_cast<int>(every);
      i += 2;
    } else if (kw == "box") {
      box = read_box(args, i);
      have_box = true;
      i += 7;
    } else if (kw == "pressure") {
      const std::vector<double> p =
          numbers_after(args, i, 2, {"P_in", "P_out"});
      if (!(p[0] > p[1]))
        args.fail("pressure P_in " + std::string(args[i + 1]) +
                  " must exceed P_out " + args[i + 2] +
                  " (Pa: the inflow face holds the higher pressure; "
                  "equal pressures drive no flow)");
      options_.inflow_pressure = p[0];
      options_.outflow_pressure = p[1];
      have_pressure = true;
      i += 3;
    } else if (kw == "viscosity") {
      options_.viscosity = args.number(i, "the fluid's dynamic viscosity, Pa s");
      args.require(options_.viscosity > 0.0, i,
                   "must be positive (Pa s; water at 20 C: 1e-3)");
      i += 2;
    } else if (kw == "direction") {
      const int c = args.choice(i, {"x", "y", "z", "-x", "-y", "-z"});
      axis_ = c % 3;
      sign_ = c < 3 ? 1 : -1;
      i += 2;
    } else {
      args.unknown_keyword(i);
    }
  }
  if (every_ == 0)
    args.fail("keyword 'every' is required: every N, the steps between "
              "two solves of the flow");
  if (!have_box)
    args.fail("keyword 'box' is required: box xlo xhi ylo yhi zlo zhi, "
              "the walls of the flow domain");
  if (!have_pressure)
    args.fail("keyword 'pressure' is required: pressure P_in P_out, the "
              "pressures (Pa) on the inflow and outflow faces");
  if (!atom->radius_flag)
    error->all(FLERR, "Fix pore/flow: needs an atom style with a radius per "
                      "atom (atom_style granular or sphere)");
  if (!atom->tag_enable)
    error->all(FLERR, "Fix pore/flow: needs atom IDs (atom_modify id yes)");
  // the box's corners in the core's frame (a half turn swaps lo and hi)
  const fabric::Vec3 a = to_core(box.lo.data(), axis_, sign_);
  const fabric::Vec3 b = to_core(box.hi.data(), axis_, sign_);
  for (int k = 0; k < 3; ++k) {
    options_.box.lo[k] = std::min(a[k], b[k]);
    options_.box.hi[k] = std::max(a[k], b[k]);
  }

  vector_flag = 1;
  size_vector = fabric::kPoreFlowEntries;
  global_freq = 1;
  extvector = 0;
  peratom_flag = 1;  // each grain's fluid force f_ID[1..3], pressure f_ID[4]
  size_peratom_cols = kAtomColumns;
  peratom_freq = 1;
  array_atom = nullptr;
}

FixPoreFlow::~FixPoreFlow() { memory->destroy(array_atom); }

int FixPoreFlow::setmask() { return POST_FORCE; }

// The grains may have moved, or been added, since the last run: solve anew.
void FixPoreFlow::setup(int vflag) {
  solve();
  post_force(vflag);
}

void FixPoreFlow::post_force(int) {
  if (update->ntimestep % every_ == 0 && solved_step_ != update->ntimestep)
    solve();
  if (atom->nmax > nmax_) {
    memory->destroy(array_atom);
    nmax_ = atom->nmax;
    memory->create(array_atom, nmax_, kAtomColumns, "pore/flow:array_atom");
  }
  double **f = atom->f;
  const tagint *tag = atom->tag;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; ++i) {
    std::fill(array_atom[i], array_atom[i] + kAtomColumns, 0.0);
    if (!(mask[i] & groupbit)) continue;
    // a grain that joined the group after the last solve feels no force
    const auto it = std::lower_bound(ids_.begin(), ids_.end(), tag[i]);
    if (it == ids_.end() || *it != tag[i]) continue;
    const std::array<double, 3> &fi = force_[it - ids_.begin()];
    for (int k = 0; k < 3; ++k) {
      f[i][k] += fi[k];
      array_atom[i][k] = fi[k];
    }
    array_atom[i][3] = pressure_[it - ids_.begin()];
  }
}

// Every rank gets every grain of the group (ID, centre, radius), in the
// order of the IDs, so that any rank count solves the same system.
std::vector<fabric::Sphere> FixPoreFlow::gather() {
  constexpr int kRecord = 5;
  std::vector<double> mine;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double *x = atom->x[i];
    mine.insert(mine.end(), {static_cast<double>(atom->tag[i]), x[0], x[1],
                             x[2], atom->radius[i]});
  }
  const int n = static_cast<int>(mine.size());
  std::vector<int> counts(comm->nprocs), offsets(comm->nprocs, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  std::partial_sum(counts.begin(), counts.end() - 1, offsets.begin() + 1);
  std::vector<double> all(offsets.back() + counts.back());
  MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(),
                 offsets.data(), MPI_DOUBLE, world);

  const long grains = static_cast<long>(all.size()) / kRecord;
  std::vector<long> order(grains);
  std::iota(order.begin(), order.end(), 0L);
  std::sort(order.begin(), order.end(), [&all](long a, long b) {
    return all[kRecord * a] < all[kRecord * b];
  });
  // A grain whose centre has crossed the outflow face (the core's z = hi)
  // has left the flow domain, e.g. through an outlet that deletes it only
  // at the next neighbour-list build: it is left out of the solve and feels
  // no force (counted in left_out). One outside any other face is an error
  // of the core's.
  std::vector<fabric::Sphere> spheres;
  spheres.reserve(grains);
  ids_.clear();
  left_out_ = 0;
  for (long k = 0; k < grains; ++k) {
    const double *r = &all[kRecord * order[k]];
    const fabric::Vec3 c = to_core(r + 1, axis_, sign_);
    if (c.z() >= options_.box.hi.z()) {
      ++left_out_;
      continue;
    }
    ids_.push_back(static_cast<tagint>(r[0]));
    spheres.push_back({c, r[4]});
  }
  return spheres;
}

void FixPoreFlow::solve() {
  const std::vector<fabric::Sphere> spheres = gather();
  const long grains = static_cast<long>(spheres.size());
  fabric::PoreFlow flow;
  try {
    flow = fabric::pore_flow(spheres, options_);
  } catch (const std::exception &e) {
    // the core counts the spheres from 0 in the order of their IDs
    std::string what = e.what();
    std::smatch m;
    if (std::regex_search(what, m, std::regex("sphere (\\d+)")) &&
        std::stol(m[1]) < grains)
      what.insert(m.position(0) + m.length(0),
                  " (atom ID " + std::to_string(ids_[std::stol(m[1])]) + ")");
    error->all(FLERR, ("Fix pore/flow: " + what).c_str());
  }
  force_.resize(grains);
  for (long k = 0; k < grains; ++k) force_[k] = from_core(flow.force[k], axis_, sign_);
  pressure_ = flow.grain_pressure;
  vector_ = fabric::pore_flow_vector(flow, options_,
                                     static_cast<double>(update->ntimestep),
                                     left_out_);
  solved_step_ = update->ntimestep;
}

double FixPoreFlow::compute_vector(int i) {
  if (solved_step_ < 0)
    error->all(FLERR, "Fix pore/flow: its vector is asked for before the "
                      "first solve (the setup of the first run)");
  return vector_[i];
}

double FixPoreFlow::memory_usage() {
  return static_cast<double>(ids_.size()) * sizeof(tagint) +
         static_cast<double>(force_.size()) * sizeof(force_[0]) +
         static_cast<double>(pressure_.size()) * sizeof(double) +
         static_cast<double>(kAtomColumns) * nmax_ * sizeof(double);
}
