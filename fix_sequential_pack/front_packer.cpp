#include "front_packer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>

#include "psd.h"
#include "sphere_grid.h"

namespace fabric {

std::string to_string(Arrangement a) {
  return a == Arrangement::discrete ? "discrete" : "layerwise";
}

std::string to_string(Start s) {
  switch (s) {
    case Start::floor: return "floor";
    case Start::centre: return "centre";
    case Start::floor_ceiling: return "floor_ceiling";
    case Start::automatic: return "auto";
  }
  return "?";
}

std::string to_string(Placement p) {
  static const char* names[kPlacementKinds] = {
      "first face", "trilateration", "constriction centre", "touching two",
      "two spheres and a wall", "one sphere and two walls", "corner",
      "into a vacancy"};
  return names[static_cast<int>(p)];
}

PackingSpec packing_spec(const ParticleList& list, const Vec3& lo,
                         const Vec3& hi) {
  PackingSpec spec;
  spec.lo = lo;
  spec.hi = hi;
  for (size_t k = 0; k < list.count.size(); ++k) {
    spec.radius.push_back(0.5 * list.diameter[k]);
    spec.count.push_back(list.count[k]);
  }
  return spec;
}

long long PackingResult::unplaced() const {
  long long n = 0;
  for (long long u : unplaced_per_class) n += u;
  return n;
}

namespace {

// SplitMix64: tiny, portable and the same on every platform and rank.
struct Random {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  double uniform() { return (next() >> 11) * 0x1.0p-53; }
  Vec3 unit_vector() {
    double z = 2.0 * uniform() - 1.0, phi = 2.0 * M_PI * uniform();
    double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    return Vec3(s * std::cos(phi), s * std::sin(phi), z);
  }
};

// Each deck is the list plus this many grains of each size (new_deck()).
constexpr long long kDeckExtra = 2;
// DA: how much faster than by number the coarsest size is drawn (x^2
// between).
constexpr double kCoarseBoost = 0.6;
// LA: how strongly a size that falls behind its schedule is favoured:
// e^(100 x) for a size x (as a share of its deck) behind.
constexpr double kCatchUp = 100.0;

// ---- The arrangement rules: the one place DA and LA differ. ----
// Both place a drawn grain on the lowest site that fits it; a rule decides
// which size is drawn next, which two face spheres a Fig. 8 grain touches
// and where a specimen starts by default.

// The sizes as a rule sees them, per rank (finest first): the list's count
// and where the size lies between the finest and the coarsest, in ln r.
struct Sizes {
  std::vector<long long> count;
  std::vector<double> volume;  // of one grain
  std::vector<double> x;       // 0 the finest, 1 the coarsest
};

// The deck as the next draw finds it, per rank: grains left and the share
// of the size's decks spent; t the solid volume placed so far as a share of
// the list's. Ranks 0 .. n-1 may be drawn.
struct DrawState {
  const long long* left;
  const double* spent;
  int n;
  double t;
};

class Rule {
 public:
  virtual ~Rule() = default;
  virtual Start default_start() const = 0;
  // Fig. 8: the grain touches the two smaller face spheres, else the two
  // larger.
  virtual bool touches_smaller_pair() const = 0;
  // The weight w[i] >= 0 of each rank i < st.n in the draw; all 0 when
  // none of these sizes is left in the deck.
  virtual void weigh(const DrawState& st, double* w) const = 0;
};

// DA: by number, the coarse sizes up to 60 % faster, so a deck's coarse
// grains are placed before the container is nearly full, where they would
// find no room.
class Discrete : public Rule {
 public:
  explicit Discrete(const Sizes& sizes) {
    for (double x : sizes.x) boost_.push_back(1.0 + kCoarseBoost * x * x);
  }
  Start default_start() const override { return Start::automatic; }
  bool touches_smaller_pair() const override { return false; }
  void weigh(const DrawState& st, double* w) const override {
    for (int i = 0; i < st.n; ++i)
      w[i] = static_cast<double>(st.left[i]) * boost_[i];
  }

