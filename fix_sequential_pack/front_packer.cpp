#include "front_packer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "sphere_grid.h"

namespace fabric {

std::string to_string(Arrangement a) {
  return a == Arrangement::discrete ? "discrete" : "layerwise";
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

struct Face {
  int v[3];  // sphere indices; right-hand normal points to the open side
};

// What the placements on one face share, computed once per face (a DA face
// is offered up to one size per class in turn): its spheres, its frame and,
// when first needed, its Fig. 7-8 fallback data.
struct FaceData {
  int index;  // in faces_
  Sphere s[3];
  // Pore side: the vertex of the face that the face's third sphere was
  // placed on that is not on this face (-1: none). A sphere put behind the
  // face most often overlaps it, so it is tested first.
  int behind = -1;
  std::optional<FaceFrame> frame;
  bool fallback_known = false;
  std::optional<Constriction> con;
  bool equilateral = false;  // nearly_equilateral(), known once con is
  bool equilateral_known = false;
  int pair[3];  // Fig. 8: touch s[pair[0]] and s[pair[1]], towards s[pair[2]]
};

constexpr double kDrawExponent = 4.0;

// How many of a fixed set of distances lie below x: the count that
// std::lower_bound gives on the sorted set, without sorting it. The values
// are grouped into buckets by a function of their value that never
// decreases, so the values in buckets below x's are all below x, those above
// all not, and only x's own bucket is compared one by one.
class CountBelow {
 public:
  CountBelow() = default;
  explicit CountBelow(std::vector<double> v) : n_(v.size()) {
    double hi = 0.0;
    bool plain = !v.empty();
    for (double x : v) {
      if (!(x >= 0.0) || !std::isfinite(x)) plain = false;
      hi = std::max(hi, x);
    }
    scale_ = kBuckets / hi;
    if (!plain || !(hi > 0.0) || !std::isfinite(scale_)) {
      std::sort(v.begin(), v.end());  // anything odd: a plain sorted list
      sorted_ = std::move(v);
      return;
    }
    start_.assign(kBuckets + 1, 0);
    for (double x : v) ++start_[bucket(x) + 1];
    for (size_t b = 0; b < kBuckets; ++b) start_[b + 1] += start_[b];
    bucketed_.resize(n_);
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (double x : v) bucketed_[fill[bucket(x)]++] = x;
  }
  std::ptrdiff_t operator()(double x) const {
    if (start_.empty())
      return std::lower_bound(sorted_.begin(), sorted_.end(), x) -
             sorted_.begin();
    if (!(x > 0.0)) return 0;  // every value is >= 0 (or x is NaN)
    size_t b = bucket(x);
    std::ptrdiff_t count = start_[b];
    for (size_t i = start_[b]; i < start_[b + 1]; ++i)
      count += bucketed_[i] < x;
    return count;
  }
  size_t size() const { return n_; }

 private:
  static constexpr size_t kBuckets = 8192;
  size_t bucket(double x) const {  // x >= 0; never decreases with x
    double t = x * scale_;
    return t < static_cast<double>(kBuckets - 1) ? static_cast<size_t>(t)
                                                 : kBuckets - 1;
  }
  size_t n_ = 0;
  double scale_ = 0.0;
  std::vector<double> bucketed_;      // the values, bucket by bucket
  std::vector<std::uint32_t> start_;  // first index of each bucket; empty:
  std::vector<double> sorted_;        // the fallback, sorted
};

// The open faces, nearest the container centre first: the order of
// std::priority_queue<Item, std::vector<Item>, std::greater<Item>> (distance,
// then face index; every item is distinct, so any correct priority queue
// gives the same sequence). The items are split into shells of distance, a
// heap each; no shell holds a larger distance than a later one, so the first
// shell that holds any has the least item on top. The heaps stay small.
class FrontQueue {
 public:
  using Item = std::pair<double, size_t>;
  FrontQueue(double max_dist, size_t shells)
      : shell_(std::max<size_t>(shells, 1)),
        per_dist_(static_cast<double>(shell_.size()) / max_dist) {
    if (!(per_dist_ > 0.0) || !std::isfinite(per_dist_)) per_dist_ = 0.0;
  }
  bool empty() const { return size_ == 0; }
  void push(const Item& it) {
    size_t s = shell(it.first);
    shell_[s].push_back(it);
    std::push_heap(shell_[s].begin(), shell_[s].end(), std::greater<Item>());
    first_ = std::min(first_, s);
    ++size_;
  }
  const Item& top() {  // not empty()
    while (shell_[first_].empty()) ++first_;
    return shell_[first_].front();
  }
  void pop() {  // after top()
    std::vector<Item>& h = shell_[first_];
    std::pop_heap(h.begin(), h.end(), std::greater<Item>());
    h.pop_back();
    --size_;
  }

 private:
  // Never decreases with d (NaN: the last shell).
  size_t shell(double d) const {
    double t = d * per_dist_;
    if (t < 1.0) return 0;  // also d < 0
    return t < static_cast<double>(shell_.size() - 1) ? static_cast<size_t>(t)
                                                      : shell_.size() - 1;
  }
  std::vector<std::vector<Item>> shell_;  // a heap each
  double per_dist_;
  size_t first_ = 0;  // no shell before it holds an item
  size_t size_ = 0;
};

enum FaceState : std::uint8_t { kOpen, kFilled, kFailed };

// Which side of a face the sphere goes to.
enum class Side { open, pore };

class FrontPacker {
 public:
  explicit FrontPacker(const PackingSpec& spec);
  PackingResult run();

 private:
  void place_first_face();
  bool fill_face(int face, Side side);
  bool try_place(const Face& f, FaceData& d, int size_class, Side side);
  bool try_fallback(const Face& f, FaceData& d, int size_class, Side side);
  bool place_if_free(const Face& f, const FaceData& d, const Vec3& c,
                     int size_class, Placement how, Side side);
  void add_sphere(const Vec3& c, int size_class, Placement how,
                  int parent_face);
  void open_faces(const Face& parent, int p, Placement how);
  bool inside(const Vec3& c, double r) const;
  std::optional<Vec3> against_wall(const Sphere* s, const Vec3& cand,
                                   double r) const;
  int largest_left();
  int take_random_left(Random& rng);
  void report_progress();
  void skip_class(int k);
  bool behind_target();
  double swept_volume(double radius) const;

  const PackingSpec& spec_;
  SphereGrid grid_;
  std::vector<Face> faces_;
  std::vector<std::uint8_t> state_;
  std::vector<long long> left_;
  std::vector<int> by_size_;  // size classes, largest first
  std::vector<size_t> smaller_from_;  // per class: first smaller in by_size_
  size_t first_left_ = 0;     // by_size_[first_left_] is the largest left
  long long total_left_ = 0, total_ = 0, next_report_ = 0;
  PackingResult res_;
  Random rng_;
  Vec3 centre_;
  double reach_ = 0.0;          // distance of the farthest face taken so far
  double placed_volume_ = 0.0;
  double target_density_ = 0.0;  // solid volume of the list / container
  double margin_ = 0.0;          // volume-weighted mean radius of the list
  CountBelow sample_dist_;  // centre distances of a lattice
  std::vector<double> draw_weight_, volume_;  // per class
  // take_random_left(): left_ * draw_weight_ per class in by_size_ order and
  // their sum, valid while !draw_stale_ (set whenever left_ changes)
  std::vector<double> draw_left_;
  double draw_total_ = 0.0;
  bool draw_stale_ = true;
  // Where to look first for an overlap: the sphere that last stopped a
  // placement, and per sphere, the last one that the full search found
  // stopping a placement on a face of that sphere.
  int blocker_ = -1;
  std::vector<int32_t> vertex_blocker_;
  std::vector<int32_t> parent_face_;  // per sphere: the face it went on
  // swept_volume(reach_ + margin_) for reach_ == swept_for_reach_
  double swept_for_reach_ = std::numeric_limits<double>::quiet_NaN();
  double swept_ = 0.0;
};

FrontPacker::FrontPacker(const PackingSpec& spec)
    : spec_(spec),
      grid_(spec.lo, spec.hi, spec.radius,
            // a few cells per sphere is plenty; never less than 1 Mi cells
            std::max<std::size_t>(1u << 20, 4 * [&] {
              long long n = 0;
              for (long long c : spec.count) n += c;
              return static_cast<std::size_t>(n);
            }())),
      left_(spec.count),
      rng_{spec.seed ^ 0x5eedULL} {
  if (spec.radius.empty() || spec.radius.size() != spec.count.size())
    throw std::invalid_argument("packing needs one count per size class");
  for (size_t k = 0; k < spec.radius.size(); ++k) {
    if (!(spec.radius[k] > 0.0) || !std::isfinite(spec.radius[k]))
      throw std::invalid_argument("sphere radius must be positive and finite");
    if (spec.count[k] < 0)
      throw std::invalid_argument("sphere count must not be negative");
    total_ += spec.count[k];
  }
  for (int a = 0; a < 3; ++a)
    if (!(spec.hi[a] > spec.lo[a]))
      throw std::invalid_argument("container must have positive extent");
  if (total_ < 3)
    throw std::invalid_argument("packing needs at least 3 spheres, got " +
                                std::to_string(total_));
  if (total_ > INT32_MAX / 4)
    throw std::invalid_argument("packing supports at most " +
                                std::to_string(INT32_MAX / 4) + " spheres");
  total_left_ = total_;
  centre_ = 0.5 * (spec.lo + spec.hi);
  for (double r : spec.radius) {
    draw_weight_.push_back(std::pow(r, kDrawExponent));
    volume_.push_back(4.0 / 3.0 * M_PI * r * r * r);
  }
  double vol = 0.0, r4 = 0.0;
  for (size_t k = 0; k < spec.radius.size(); ++k) {
    double r = spec.radius[k];
    vol += spec.count[k] * 4.0 / 3.0 * M_PI * r * r * r;
    r4 += spec.count[k] * r * r * r * r;
  }
  margin_ = r4 / (vol * 3.0 / (4.0 * M_PI));
  target_density_ = vol / (spec.hi - spec.lo).prod();
  // The container volume within a distance of its centre, from a lattice.
  const int n = 48;
  Vec3 ext = spec.hi - spec.lo;
  // Per axis, the lattice point minus the centre (q - centre_ of the point
  // q = lo + ((i + 0.5) / n * ext[0], ...), a component at a time).
  double offset[3][n];
  for (int a = 0; a < 3; ++a)
    for (int i = 0; i < n; ++i)
      offset[a][i] = (spec.lo[a] + (i + 0.5) / n * ext[a]) - centre_[a];
  std::vector<double> dist;
  dist.reserve(n * n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        dist.push_back(Vec3(offset[0][i], offset[1][j], offset[2][k]).norm());
  sample_dist_ = CountBelow(std::move(dist));
  by_size_.resize(spec.radius.size());
  for (size_t k = 0; k < by_size_.size(); ++k) by_size_[k] = static_cast<int>(k);
  std::stable_sort(by_size_.begin(), by_size_.end(), [&](int a, int b) {
    return spec.radius[a] > spec.radius[b];
  });
  draw_left_.assign(by_size_.size(), 0.0);
  smaller_from_.assign(spec.radius.size(), by_size_.size());
  for (size_t k = 0; k < spec.radius.size(); ++k)
    for (size_t i = 0; i < by_size_.size(); ++i)
      if (spec.radius[by_size_[i]] < spec.radius[k]) {
        smaller_from_[k] = i;
        break;
      }
  res_.placed_per_class.assign(spec.radius.size(), 0);
  res_.skipped_per_class.assign(spec.radius.size(), 0);
  grid_.reserve(total_);
  vertex_blocker_.reserve(total_);
  parent_face_.reserve(total_);
  res_.centre.reserve(total_);
  res_.radius.reserve(total_);
  res_.size_class.reserve(total_);
  res_.placement.reserve(total_);
  faces_.reserve(3 * total_ + 2);
  state_.reserve(3 * total_ + 2);
}

int FrontPacker::largest_left() {
  while (first_left_ < by_size_.size() && left_[by_size_[first_left_]] == 0)
    ++first_left_;
  return first_left_ < by_size_.size() ? by_size_[first_left_] : -1;
}

int FrontPacker::take_random_left(Random& rng) {
  // Weighted by the volume left in each class, so every class advances at
  // its mass share and the specimen is homogeneous by mass. The weights and
  // their total (summed in this order) are kept until a count changes.
  if (draw_stale_) {
    double total = 0.0;
    for (size_t i = 0; i < by_size_.size(); ++i) {
      int k = by_size_[i];
      draw_left_[i] = left_[k] * draw_weight_[k];
      total += draw_left_[i];
    }
    draw_total_ = total;
    draw_stale_ = false;
  }
  double pick = rng.uniform() * draw_total_;
  for (size_t i = 0; i < by_size_.size(); ++i) {
    int k = by_size_[i];
    double w = draw_left_[i];
    if (left_[k] > 0 && pick < w) return k;
    pick -= w;
  }
  return largest_left();
}

bool FrontPacker::inside(const Vec3& c, double r) const {
  double slack = spec_.overlap_tolerance * r;
  for (int a = 0; a < 3; ++a)
    if (c[a] - r < spec_.lo[a] - slack || c[a] + r > spec_.hi[a] + slack)
      return false;
  return true;
}

void FrontPacker::add_sphere(const Vec3& c, int k, Placement how,
                             int parent_face) {
  grid_.insert(c, k);
  vertex_blocker_.push_back(-1);
  parent_face_.push_back(parent_face);
  res_.centre.push_back(c);
  res_.radius.push_back(spec_.radius[k]);
  res_.size_class.push_back(k);
  res_.placement.push_back(how);
  ++res_.placed_per_class[k];
  ++res_.placed_by[static_cast<int>(how)];
  --left_[k];
  --total_left_;
  draw_stale_ = true;
  placed_volume_ += volume_[k];
}

void FrontPacker::place_first_face() {
  Random rng{spec_.seed};
  // Section 2.2: the largest sphere first, at the container centre; LA takes
  // the next largest as companions, DA two drawn at random by number.
  int k[3];
  k[0] = largest_left();
  --left_[k[0]], --total_left_;
  draw_stale_ = true;
  for (int i = 1; i < 3; ++i) {
    k[i] = spec_.arrangement == Arrangement::layerwise ? largest_left()
                                                        : take_random_left(rng);
    --left_[k[i]], --total_left_;
    draw_stale_ = true;
  }
  for (int i = 0; i < 3; ++i) ++left_[k[i]], ++total_left_;
  draw_stale_ = true;

  double r0 = spec_.radius[k[0]], r1 = spec_.radius[k[1]],
         r2 = spec_.radius[k[2]];
  Vec3 c0 = 0.5 * (spec_.lo + spec_.hi), c1;
  std::optional<Vec3> c2;
  // A random orientation; in a tight container, the first of a few that fits.
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
  add_sphere(c0, k[0], Placement::first_face, -1);
  add_sphere(c1, k[1], Placement::first_face, -1);
  add_sphere(*c2, k[2], Placement::first_face, -1);
  // The first face is open on both sides.
  faces_.push_back(Face{{0, 1, 2}});
  faces_.push_back(Face{{0, 2, 1}});
  state_.assign(2, kOpen);
}

void FrontPacker::open_faces(const Face& parent, int p, Placement how) {
  const Vec3 a = grid_.centre(parent.v[0]), b = grid_.centre(parent.v[1]),
             c = grid_.centre(parent.v[2]);
  const Vec3 parent_normal = (b - a).cross(c - a);
  const Vec3 cp = grid_.centre(p);
  for (int e = 0; e < 3; ++e) {
    int u = parent.v[e], v = parent.v[(e + 1) % 3], w = parent.v[(e + 2) % 3];
    Vec3 cu = grid_.centre(u), cv = grid_.centre(v);
    Vec3 n = (cv - cu).cross(cp - cu);
    // A sphere on top of the face: the new faces open away from the opposite
    // vertex. A sphere in the face plane: they open to the parent's side.
    bool flip = how == Placement::trilateration || how == Placement::wall
                    ? n.dot(grid_.centre(w) - cu) > 0.0
                    : n.dot(parent_normal) < 0.0;
    faces_.push_back(flip ? Face{{v, u, p}} : Face{{u, v, p}});
    state_.push_back(kOpen);
  }
  res_.faces = static_cast<long long>(faces_.size());
}

// A sphere whose Eq. (1) position crosses a wall is moved to touch that wall
// and two of the face spheres instead (the wall stands in for the third):
// without this the layer along the walls stays much looser than the bulk.
std::optional<Vec3> FrontPacker::against_wall(const Sphere* s, const Vec3& cand,
                                              double r) const {
  // The wall crossed the most.
  int axis = 0, sign = 0;
  double worst = 0.0;
  for (int a = 0; a < 3; ++a) {
    double below = spec_.lo[a] - (cand[a] - r), above = cand[a] + r - spec_.hi[a];
    if (below > worst) worst = below, axis = a, sign = +1;
    if (above > worst) worst = above, axis = a, sign = -1;
  }
  if (sign == 0) return std::nullopt;
  Vec3 inward = Vec3::Zero();
  inward[axis] = sign;
  Vec3 point = sign > 0 ? spec_.lo : spec_.hi;
  std::optional<Vec3> best;
  for (int e = 0; e < 3; ++e) {
    const Sphere &a = s[e], &b = s[(e + 1) % 3], &c = s[(e + 2) % 3];
    auto m = touch_two_and_plane(a, b, point, inward, r);
    if (!m) continue;
    for (const Vec3& q : {m->positive, m->negative}) {
      double gap = (q - c.centre).norm() - (r + c.radius);
      if (gap < -spec_.overlap_tolerance * std::min(r, c.radius) || !inside(q, r))
        continue;
      if (!best || (q - cand).squaredNorm() < (*best - cand).squaredNorm())
        best = q;
    }
  }
  return best;
}

bool FrontPacker::try_place(const Face& f, FaceData& d, int k, Side side) {
  ++res_.attempts;
  const double r = spec_.radius[k];
  std::optional<MirrorPair> m;
  if (d.frame)
    m = trilaterate(*d.frame, d.s[0].radius, d.s[1].radius, d.s[2].radius, r);
  if (!m) return try_fallback(f, d, k, side);
  // Eq. (1), the common case.
  const Vec3& cand = side == Side::open ? m->positive : m->negative;
  if (!inside(cand, r)) {
    if (side != Side::open) return false;
    auto w = against_wall(d.s, cand, r);
    return w && place_if_free(f, d, *w, k, Placement::wall, side);
  }
  return place_if_free(f, d, cand, k, Placement::trilateration, side);
}

// Figs. 7-8: a sphere too small to touch all three.
bool FrontPacker::try_fallback(const Face& f, FaceData& d, int k, Side side) {
  const double r = spec_.radius[k];
  const Sphere* s = d.s;
  if (!d.fallback_known) {
    d.fallback_known = true;
    if (d.frame)
      d.con = constriction(*d.frame, s[0].radius, s[1].radius, s[2].radius);
    int o[3] = {0, 1, 2};
    std::sort(o, o + 3, [&](int x, int y) { return s[x].radius > s[y].radius; });
    // DA touches the two larger spheres, LA the two smaller.
    d.pair[0] = o[0], d.pair[1] = o[1], d.pair[2] = o[2];
    if (spec_.arrangement == Arrangement::layerwise)
      d.pair[0] = o[1], d.pair[1] = o[2], d.pair[2] = o[0];
  }
  if (d.con && r <= d.con->radius && !d.equilateral_known) {
    d.equilateral_known = true;
    d.equilateral = nearly_equilateral(s[0].centre, s[1].centre, s[2].centre,
                                       spec_.equilateral_tolerance);
  }
  Vec3 cand;
  Placement how;
  if (d.con && r <= d.con->radius && d.equilateral) {
    cand = d.con->centre;
    how = Placement::constriction;
  } else {
    auto t = touch_two_in_plane(s[d.pair[0]], s[d.pair[1]],
                                s[d.pair[2]].centre, r);
    if (!t) return false;
    cand = *t;
    how = Placement::touch_two;
  }
  if (!inside(cand, r)) return false;
  return place_if_free(f, d, cand, k, how, side);
}

bool FrontPacker::place_if_free(const Face& f, const FaceData& d,
                                const Vec3& cand, int k, Placement how,
                                Side side) {
  const double r = spec_.radius[k];
  // Hints only: which sphere is tested first changes no answer.
  const int hint[5] = {d.behind, blocker_, vertex_blocker_[f.v[0]],
                       vertex_blocker_[f.v[1]], vertex_blocker_[f.v[2]]};
  int found;
  bool from_hint;
  if (grid_.overlaps(cand, r, spec_.overlap_tolerance, hint, 5, found,
                     from_hint)) {
    blocker_ = found;
    if (!from_hint)
      for (int v : f.v) vertex_blocker_[v] = found;
    return false;
  }
  int p = grid_.size();
  add_sphere(cand, k, how, d.index);
  // A sphere that went into the pore behind a face opens no new front.
  if (side == Side::open || how != Placement::trilateration)
    open_faces(f, p, how);
  return true;
}

// The arrangement rule: which sizes a face is offered, in which order.
bool FrontPacker::fill_face(int face, Side side) {
  int largest = largest_left();
  if (largest < 0) return false;
  const Face& f = faces_[face];
  FaceData d;
  d.index = face;
  for (int i = 0; i < 3; ++i) d.s[i] = grid_.sphere(f.v[i]);
  if (side == Side::pore && parent_face_[f.v[2]] >= 0)
    for (int q : faces_[parent_face_[f.v[2]]].v)
      if (q != f.v[0] && q != f.v[1]) d.behind = q;
  d.frame = face_frame(d.s[0].centre, d.s[1].centre, d.s[2].centre);
  if (spec_.arrangement == Arrangement::layerwise)
    return try_place(f, d, largest, side);
  // DA: the next sphere of a random sequence (drawn by volume), then, while
  // the specimen is behind its target density, every smaller size.
  int drawn = take_random_left(rng_);
  if (try_place(f, d, drawn, side)) return true;
  if (!behind_target()) return false;
  // The sizes after `drawn` in by_size_ that are smaller (sizes as large as
  // `drawn` are never retried), each radius once.
  double failed_radius = spec_.radius[drawn];
  for (size_t i = std::max(first_left_, smaller_from_[drawn]);
       i < by_size_.size(); ++i) {
    int k = by_size_[i];
    if (left_[k] == 0 || spec_.radius[k] == failed_radius) continue;
    if (try_place(f, d, k, side)) return true;
    failed_radius = spec_.radius[k];
  }
  return false;
}

double FrontPacker::swept_volume(double radius) const {
  return (spec_.hi - spec_.lo).prod() * sample_dist_(radius) /
         static_cast<double>(sample_dist_.size());
}

// The density control: the rule's retries (DA: smaller sizes, LA: reopening
// closed faces) are spent only while the spheres placed so far hold less
// than the target solid fraction of the container volume the front swept.
bool FrontPacker::behind_target() {
  if (!(reach_ == swept_for_reach_)) {
    swept_for_reach_ = reach_;
    swept_ = swept_volume(reach_ + margin_);
  }
  return placed_volume_ < target_density_ * swept_;
}

void FrontPacker::skip_class(int k) {
  res_.skipped_per_class[k] += left_[k];
  total_left_ -= left_[k];
  left_[k] = 0;
  draw_stale_ = true;
}

void FrontPacker::report_progress() {
  if (!spec_.progress || res_.placed() < next_report_) return;
  spec_.progress(res_.placed(), total_);
  next_report_ = res_.placed() + std::max<long long>(total_ / 10, 1);
}

PackingResult FrontPacker::run() {
  place_first_face();
  // Main loop: the open face nearest the container centre first, so the
  // front grows as a compact ball out to the walls.
  using Item = FrontQueue::Item;
  // Shells a quarter of the finest radius thick (no more than spheres, and
  // at most 2^16).
  const double max_dist = 0.5 * (spec_.hi - spec_.lo).norm();
  const double finest = spec_.radius[by_size_.back()];
  const double shells = std::min({65536.0, static_cast<double>(total_),
                                  4.0 * max_dist / finest});
  FrontQueue front(max_dist, static_cast<size_t>(std::max(1.0, shells)));
  std::vector<Item> parked;  // LA: faces closed for the current size
  size_t queued = 0;
  auto enqueue_new_faces = [&] {
    for (; queued < faces_.size(); ++queued) {
      const Face& f = faces_[queued];
      Vec3 centroid = (grid_.centre(f.v[0]) + grid_.centre(f.v[1]) +
                       grid_.centre(f.v[2])) / 3.0;
      front.push({(centroid - centre_).norm(), queued});
    }
  };
  enqueue_new_faces();
  int current = largest_left();
  // Only faces near the front reopen: deep inside, a layer stays as it grew.
  auto reopen = [&](std::vector<Item>& parked, FrontQueue& q) {
    double depth = 2.0 * spec_.radius[by_size_.front()];
    for (const Item& it : parked)
      if (it.first > reach_ - depth) q.push(it);
    parked.clear();
  };
  while (total_left_ > 0) {
    if (front.empty()) {
      if (parked.empty()) break;  // all faces closed
      // LA: no open face takes the current size: set it aside.
      skip_class(current);
      current = largest_left();
      reopen(parked, front);
      continue;
    }
    auto [dist, f] = front.top();
    front.pop();
    reach_ = std::max(reach_, dist);
    bool ok = fill_face(static_cast<int>(f), Side::open);
    state_[f] = ok ? kFilled : kFailed;
    if (ok) {
      enqueue_new_faces();
      report_progress();
    } else if (spec_.arrangement == Arrangement::layerwise && behind_target()) {
      parked.push_back({dist, f});
    }
    if (spec_.arrangement == Arrangement::layerwise && largest_left() != current) {
      // A smaller size is current: parked faces reopen.
      current = largest_left();
      reopen(parked, front);
    }
  }
  // Second loop (DA): the spheres left go into the pores behind the faces
  // and into the constrictions; new faces this opens are filled in turn.
  if (spec_.arrangement == Arrangement::discrete && spec_.fill_pores) {
    reach_ = std::numeric_limits<double>::infinity();
    size_t main_loop_faces = faces_.size();
    for (size_t i = 0; i < faces_.size() && total_left_ > 0; ++i) {
      // A face that closed without a sphere gets its open side again first
      // (with reach_ infinite every smaller size is tried), then the pore.
      bool placed = false;
      if (i < main_loop_faces && state_[i] == kFailed)
        placed = fill_face(static_cast<int>(i), Side::open);
      if (!placed)
        placed = fill_face(static_cast<int>(i), i < main_loop_faces ? Side::pore : Side::open);
      if (placed) {
        res_.placed_in_second_loop++;
        state_[i] = kFilled;
      }
      report_progress();
    }
  }
  res_.peak_bytes = grid_.memory_bytes() + faces_.capacity() * sizeof(Face) +
                    vertex_blocker_.capacity() * sizeof(int32_t) +
                    parent_face_.capacity() * sizeof(int32_t) +
                    state_.capacity() +
                    res_.centre.capacity() * sizeof(Vec3) +
                    res_.radius.capacity() * sizeof(double) +
                    res_.size_class.capacity() * sizeof(int) +
                    res_.placement.capacity() * sizeof(Placement);
  if (spec_.progress) spec_.progress(res_.placed(), total_);
  return std::move(res_);
}

}  // namespace

PackingResult pack(const PackingSpec& spec) {
  FrontPacker packer(spec);
  return packer.run();
}

}  // namespace fabric
