// The Packer's vacancies (packer.h): which spheres of the full packing are
// left out of the specimen, cell by cell (choose_vacancies), and the second
// loop, which puts a class's missing grains into vacancies.
#include "packer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace fabric {
namespace detail {

namespace {

// The vacancy choice of a coarse class: candidates weighed per vacancy.
constexpr int kVacancyCandidates = 24;

}  // namespace

// The packing holds the particle list with room to spare: per size class,
// the list's count of its spheres are the specimen and the others are
// vacancies, grain-sized holes. Which ones is chosen cell by cell so that
// every cell is left as close to the target porosity as its packing allows
// (CellShares says where each sphere's volume lies). Coarse classes go
// first (remove_coarse), then the numerous fines even out the rest
// (remove_fines).
void Packer::choose_vacancies() {
  cells_ = split_over_cells(grid_, spec_.lo, spec_.hi,
                            2.0 * spec_.radius[asc_.back()]);
  const CellShares& cs = cells_;
  std::vector<double> placed(cs.cells, 0.0);
  double total_placed = 0.0, list_volume = 0.0;
  for (int i = 0; i < grid_.size(); ++i) {
    const double v = volume_[grid_.sphere_class(i)];
    total_placed += v;
    for (std::uint32_t j = cs.begin[i]; j < cs.begin[i + 1]; ++j)
      placed[cs.part[j].first] += v * cs.part[j].second;
  }
  for (int k = 0; k < nclass_; ++k) list_volume += spec_.count[k] * volume_[k];
  // What each cell should lose: its excess over the target solid volume,
  // scaled so that the cells together lose what the packing holds too much.
  const double cell_volume = (spec_.hi - spec_.lo).prod() / cs.cells;
  const double target = list_volume / (spec_.hi - spec_.lo).prod();
  lose_.assign(cs.cells, 0.0);
  double excess = 0.0;
  for (int c = 0; c < cs.cells; ++c) {
    lose_[c] = std::max(0.0, placed[c] - target * cell_volume);
    excess += lose_[c];
  }
  const double scale =
      excess > 0.0 ? std::max(0.0, total_placed - list_volume) / excess : 0.0;
  for (double& l : lose_) l *= scale;
  std::vector<std::vector<int>> of_class(nclass_);
  for (int i = 0; i < grid_.size(); ++i)
    of_class[grid_.sphere_class(i)].push_back(i);
  for (int rk = nclass_ - 1; rk >= 0; --rk) {
    const int k = asc_[rk];
    std::vector<int>& v = of_class[k];
    const long long keep = std::min<long long>(spec_.count[k], v.size());
    missing_[k] = spec_.count[k] - keep;
    const long long removals = static_cast<long long>(v.size()) - keep;
    if (removals == 0) continue;
    if (spec_.radius[k] >= cs.split_radius)
      remove_coarse(v, removals, k);
    else
      remove_fines(v, removals);
  }
}

// Sphere i becomes a vacancy: its cells have that much less to lose.
void Packer::make_vacant(int i) {
  vacant_[i] = 1;
  const double v = volume_[grid_.sphere_class(i)];
  for (std::uint32_t j = cells_.begin[i]; j < cells_.begin[i + 1]; ++j)
    lose_[cells_.part[j].first] -= v * cells_.part[j].second;
}

// A coarse class (spheres of class k in v): each vacancy is the best of a
// few random spheres of it, the one whose removal brings the cells' losses
// closest to zero (the drop of their sum of squares; an overshoot counts
// against).
void Packer::remove_coarse(std::vector<int>& v, long long removals, int k) {
  for (long long t = 0; t < removals; ++t) {
    const size_t left = v.size() - t;
    size_t best = 0;
    double best_score = -std::numeric_limits<double>::infinity();
    for (int trial = 0; trial < kVacancyCandidates; ++trial) {
      size_t j = t + std::min(left - 1,
                              static_cast<size_t>(vacancy_rng_.uniform() * left));
      const int i = v[j];
      double score = 0.0;
      for (std::uint32_t q = cells_.begin[i]; q < cells_.begin[i + 1]; ++q) {
        double d = volume_[k] * cells_.part[q].second;
        score += d * (2.0 * lose_[cells_.part[q].first] - d);
      }
      if (score > best_score) best_score = score, best = j;
    }
    std::swap(v[t], v[best]);
    make_vacant(v[t]);
  }
}

// A fine class (spheres in v): removals per cell by systematic sampling of
// what each cell still has to lose, weighted by how over-represented the
// size is in the cell (fines that crowd along the walls go first there, and
// the local PSD follows the global one), then spheres drawn at random
// within the cell; a cell asked for more than it holds passes the rest on.
void Packer::remove_fines(const std::vector<int>& v, long long removals) {
  const CellShares& cs = cells_;
  std::vector<std::vector<int>> in_cell(cs.cells);
  std::vector<double> all_in_cell(cs.cells, 0.0), w(cs.cells, 0.0);
  for (int i = 0; i < grid_.size(); ++i) all_in_cell[cs.home(i)] += 1.0;
  for (int i : v) in_cell[cs.home(i)].push_back(i);
  const double global = static_cast<double>(v.size()) / grid_.size();
  double weight_total = 0.0;
  for (int c = 0; c < cs.cells; ++c) {
    const double share = in_cell[c].size() / all_in_cell[c];
    w[c] = in_cell[c].empty()
               ? 0.0
               : std::max(lose_[c], 0.0) * std::pow(share / global, 3.0) + 1e-300;
    weight_total += w[c];
  }
  const double step = weight_total / static_cast<double>(removals);
  double next = vacancy_rng_.uniform() * step, cum = 0.0;
  long long planned = 0;
  std::vector<long long> quota(cs.cells, 0);
  for (int c = 0; c < cs.cells && planned < removals; ++c) {
    cum += w[c];
    while (next < cum && planned < removals) ++quota[c], ++planned, next += step;
  }
  long long carry = removals - planned;
  for (int pass = 0; pass < 2; ++pass)
    for (int c = 0; c < cs.cells; ++c) {
      std::vector<int>& l = in_cell[c];
      const long long q = (pass == 0 ? quota[c] : 0) + carry;
      long long taken = 0;
      for (size_t t = 0; t < l.size() && taken < q; ++t) {
        size_t j = t + std::min(l.size() - t - 1,
                                static_cast<size_t>(vacancy_rng_.uniform() *
                                                    (l.size() - t)));
        std::swap(l[t], l[j]);
        if (!vacant_[l[t]]) make_vacant(l[t]), ++taken;
      }
      carry = q - taken;
    }
}

// The second loop: a class the packing holds too few of (the target is
// denser than the packing, or the last coarse grains found no room under
// the lid) has its missing grains put, largest first, into a vacancy of
// their size or the smallest larger one, at its centre.
void Packer::second_loop() {
  std::vector<std::vector<int>> vacancy(nclass_);  // by rank
  for (int i = 0; i < grid_.size(); ++i)
    if (vacant_[i]) vacancy[rank_[grid_.sphere_class(i)]].push_back(i);
  for (int rk = nclass_ - 1; rk >= 0; --rk) {
    int k = asc_[rk];
    while (missing_[k] > 0) {
      int from = -1;
      for (int v = rk; v < nclass_ && from < 0; ++v)
        if (!vacancy[v].empty() && spec_.radius[asc_[v]] >= spec_.radius[k])
          from = v;
      if (from < 0) break;
      // A random one of them, so the second loop's grains are spread too.
      std::vector<int>& holes = vacancy[from];
      size_t pick = std::min(holes.size() - 1,
                             static_cast<size_t>(vacancy_rng_.uniform() * holes.size()));
      int hole = holes[pick];
      holes[pick] = holes.back();
      holes.pop_back();
      fill_vacancy(hole, k);
    }
  }
  // A grain still missing (no vacancy of its size) goes, if it fits among
  // the specimen's spheres, at the centre of a smaller vacancy whose
  // neighbours are vacancies too.
  long long still = 0;
  for (long long m : missing_) still += m;
  if (still == 0) return;
  SphereGrid real(spec_.lo, spec_.hi, spec_.radius,
                  std::max<std::size_t>(1u << 16, res_.centre.size()));
  for (size_t i = 0; i < res_.centre.size(); ++i)
    real.insert(res_.centre[i], res_.size_class[i]);
  std::vector<int> holes;
  for (int v = nclass_ - 1; v >= 0; --v)
    for (int i : vacancy[v]) holes.push_back(i);
  for (int rk = nclass_ - 1; rk >= 0; --rk) {
    int k = asc_[rk];
    const double r = spec_.radius[k];
    for (size_t h = 0; h < holes.size() && missing_[k] > 0; ++h) {
      int hole = holes[h];
      if (hole < 0) continue;
      Vec3 c = grid_.centre(hole);
      if (!inside(c, r) || real.overlaps(c, r, spec_.overlap_tolerance)) continue;
      real.insert(c, k);
      holes[h] = -1;
      fill_vacancy(hole, k);
    }
  }
}

// A missing grain of class k goes to the centre of vacancy `hole`.
void Packer::fill_vacancy(int hole, int k) {
  vacant_[hole] = 2;  // filled
  res_.centre.push_back(grid_.centre(hole));
  res_.radius.push_back(spec_.radius[k]);
  res_.size_class.push_back(k);
  res_.placement.push_back(Placement::vacancy);
  ++res_.placed_per_class[k];
  ++res_.placed_by[static_cast<int>(Placement::vacancy)];
  ++res_.placed_in_second_loop;
  --missing_[k];
}

}  // namespace detail
}  // namespace fabric