 private:
  std::vector<double> boost_;
};

// LA, a graded bed: the draw follows the list from the coarsest size to the
// finest. The list ordered coarse first gives each size a share [b, e] of
// its solid volume; at t the size is drawn with weight (left in the deck)
// * exp(-(t - (b + e) / 2)^2 / (2 w^2)), w = spec.layering, and a size that
// falls behind its schedule (by t it should have spent min(1, (t - b) /
// (e - b)) of its deck) is favoured by kCatchUp, so no size is starved.
class GradedBed : public Rule {
 public:
  GradedBed(const Sizes& sizes, double width) : width_(width) {
    if (!(width > 0.0 && std::isfinite(width)))
      throw std::invalid_argument("layering must be positive and finite, got " +
                                  std::to_string(width));
    const int n = static_cast<int>(sizes.count.size());
    double total = 0.0;
    for (int i = 0; i < n; ++i) total += sizes.count[i] * sizes.volume[i];
    begin_.assign(n, 0.0), end_.assign(n, 0.0);
    double done = 0.0;
    for (int i = n - 1; i >= 0; --i) {
      begin_[i] = done / total;
      done += sizes.count[i] * sizes.volume[i];
      end_[i] = done / total;
    }
  }
  Start default_start() const override { return Start::floor; }
  bool touches_smaller_pair() const override { return true; }
  void weigh(const DrawState& st, double* w) const override {
    double top = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < st.n; ++i) {
      w[i] = -std::numeric_limits<double>::infinity();  // ln of the weight
      if (st.left[i] <= 0) continue;
      double d = (st.t - 0.5 * (begin_[i] + end_[i])) / width_;
      double due = end_[i] > begin_[i]
          ? std::clamp((st.t - begin_[i]) / (end_[i] - begin_[i]), 0.0, 1.0)
          : 1.0;
      double behind = std::max(0.0, due - st.spent[i]);
      w[i] = std::log(static_cast<double>(st.left[i])) - 0.5 * d * d +
             kCatchUp * behind;
      top = std::max(top, w[i]);
    }
    for (int i = 0; i < st.n; ++i)
      w[i] = st.left[i] > 0 ? std::exp(w[i] - top) : 0.0;
  }

 private:
  double width_;
  std::vector<double> begin_, end_;  // per rank, shares of the list's volume
};

std::unique_ptr<Rule> make_rule(Arrangement a, const Sizes& sizes,
                                double layering) {
  if (a == Arrangement::layerwise)
    return std::make_unique<GradedBed>(sizes, layering);
  return std::make_unique<Discrete>(sizes);
}

// A support of a site: a placed sphere (index >= 0) or a wall (< 0): wall
// -1 - (2 axis + side), side 0 the low wall of that axis, 1 the high one.
inline bool is_wall(int s) { return s < 0; }
inline int wall_code(int axis, int side) { return -1 - (2 * axis + side); }
inline int wall_axis(int w) { return (-1 - w) / 2; }
inline int wall_side(int w) { return (-1 - w) % 2; }

// A place for a grain: its three supports (spheres first, then walls) and
// which of the two mirror solutions. Ordered by key (height or distance from
// the centre), then by the order sites were opened.
struct Site {
  double key;
  std::uint32_t order;
  std::int32_t s[3];
  std::int8_t mirror;  // +1: the positive solution, -1: the negative one
  // The sphere that kept the last grain offered here out (-1: none yet):
  // tested first when the site is offered a smaller grain, which it blocks
  // too more often than not (the answer is the same, only found sooner).
  std::int32_t blocker;
};
static_assert(sizeof(Site) == 32, "a site is kept in 32 bytes");

// A heap of sites with four children per node: half the levels of a binary
// heap, and a node's children share two cache lines (measured: about 5-10 %
// less CPU time for the whole packing than std::push_heap / pop_heap;
// buckets of key, each a heap, were not faster). (key, order) is unique, so
// the sites come out in the same order from any exact heap: the same
// specimen.
// Keys are heights above a wall or distances from the centre of spheres
// inside the container: positive and finite, so their bit patterns order as
// the numbers do, and the comparison needs no branch (a mispredicted branch
// per child was most of the cost of taking the top).
inline std::uint64_t key_bits(const Site& s) {
  std::uint64_t b;
  std::memcpy(&b, &s.key, sizeof b);
  return b;
}
inline bool earlier(const Site& a, const Site& b) {
  const std::uint64_t ka = key_bits(a), kb = key_bits(b);
  return (ka < kb) | ((ka == kb) & (a.order < b.order));
}
void heap_push(std::vector<Site>& h, const Site& s) {
  std::size_t i = h.size();
  h.push_back(s);
  while (i > 0) {
    std::size_t parent = (i - 1) / 4;
    if (!earlier(s, h[parent])) break;
    h[i] = h[parent];
    i = parent;
  }
  h[i] = s;
}
Site heap_pop(std::vector<Site>& h) {
  Site top = h.front(), last = h.back();
  h.pop_back();
  const std::size_t n = h.size();
  if (n == 0) return top;
  std::size_t i = 0;
  for (;;) {
    std::size_t first = 4 * i + 1;
    if (first >= n) break;
    std::size_t best = first, end = std::min(first + 4, n);
    for (std::size_t c = first + 1; c < end; ++c)
      best = earlier(h[c], h[best]) ? c : best;
    if (!earlier(h[best], last)) break;
    h[i] = h[best];
    i = best;
  }
  h[i] = last;
  return top;
}

// The vacancy choice of a coarse class: candidates weighed per vacancy.
constexpr int kVacancyCandidates = 24;

// The cells of the vacancy choice (about a coarsest diameter each) and the
// share of each placed sphere's volume in each cell it meets: a sphere wider
// than an eighth of a cell is split over the cells it meets by a lattice
// quadrature; a smaller one counts in the cell of its centre.
struct CellShares {
  int n[3];
  Vec3 lo, cell_size;
  int cells = 0;
  double split_radius = 0.0;
  std::vector<std::uint32_t> begin;          // per sphere, into part
  std::vector<std::pair<int, double>> part;  // (cell, share of the volume)
  int cell_at(const Vec3& q) const {
    int idx[3];
    for (int a = 0; a < 3; ++a)
      idx[a] = std::clamp(static_cast<int>((q[a] - lo[a]) / cell_size[a]), 0,
                          n[a] - 1);
    return (idx[2] * n[1] + idx[1]) * n[0] + idx[0];
  }
  int home(int i) const { return part[begin[i]].first; }
};

// Quadrature points of the unit ball: the centres of an 8^3 lattice on
// [-1, 1]^3 that lie inside it.
const std::vector<Vec3>& unit_ball_points() {
  static const std::vector<Vec3> ball = [] {
    std::vector<Vec3> p;
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j)
        for (int k = 0; k < 8; ++k) {
          Vec3 q((i + 0.5) / 4.0 - 1.0, (j + 0.5) / 4.0 - 1.0,
                 (k + 0.5) / 4.0 - 1.0);
          if (q.squaredNorm() <= 1.0) p.push_back(q);
        }
    return p;
  }();
  return ball;
}

