// The Packer's sites (packer.h): where a grain on a site goes (Eq. 1, Figs.
// 7-8, walls), the heaps of sites per size that hand out the lowest site
// first, the sites a new sphere opens, and a grain offered to a site.
#include "packer.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace fabric {
namespace detail {

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

}  // namespace detail
}  // namespace fabric
