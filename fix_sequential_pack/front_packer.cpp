// The sequential packer (front_packer.h): its public functions, and the
// Packer's construction, deck and draw, first face and run().
#include "front_packer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "packer.h"
#include "psd.h"

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

namespace detail {

namespace {

// Each deck is the list plus this many grains of each size (new_deck()).
constexpr long long kDeckExtra = 2;

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

}  // namespace

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

void Packer::report_progress() {
  if (!spec_.progress || grid_.size() < next_report_) return;
  spec_.progress(grid_.size(), total_);
  next_report_ = grid_.size() + std::max<long long>(total_ / 10, 1);
}

PackingResult Packer::run() {
  grid_.reserve(static_cast<std::size_t>(total_ * 1.2) + 16);
  next_report_ = std::max<long long>(total_ / 10, 1);
  if (spec_.start == Start::centre) first_face();
  open_corner_sites();
  pack_full();
  choose_vacancies();
  // The specimen: its grains in placement order, then the second loop's.
  take_specimen();
  if (spec_.fill_pores) second_loop();
  tally();
  if (spec_.progress) spec_.progress(grid_.size(), total_);
  return std::move(res_);
}

// The eight corners are sites (three walls) from the start.
void Packer::open_corner_sites() {
  for (int x = 0; x < 2; ++x)
    for (int y = 0; y < 2; ++y)
      for (int z = 0; z < 2; ++z)
        push(Site{0.0, next_order_++,
                  {wall_code(0, x), wall_code(1, y), wall_code(2, z)}, 1, -1},
             nclass_ - 1);
}

// The container is packed full: grains are drawn until no site takes one.
// A grain drawn that does not fit where it was offered waits for the next
// site that fits it, so no size is replaced by smaller ones on the spot.
void Packer::pack_full() {
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
}

// The spheres of the full packing that are not vacancies go into the
// result, in placement order.
void Packer::take_specimen() {
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
}

// What the result reports besides the specimen: unplaced grains, volumes,
// the packer's peak memory.
void Packer::tally() {
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
}

}  // namespace detail

Start default_start(Arrangement a) {
  return detail::make_rule(a, detail::Sizes{}, kDefaultLayering)
      ->default_start();
}

namespace {
double unplaced_volume(const PackingResult& r, const PackingSpec& spec) {
  double v = 0.0;
  for (std::size_t k = 0; k < r.unplaced_per_class.size(); ++k)
    v += r.unplaced_per_class[k] * sphere_volume(2.0 * spec.radius[k]);
  return v;
}
PackingResult pack_from(const PackingSpec& spec) {
  PackingResult r = detail::Packer(spec).run();
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