CellShares split_over_cells(const SphereGrid& grid, const Vec3& lo,
                            const Vec3& hi, double dmax) {
  CellShares cs;
  cs.lo = lo;
  const Vec3 ext = hi - lo;
  for (int a = 0; a < 3; ++a) {
    cs.n[a] = std::max(1, static_cast<int>(std::lround(ext[a] / dmax)));
    cs.cell_size[a] = ext[a] / cs.n[a];
  }
  cs.cells = cs.n[0] * cs.n[1] * cs.n[2];
  cs.split_radius = 0.125 * cs.cell_size.minCoeff();
  const std::vector<Vec3>& ball = unit_ball_points();
  std::vector<int> count_in(cs.cells), touched;
  cs.begin.assign(grid.size() + 1, 0);
  for (int i = 0; i < grid.size(); ++i) {
    cs.begin[i] = static_cast<std::uint32_t>(cs.part.size());
    const Vec3 c = grid.centre(i);
    const double r = grid.radius(i);
    bool within = true;  // does the sphere lie in the cell of its centre?
    for (int a = 0; a < 3 && within; ++a) {
      double cl = lo[a] + std::floor((c[a] - lo[a]) / cs.cell_size[a]) *
                              cs.cell_size[a];
      within = c[a] - r >= cl && c[a] + r <= cl + cs.cell_size[a];
    }
    if (within || r < cs.split_radius) {
      cs.part.push_back({cs.cell_at(c), 1.0});
      continue;
    }
    std::fill(count_in.begin(), count_in.end(), 0);
    touched.clear();
    for (const Vec3& q : ball) {
      int cq = cs.cell_at(c + r * q);
      if (count_in[cq]++ == 0) touched.push_back(cq);
    }
    for (int cq : touched)
      cs.part.push_back({cq, static_cast<double>(count_in[cq]) / ball.size()});
  }
  cs.begin[grid.size()] = static_cast<std::uint32_t>(cs.part.size());
  return cs;
}

class Packer {
 public:
  explicit Packer(const PackingSpec& spec);
  PackingResult run();

 private:
  // What a site's position depends on besides the grain's radius: its
  // spheres and, for three, their face frame, computed once however many
  // sizes the site is offered (bit-identical to computing them each time).
  struct Geometry {
    int spheres = 0;
    Sphere sphere[3];
    std::optional<FaceFrame> frame;
  };
  Geometry geometry(const Site& s) const;
  std::optional<Vec3> position(const Site& s, const Geometry& g, double r,
                               Placement& how) const;
  bool inside(const Vec3& c, double r) const;
  double key_of(const Vec3& c) const;
  double wall_gap(int w, const Vec3& c, double r) const;
  Sphere support(int i) const { return grid_.sphere(i); }
  void open_sites(int p);
  void add_site(int a, int b, int c);
  void push(Site s, int level, const Geometry& g);
  void push(const Site& s, int level) { push(s, level, geometry(s)); }
  bool pop_lowest(int min_level, Site& s, int& level);
  void refresh_front(int level);
  void demote(const Site& s, int k, const Geometry& g);
  struct Front {
    double key;
    std::uint32_t order;
  };
  std::vector<Front> front_;  // per level: key and order of its heap's top
  int take_from_deck(const double* w, int n, double total);
  int draw();
  int place(const Vec3& c, int k, Placement how);
  bool try_site(Site& s, int k, const Geometry& g);
  void first_face();
  void choose_vacancies();
  void make_vacant(int i);
  void remove_coarse(std::vector<int>& v, long long removals, int k);
  void remove_fines(const std::vector<int>& v, long long removals);
  CellShares cells_;          // the vacancy choice's cells
  std::vector<double> lose_;  // per cell: solid volume it still has to lose
  void second_loop();
  void fill_vacancy(int hole, int k);
  void report_progress();

