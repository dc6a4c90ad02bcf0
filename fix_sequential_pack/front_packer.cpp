#include "front_packer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
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

constexpr double kDrawExponent = 4.0;

enum FaceState : std::uint8_t { kOpen, kFilled, kFailed };

// Which side of a face the sphere goes to.
enum class Side { open, pore };

class FrontPacker {
 public:
  explicit FrontPacker(const PackingSpec& spec);
  PackingResult run();

 private:
  void place_first_face();
  bool fill_face(const Face& f, Side side);
  bool try_place(const Face& f, int size_class, Side side);
  void add_sphere(const Vec3& c, int size_class, Placement how);
  void open_faces(const Face& parent, int p, Placement how);
  bool inside(const Vec3& c, double r) const;
  std::optional<Vec3> against_wall(const Sphere* s, const Vec3& cand,
                                   double r) const;
  int largest_left();
  int take_random_left(Random& rng);
  void report_progress();
  void run_layerwise();
  void skip_class(int k);
  bool behind_target() const;
  double swept_volume(double radius) const;

  const PackingSpec& spec_;
  SphereGrid grid_;
  std::vector<Face> faces_;
  std::vector<std::uint8_t> state_;
  std::vector<long long> left_;
  std::vector<int> by_size_;  // size classes, largest first
  size_t first_left_ = 0;     // by_size_[first_left_] is the largest left
  long long total_left_ = 0, total_ = 0, next_report_ = 0;
  PackingResult res_;
  Random rng_;
  Vec3 centre_;
  double reach_ = 0.0;          // distance of the farthest face taken so far
  double placed_volume_ = 0.0;
  double target_density_ = 0.0;  // solid volume of the list / container
  double margin_ = 0.0;          // volume-weighted mean radius of the list
  std::vector<double> sample_dist_;  // sorted centre distances of a lattice
  std::vector<double> draw_weight_, volume_;  // per class
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
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        Vec3 q = spec.lo + Vec3((i + 0.5) / n * ext[0], (j + 0.5) / n * ext[1],
                                (k + 0.5) / n * ext[2]);
        sample_dist_.push_back((q - centre_).norm());
      }
  std::sort(sample_dist_.begin(), sample_dist_.end());
  by_size_.resize(spec.radius.size());
  for (size_t k = 0; k < by_size_.size(); ++k) by_size_[k] = static_cast<int>(k);
  std::stable_sort(by_size_.begin(), by_size_.end(), [&](int a, int b) {
    return spec.radius[a] > spec.radius[b];
  });
  res_.placed_per_class.assign(spec.radius.size(), 0);
  res_.skipped_per_class.assign(spec.radius.size(), 0);
  grid_.reserve(total_);
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
  // its mass share and the specimen is homogeneous by mass.
  double total = 0.0;
  for (int k : by_size_) total += left_[k] * draw_weight_[k];
  double pick = rng.uniform() * total;
  for (int k : by_size_) {
    double w = left_[k] * draw_weight_[k];
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

void FrontPacker::add_sphere(const Vec3& c, int k, Placement how) {
  grid_.insert(c, spec_.radius[k], k);
  res_.centre.push_back(c);
  res_.radius.push_back(spec_.radius[k]);
  res_.size_class.push_back(k);
  res_.placement.push_back(how);
  ++res_.placed_per_class[k];
  ++res_.placed_by[static_cast<int>(how)];
  --left_[k];
  --total_left_;
  placed_volume_ += volume_[k];
}

void FrontPacker::place_first_face() {
  Random rng{spec_.seed};
  // Section 2.2: the largest sphere first, at the container centre; LA takes
  // the next largest as companions, DA two drawn at random by number.
  int k[3];
  k[0] = largest_left();
  --left_[k[0]], --total_left_;
  for (int i = 1; i < 3; ++i) {
    k[i] = spec_.arrangement == Arrangement::layerwise ? largest_left()
                                                        : take_random_left(rng);
    --left_[k[i]], --total_left_;
  }
  for (int i = 0; i < 3; ++i) ++left_[k[i]], ++total_left_;

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
  add_sphere(c0, k[0], Placement::first_face);
  add_sphere(c1, k[1], Placement::first_face);
  add_sphere(*c2, k[2], Placement::first_face);
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

bool FrontPacker::try_place(const Face& f, int k, Side side) {
  ++res_.attempts;
  const double r = spec_.radius[k];
  const Sphere s[3] = {grid_.sphere(f.v[0]), grid_.sphere(f.v[1]),
                       grid_.sphere(f.v[2])};
  Vec3 cand;
  Placement how;
  if (auto m = trilaterate(s[0], s[1], s[2], r)) {
    cand = side == Side::open ? m->positive : m->negative;
    how = Placement::trilateration;
  } else {
    // Figs. 7-8: too small to touch all three.
    auto con = constriction(s[0], s[1], s[2]);
    if (con && r <= con->radius &&
        nearly_equilateral(s[0].centre, s[1].centre, s[2].centre,
                           spec_.equilateral_tolerance)) {
      cand = con->centre;
      how = Placement::constriction;
    } else {
      int o[3] = {0, 1, 2};
      std::sort(o, o + 3, [&](int x, int y) { return s[x].radius > s[y].radius; });
      // DA touches the two larger spheres, LA the two smaller.
      int i = o[0], j = o[1], other = o[2];
      if (spec_.arrangement == Arrangement::layerwise) i = o[1], j = o[2], other = o[0];
      auto t = touch_two_in_plane(s[i], s[j], s[other].centre, r);
      if (!t) return false;
      cand = *t;
      how = Placement::touch_two;
    }
  }
  if (!inside(cand, r)) {
    if (how != Placement::trilateration || side != Side::open) return false;
    auto w = against_wall(s, cand, r);
    if (!w) return false;
    cand = *w;
    how = Placement::wall;
  }
  if (grid_.overlaps(cand, r, spec_.overlap_tolerance)) return false;
  int p = grid_.size();
  add_sphere(cand, k, how);
  // A sphere that went into the pore behind a face opens no new front.
  if (side == Side::open || how != Placement::trilateration)
    open_faces(f, p, how);
  return true;
}

// The arrangement rule: which sizes a face is offered, in which order.
bool FrontPacker::fill_face(const Face& f, Side side) {
  int largest = largest_left();
  if (largest < 0) return false;
  if (spec_.arrangement == Arrangement::layerwise)
    return try_place(f, largest, side);
  // DA: the next sphere of a random sequence (drawn by volume), then, while
  // the specimen is behind its target density, every smaller size.
  int drawn = take_random_left(rng_);
  if (try_place(f, drawn, side)) return true;
  if (!behind_target()) return false;
  double failed_radius = spec_.radius[drawn];
  for (size_t i = first_left_; i < by_size_.size(); ++i) {
    if (spec_.radius[by_size_[i]] > spec_.radius[drawn]) continue;
    if (by_size_[i] == drawn) continue;
    int k = by_size_[i];
    if (left_[k] == 0 || spec_.radius[k] == failed_radius) continue;
    if (try_place(f, k, side)) return true;
    failed_radius = spec_.radius[k];
  }
  return false;
}

double FrontPacker::swept_volume(double radius) const {
  auto it = std::lower_bound(sample_dist_.begin(), sample_dist_.end(), radius);
  return (spec_.hi - spec_.lo).prod() * (it - sample_dist_.begin()) /
         static_cast<double>(sample_dist_.size());
}

// The density control: the rule's retries (DA: smaller sizes, LA: reopening
// closed faces) are spent only while the spheres placed so far hold less
// than the target solid fraction of the container volume the front swept.
bool FrontPacker::behind_target() const {
  return placed_volume_ < target_density_ * swept_volume(reach_ + margin_);
}

void FrontPacker::skip_class(int k) {
  res_.skipped_per_class[k] += left_[k];
  total_left_ -= left_[k];
  left_[k] = 0;
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
  using Item = std::pair<double, size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> front;
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
  auto reopen = [&](std::vector<Item>& parked, decltype(front)& q) {
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
    bool ok = fill_face(faces_[f], Side::open);
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
      Side side = i < main_loop_faces ? Side::pore : Side::open;
      if (fill_face(faces_[i], side)) {
        res_.placed_in_second_loop++;
        state_[i] = kFilled;
      }
      report_progress();
    }
  }
  res_.peak_bytes = grid_.memory_bytes() + faces_.capacity() * sizeof(Face) +
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