  const PackingSpec& spec_;
  SphereGrid grid_;
  int nclass_ = 0;
  std::vector<int> asc_;    // classes by radius, finest first
  std::vector<int> rank_;   // class -> its position in asc_
  std::vector<int> below_;  // rank -> largest rank of a smaller radius, or -1
  std::vector<double> volume_;
  std::unique_ptr<Rule> rule_;  // DA or LA: which size is drawn next
  std::vector<std::vector<Site>> heap_;  // per rank: sites for sizes <= it
  // The grains come from decks, each deck the particle list once, shuffled
  // by drawing without replacement; the next deck opens when one is spent.
  std::vector<long long> deck_, deck_size_;
  long long deck_total_ = 0;
  double placed_volume_ = 0.0, list_volume_ = 0.0;

  // No open site takes a size of this rank or above (until a site opens
  // for one); such grains are not drawn, they stay in the deck.
  int blocked_ = 0;
  void new_deck();
  long long total_ = 0, next_report_ = 0;
  std::vector<std::uint8_t> vacant_;     // per placed sphere: 1 a vacancy
  std::vector<Placement> how_;           // per placed sphere
  std::vector<long long> missing_;       // per class: list count not placed
  Random rng_, vacancy_rng_;
  Vec3 centre_;
  double gap_ = 0.0;             // supports of a site lie within this gap
  std::uint32_t next_order_ = 0;
  std::vector<int> near_;        // scratch: neighbours of a new sphere
  std::size_t peak_sites_ = 0, live_sites_ = 0;
  PackingResult res_;
};

// The number of spheres of a usable spec; throws std::invalid_argument
// naming what is wrong otherwise.
long long checked_total(const PackingSpec& spec) {
  if (spec.radius.empty() || spec.radius.size() != spec.count.size())
    throw std::invalid_argument("packing needs one count per size class");
  long long total = 0;
  double rmax = 0.0;
  for (std::size_t k = 0; k < spec.radius.size(); ++k) {
    if (!(spec.radius[k] > 0.0) || !std::isfinite(spec.radius[k]))
      throw std::invalid_argument("sphere radius must be positive and finite");
    if (spec.count[k] < 0)
      throw std::invalid_argument("sphere count must not be negative");
    total += spec.count[k];
    if (spec.count[k] > 0) rmax = std::max(rmax, spec.radius[k]);
  }
  for (int a = 0; a < 3; ++a)
    if (!(spec.hi[a] > spec.lo[a]))
      throw std::invalid_argument("container must have positive extent");
  if (total < 3)
    throw std::invalid_argument("packing needs at least 3 spheres, got " +
                                std::to_string(total));
  if (total > INT32_MAX / 4)
    throw std::invalid_argument("packing supports at most " +
                                std::to_string(INT32_MAX / 4) + " spheres");
  for (int a = 0; a < 3; ++a)
    if (spec.hi[a] - spec.lo[a] < 2.0 * rmax)
      throw std::invalid_argument(
          "container is narrower than the largest sphere (diameter " +
          std::to_string(2.0 * rmax) + ")");
  return total;
}

Packer::Packer(const PackingSpec& spec)
    : spec_(spec),
      grid_(spec.lo, spec.hi, spec.radius,
            std::max<std::size_t>(1u << 20, 4 * [&] {
              long long n = 0;
              for (long long c : spec.count) n += std::max(0LL, c);
              return static_cast<std::size_t>(n);
            }())),
      rng_{spec.seed ^ 0x5eedULL},
      vacancy_rng_{spec.seed ^ 0x7ac4ULL} {
  total_ = checked_total(spec);
  nclass_ = static_cast<int>(spec.radius.size());
  centre_ = 0.5 * (spec.lo + spec.hi);
  asc_.resize(nclass_);
  for (int k = 0; k < nclass_; ++k) asc_[k] = k;
  std::stable_sort(asc_.begin(), asc_.end(), [&](int a, int b) {
    return spec.radius[a] < spec.radius[b];
  });
  rank_.resize(nclass_);
  below_.assign(nclass_, -1);
  for (int i = 0; i < nclass_; ++i) {
    rank_[asc_[i]] = i;
    if (i > 0)
      below_[i] = spec.radius[asc_[i - 1]] < spec.radius[asc_[i]]
                      ? i - 1 : below_[i - 1];
  }
  double rmin = std::numeric_limits<double>::infinity();
  double rmax = 0.0;
  for (int k = 0; k < nclass_; ++k) {
    double r = spec.radius[k];
    volume_.push_back(sphere_volume(2.0 * r));
    if (spec.count[k] > 0) rmin = std::min(rmin, r), rmax = std::max(rmax, r);
  }
  // Supports of a site lie within a finest diameter of each other: every
  // pocket a grain can sit in, and few enough triples to stay fast.
  gap_ = 2.0 * rmin;
  heap_.resize(nclass_);
  front_.assign(nclass_, Front{std::numeric_limits<double>::infinity(),
                               std::numeric_limits<std::uint32_t>::max()});
  // The sizes by rank, for the rule; x: where a size lies between the
  // finest and the coarsest, in ln(r).
  Sizes sizes;
  const double span = std::log(rmax / rmin);
  for (int i = 0; i < nclass_; ++i) {
    const int k = asc_[i];
    sizes.count.push_back(spec.count[k]);
    sizes.volume.push_back(volume_[k]);
    sizes.x.push_back(span > 0.0
        ? std::clamp(std::log(spec.radius[k] / rmin) / span, 0.0, 1.0)
        : 0.0);
    list_volume_ += spec.count[k] * volume_[k];
  }
  rule_ = make_rule(spec.arrangement, sizes, spec.layering);
  res_.placed_per_class.assign(nclass_, 0);
  missing_.assign(nclass_, 0);
  deck_.assign(nclass_, 0);
  deck_size_.assign(nclass_, 0);
}

bool Packer::inside(const Vec3& c, double r) const {
  double slack = spec_.overlap_tolerance * r;
  for (int a = 0; a < 3; ++a)
    if (c[a] - r < spec_.lo[a] - slack || c[a] + r > spec_.hi[a] + slack)
      return false;
  return true;
}

double Packer::key_of(const Vec3& c) const {
  switch (spec_.start) {
    case Start::floor: return c[2] - spec_.lo[2];
    case Start::floor_ceiling:
      return std::min(c[2] - spec_.lo[2], spec_.hi[2] - c[2]);
    case Start::centre:
    case Start::automatic: break;  // pack() resolves automatic
  }
  return (c - centre_).norm();
}

// Distance between a sphere's surface and a wall.
double Packer::wall_gap(int w, const Vec3& c, double r) const {
  int a = wall_axis(w);
  return wall_side(w) == 0 ? c[a] - r - spec_.lo[a] : spec_.hi[a] - c[a] - r;
}

Packer::Geometry Packer::geometry(const Site& s) const {
  Geometry g;
  while (g.spheres < 3 && !is_wall(s.s[g.spheres])) {
    g.sphere[g.spheres] = support(s.s[g.spheres]);
    ++g.spheres;
  }
  if (g.spheres == 3)
    g.frame = face_frame(g.sphere[0].centre, g.sphere[1].centre,
                         g.sphere[2].centre);
  return g;
}

std::optional<Vec3> Packer::position(const Site& s, const Geometry& g,
                                     double r, Placement& how) const {
  const int spheres = g.spheres;
  auto pick = [&](const std::optional<MirrorPair>& m) -> std::optional<Vec3> {
    if (!m) return std::nullopt;
    return s.mirror > 0 ? m->positive : m->negative;
  };
  auto plane = [&](int w, Vec3& point, Vec3& inward) {
    int a = wall_axis(w);
    point = wall_side(w) == 0 ? spec_.lo : spec_.hi;
    inward = Vec3::Zero();
    inward[a] = wall_side(w) == 0 ? 1.0 : -1.0;
  };
  std::optional<Vec3> c;
  if (spheres == 3) {
    const Sphere &a = g.sphere[0], &b = g.sphere[1], &d = g.sphere[2];
    const auto& frame = g.frame;
    if (!frame) return std::nullopt;
    c = pick(trilaterate(*frame, a.radius, b.radius, d.radius, r));
    how = Placement::trilateration;
    if (!c && s.mirror > 0) {
      // Figs. 7-8: a grain too small to touch all three lies in the face
      // plane: at the constriction centre of a nearly equal-sided face,
      // else touching two face spheres (DA the two larger, LA the two
      // smaller).
      auto con = constriction(*frame, a.radius, b.radius, d.radius);
      if (con && r <= con->radius &&
          nearly_equilateral(a.centre, b.centre, d.centre,
                             spec_.equilateral_tolerance)) {
        c = con->centre;
        how = Placement::constriction;
      } else {
        Sphere f[3] = {a, b, d};
        std::sort(f, f + 3, [](const Sphere& x, const Sphere& y) {
          return x.radius > y.radius;
        });
        if (rule_->touches_smaller_pair()) std::swap(f[0], f[2]);
        c = touch_two_in_plane(f[0], f[1], f[2].centre, r);
        how = Placement::touch_two;
      }
    }
  } else if (spheres == 2) {
    Vec3 point, inward;
    plane(s.s[2], point, inward);
    c = pick(touch_two_and_plane(g.sphere[0], g.sphere[1], point, inward, r));
    how = Placement::wall;
  } else if (spheres == 1) {
    int w1 = s.s[1], w2 = s.s[2];
    int a1 = wall_axis(w1), a2 = wall_axis(w2);
    double p1 = wall_side(w1) == 0 ? spec_.lo[a1] : spec_.hi[a1];
    double p2 = wall_side(w2) == 0 ? spec_.lo[a2] : spec_.hi[a2];
    c = pick(touch_one_and_two_planes(g.sphere[0], a1, p1,
                                      wall_side(w1) == 0 ? 1.0 : -1.0, a2, p2,
                                      wall_side(w2) == 0 ? 1.0 : -1.0, r));
    how = Placement::edge;
  } else {
    Vec3 q;
    for (int i = 0; i < 3; ++i) {
      int a = wall_axis(s.s[i]);
      q[a] = wall_side(s.s[i]) == 0 ? spec_.lo[a] + r : spec_.hi[a] - r;
    }
    c = q;
    how = Placement::corner;
  }
  if (!c || !c->allFinite() || !inside(*c, r)) return std::nullopt;
  return c;
}

// A site goes to the heap of the largest size it may take, keyed by the
// position of a grain of that size; a site that holds no grain of that size
// (it would cross a wall, or is too small for Eq. 1) tries the next smaller.
void Packer::push(Site s, int level, const Geometry& g) {
  for (; level >= 0; level = below_[level]) {
    Placement how;
    auto c = position(s, g, spec_.radius[asc_[level]], how);
    if (!c) continue;
    s.key = key_of(*c);
    heap_push(heap_[level], s);
    blocked_ = std::max(blocked_, level + 1);
    refresh_front(level);
    peak_sites_ = std::max(peak_sites_, ++live_sites_);
    return;
  }
}

void Packer::refresh_front(int level) {
  const std::vector<Site>& h = heap_[level];
  front_[level] = h.empty() ? Front{std::numeric_limits<double>::infinity(),
                                    std::numeric_limits<std::uint32_t>::max()}
                            : Front{h.front().key, h.front().order};
}

// A site on which grain k did not fit goes to the heap of the sizes below
// k. (Closing it when even the finest size does not fit there cut the
// attempts per grain from 155 to 57 but left the specimens less uniform:
// Cu 2.5 DA sub-cubes up to 0.383 against 0.372.)
void Packer::demote(const Site& s, int k, const Geometry& g) {
  push(s, below_[rank_[k]], g);
}

bool Packer::pop_lowest(int min_level, Site& s, int& level) {
  level = -1;
  Front best{std::numeric_limits<double>::infinity(),
             std::numeric_limits<std::uint32_t>::max()};
  for (int l = std::max(min_level, 0); l < nclass_; ++l) {
    const Front& f = front_[l];
    if (f.key < best.key || (f.key == best.key && f.order < best.order))
      best = f, level = l;
  }
  if (level < 0 || heap_[level].empty()) return false;
  s = heap_pop(heap_[level]);
  refresh_front(level);
  --live_sites_;
  return true;
}

void Packer::add_site(int a, int b, int c) {
  for (std::int8_t mirror : {std::int8_t{1}, std::int8_t{-1}}) {
    Site s{0.0, next_order_++, {a, b, c}, mirror, -1};
    push(s, nclass_ - 1);
    ++res_.sites;
  }
}

// The sites of a new sphere p: p with every pair of spheres or walls within
// the gap of p and of each other. Triples of earlier spheres were opened by
// the last of them, so each triple is opened once.
void Packer::open_sites(int p) {
  const Vec3 cp = grid_.centre(p);
  const double rp = grid_.radius(p);
  near_.clear();
  grid_.within_gap(cp, rp, gap_, near_);
  near_.erase(std::remove(near_.begin(), near_.end(), p), near_.end());
  std::sort(near_.begin(), near_.end());
  int walls[6], nw = 0;
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side)
      if (wall_gap(wall_code(a, side), cp, rp) < gap_)
        walls[nw++] = wall_code(a, side);
  for (size_t i = 0; i < near_.size(); ++i) {
    Sphere qi = grid_.sphere(near_[i]);
    for (size_t j = i + 1; j < near_.size(); ++j) {
      Sphere qj = grid_.sphere(near_[j]);
      double reach = qi.radius + qj.radius + gap_;
      if ((qi.centre - qj.centre).squaredNorm() < reach * reach)
        add_site(p, near_[i], near_[j]);
    }
    for (int w = 0; w < nw; ++w)
      if (wall_gap(walls[w], qi.centre, qi.radius) < gap_)
        add_site(p, near_[i], walls[w]);
  }
  for (int w1 = 0; w1 < nw; ++w1)
    for (int w2 = w1 + 1; w2 < nw; ++w2)
      if (wall_axis(walls[w1]) != wall_axis(walls[w2]))
        add_site(p, walls[w1], walls[w2]);
}

// A deck is the particle list plus two spheres of each size: the last
// coarse grains drawn may find no room under the lid, and the choice of the
// specimen's spheres then still finds every sphere of the list.
void Packer::new_deck() {
  const bool fresh = deck_total_ == 0;
  for (int k = 0; k < nclass_; ++k) {
    long long n = spec_.count[k] > 0 ? spec_.count[k] + kDeckExtra : 0;
    if (fresh) deck_size_[k] = 0;
    deck_size_[k] += n;
    deck_[k] += n;
    deck_total_ += n;
  }
}

// The next grain, drawn by the rule from the deck among the sizes some open
// site may take (-1: none).
int Packer::draw() {
  long long left[100];
  double spent[100], w[100];
  for (int pass = 0; pass < 2; ++pass) {
    for (int i = 0; i < blocked_; ++i) {
      const int k = asc_[i];
      left[i] = deck_[k];
      spent[i] = deck_size_[k] > 0
          ? static_cast<double>(deck_size_[k] - deck_[k]) / deck_size_[k]
          : 1.0;
    }
    rule_->weigh(DrawState{left, spent, blocked_, placed_volume_ / list_volume_},
                 w);
    double total = 0.0;
    for (int i = 0; i < blocked_; ++i) total += w[i];
    if (total > 0.0) return take_from_deck(w, blocked_, total);
    new_deck();  // this one holds no size that fits: the next deck opens
  }
  return -1;
}

// Draws a rank with probability w[i] / total (i < n, total > 0) and takes a
// grain of that size out of the deck.
int Packer::take_from_deck(const double* w, int n, double total) {
  double pick = rng_.uniform() * total;
  int i = 0;
  for (; i < n - 1; ++i) {
    if (w[i] > 0.0 && pick < w[i]) break;
    pick -= w[i];
  }
  while (w[i] == 0.0) --i;  // rounding at the end of the range
  int k = asc_[i];
  --deck_[k], --deck_total_;
  return k;
}

int Packer::place(const Vec3& c, int k, Placement how) {
  int p = grid_.insert(c, k);
  placed_volume_ += volume_[k];
  vacant_.push_back(0);
  how_.push_back(how);
  report_progress();
  return p;
}

// Offers grain k to site s; places it if it fits, else notes in s the
// sphere that kept it out.
bool Packer::try_site(Site& s, int k, const Geometry& g) {
  ++res_.attempts;
  const double r = spec_.radius[k];
  Placement how;
  auto c = position(s, g, r, how);
  if (!c) return false;
  bool from_hint;
  if (grid_.overlaps(*c, r, spec_.overlap_tolerance, &s.blocker, 1, s.blocker,
                     from_hint))
    return false;
  open_sites(place(*c, k, how));
  return true;
}

// Start centre (section 2.2): the largest sphere at the container centre and
// two companions drawn by the rule (LA's draw starts with the coarsest).
void Packer::first_face() {
  Random rng{spec_.seed};
  int k[3];
  new_deck();
  int largest = nclass_ - 1;
  while (deck_[asc_[largest]] == 0) --largest;
  k[0] = asc_[largest];
  --deck_[k[0]], --deck_total_;
  blocked_ = nclass_;
  k[1] = draw();
  k[2] = draw();
  double r0 = spec_.radius[k[0]], r1 = spec_.radius[k[1]],
         r2 = spec_.radius[k[2]];
  Vec3 c0 = centre_, c1;
  std::optional<Vec3> c2;
  for (int attempt = 0; attempt < 200; ++attempt) {
    Vec3 u = rng.unit_vector();
    c1 = c0 + (r0 + r1) * u;
    Vec3 w = rng.unit_vector();
    w -= w.dot(u) * u;
    if (w.norm() < 1e-6) w = u.unitOrthogonal();
    c2 = touch_two_in_plane(Sphere{c0, r0}, Sphere{c1, r1}, c0 + w, r2);
    if (c2 && inside(c0, r0) && inside(c1, r1) && inside(*c2, r2)) break;
    c2.reset();
  }
  if (!c2)
    throw std::invalid_argument(
        "container is too small for the first face: the largest sphere "
        "(diameter " + std::to_string(2 * r0) + ") and its two companions "
        "must fit around the container centre");
  place(c0, k[0], Placement::first_face);
  place(c1, k[1], Placement::first_face);
  open_sites(place(*c2, k[2], Placement::first_face));
}

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

void Packer::report_progress() {
  if (!spec_.progress || grid_.size() < next_report_) return;
  spec_.progress(grid_.size(), total_);
  next_report_ = grid_.size() + std::max<long long>(total_ / 10, 1);
}

PackingResult Packer::run() {
  grid_.reserve(static_cast<std::size_t>(total_ * 1.2) + 16);
  next_report_ = std::max<long long>(total_ / 10, 1);
  if (spec_.start == Start::centre) first_face();
  // The eight corners are sites (three walls) from the start.
  for (int x = 0; x < 2; ++x)
    for (int y = 0; y < 2; ++y)
      for (int z = 0; z < 2; ++z)
        push(Site{0.0, next_order_++,
                  {wall_code(0, x), wall_code(1, y), wall_code(2, z)}, 1, -1},
             nclass_ - 1);
  // The container is packed full: grains are drawn until no site takes one.
  // A grain drawn that does not fit where it was offered waits for the next
  // site that fits it, so no size is replaced by smaller ones on the spot.
  int pending = -1;
  for (;;) {
    if (pending < 0) pending = draw();
    if (pending < 0) break;  // no open site at all: the container is full
    const int k = pending;
    Site s;
    int level;
    if (!pop_lowest(rank_[k], s, level)) {
      // No open site takes this size: it goes back into the deck, and this
      // size and larger ones wait until a site opens for them.
      ++deck_[k], ++deck_total_;
      blocked_ = rank_[k];
      pending = -1;
      continue;
    }
    Geometry g = geometry(s);
    if (try_site(s, k, g))
      pending = -1;
    else
      demote(s, k, g);
  }
  choose_vacancies();
  // The specimen: its grains in placement order, then the second loop's.
  for (int i = 0; i < grid_.size(); ++i) {
    if (vacant_[i]) continue;
    int k = grid_.sphere_class(i);
    res_.centre.push_back(grid_.centre(i));
    res_.radius.push_back(spec_.radius[k]);
    res_.size_class.push_back(k);
    res_.placement.push_back(how_[i]);
    ++res_.placed_per_class[k];
    ++res_.placed_by[static_cast<int>(how_[i])];
  }
  if (spec_.fill_pores) second_loop();
  res_.unplaced_per_class = missing_;
  for (int i = 0; i < grid_.size(); ++i)
    res_.packed_volume += volume_[grid_.sphere_class(i)];
  for (int i = 0; i < grid_.size(); ++i)
    if (vacant_[i] == 1) {
      ++res_.vacancies;
      res_.vacancy_volume += volume_[grid_.sphere_class(i)];
    }
  res_.peak_bytes = grid_.memory_bytes() + peak_sites_ * sizeof(Site) +
                    vacant_.capacity() + how_.capacity() * sizeof(Placement) +
                    res_.centre.capacity() * sizeof(Vec3) +
                    res_.radius.capacity() * sizeof(double) +
                    res_.size_class.capacity() * sizeof(int) +
                    res_.placement.capacity() * sizeof(Placement);
  if (spec_.progress) spec_.progress(grid_.size(), total_);
  return std::move(res_);
}

}  // namespace

Start default_start(Arrangement a) {
  return make_rule(a, Sizes{}, kDefaultLayering)->default_start();
}

namespace {
double unplaced_volume(const PackingResult& r, const PackingSpec& spec) {
  double v = 0.0;
  for (std::size_t k = 0; k < r.unplaced_per_class.size(); ++k)
    v += r.unplaced_per_class[k] * sphere_volume(2.0 * spec.radius[k]);
  return v;
}
PackingResult pack_from(const PackingSpec& spec) {
  PackingResult r = Packer(spec).run();
  r.start = spec.start;
  return r;
}
}  // namespace

PackingResult pack(const PackingSpec& spec) {
  if (spec.start != Start::automatic) return pack_from(spec);
  PackingSpec s = spec;
  s.start = Start::floor_ceiling;
  PackingResult two = pack_from(s);
  if (two.unplaced() == 0) return two;
  s.start = Start::floor;
  PackingResult one = pack_from(s);
  if (!(unplaced_volume(one, s) < unplaced_volume(two, s))) return two;
  one.unplaced_with_two_fronts = two.unplaced();
  return one;
}

}  // namespace fabric
