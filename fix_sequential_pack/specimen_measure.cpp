#include "specimen_measure.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "psd.h"

namespace fabric {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// 8-point Gauss-Legendre rule on [-1, 1], nodes found by Newton's method.
struct GaussLegendre {
  static constexpr int n = 8;
  double x[n], w[n];
  GaussLegendre() {
    for (int i = 0; i < n; ++i) {
      double t = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 1.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = t;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (t * p1 - p0) / (t * t - 1.0);
        const double dt = p1 / dp;
        t -= dt;
        if (std::abs(dt) < 1e-17) break;
      }
      x[i] = t;
      w[i] = 2.0 / ((1.0 - t * t) * dp * dp);
    }
  }
};

template <class F>
double gauss(const F& f, double a, double b) {
  static const GaussLegendre gl;
  const double m = 0.5 * (a + b), h = 0.5 * (b - a);
  double s = 0.0;
  for (int i = 0; i < GaussLegendre::n; ++i) s += gl.w[i] * f(m + h * gl.x[i]);
  return s * h;
}

template <class F>
double adaptive(const F& f, double a, double b, double whole, double tol,
                int depth) {
  const double m = 0.5 * (a + b);
  const double l = gauss(f, a, m), r = gauss(f, m, b);
  if (depth <= 0 || std::abs(l + r - whole) <= tol) return l + r;
  return adaptive(f, a, m, l, tol, depth - 1) +
         adaptive(f, m, b, r, tol, depth - 1);
}

// Volume of the part {x > a} of a sphere of radius r centred at the origin.
double cap_volume(double r, double a) {
  return kPi * (r - a) * (r - a) * (2.0 * r + a) / 3.0;
}

std::vector<double> average_ranks(const std::vector<double>& v) {
  std::vector<int> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return v[a] < v[b]; });
  std::vector<double> rank(v.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]]) ++j;
    for (std::size_t k = i; k <= j; ++k) rank[order[k]] = 0.5 * (i + j) + 1.0;
    i = j + 1;
  }
  return rank;
}

double pearson(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  if (n < 2) return kNaN;
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n;
  const double my = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  if (sxx <= 0.0 || syy <= 0.0) return kNaN;
  return sxy / std::sqrt(sxx * syy);
}

// d - sin d without cancellation for small d.
double d_minus_sin(double d) {
  if (d > 0.25) return d - std::sin(d);
  const double d2 = d * d;
  return d * d2 *
         (1.0 / 6 - d2 * (1.0 / 120 - d2 * (1.0 / 5040 - d2 * (1.0 / 362880 - d2 / 39916800))));
}

// Integral of sqrt(R^2 - x^2) over [u, v] within [-R, R], to a few ulps of
// its own size even for a thin strip anywhere: with x = R sin(phi) it is
// R^2/2 (D + sin D cos(phi_u + phi_v)), D = phi_v - phi_u, and every factor
// below is a sum of non-negative terms (for 0 <= u <= v), so nothing cancels.
double chord_integral(double R, double u, double v) {
  if (u < 0.0 && v <= 0.0) return chord_integral(R, -v, -u);
  if (u < 0.0) return chord_integral(R, 0.0, -u) + chord_integral(R, 0.0, v);
  if (v <= u) return 0.0;
  auto s_of = [R](double x) { return std::sqrt(std::max(0.0, (R - x) * (R + x))); };
  const double su = s_of(u), sv = s_of(v), R2 = R * R;
  const double sin_d = (v - u) * (su + (su + sv > 0.0 ? u * (u + v) / (su + sv) : 0.0));
  const double cos_d = su * sv + u * v;  // both times R^2
  const double d = std::atan2(sin_d, cos_d);
  const double one_plus_cos_sum = 0.5 * ((R - u) * (R + v) + (R - v) * (R + u)) + su * sv;
  return 0.5 * (R2 * d_minus_sin(d) + sin_d * one_plus_cos_sum / R2);
}

}  // namespace

double disc_rectangle_area(double R, double x0, double x1, double y0,
                           double y1) {
  if (!(R > 0.0)) return 0.0;
  const double xa = std::max(x0, -R), xb = std::min(x1, R);
  if (xa >= xb || std::max(y0, -R) >= std::min(y1, R)) return 0.0;
  // Over x the chord [-s, s], s = sqrt(R^2 - x^2), is clipped by y0 and y1;
  // which bound is active changes only where s = |y0| or |y1|.
  double xs[6] = {xa, xb};
  int n = 2;
  for (double y : {y0, y1})
    if (std::abs(y) < R) {
      const double w = std::sqrt(R * R - y * y);
      if (-w > xa && -w < xb) xs[n++] = -w;
      if (w > xa && w < xb) xs[n++] = w;
    }
  for (int i = 1; i < n; ++i)  // (std::sort here trips -Warray-bounds)
    for (int j = i; j > 0 && xs[j] < xs[j - 1]; --j) std::swap(xs[j], xs[j - 1]);
  auto s_of = [R](double x) { return std::sqrt(std::max(0.0, (R - x) * (R + x))); };
  double area = 0.0;
  for (int i = 0; i + 1 < n; ++i) {
    const double u = xs[i], v = xs[i + 1];
    if (v <= u) continue;
    const double s = s_of(0.5 * (u + v));
    const bool top_flat = y1 < s, bottom_flat = y0 > -s;
    if ((top_flat ? y1 : s) <= (bottom_flat ? y0 : -s)) continue;
    const double a = chord_integral(R, u, v);
    area += (top_flat ? y1 * (v - u) : a) + (bottom_flat ? -y0 * (v - u) : a);
  }
  return area;
}

double sphere_box_volume(const Vec3& c, double r, const Box& b) {
  if (!(r > 0.0)) return 0.0;
  const Vec3 lo = b.lo - c, hi = b.hi - c;
  if ((lo.array() >= hi.array()).any()) return 0.0;
  if (Vec3::Zero().cwiseMax(lo).cwiseMin(hi).squaredNorm() >= r * r) return 0.0;
  int cuts = 0;
  double a = 0.0;
  for (int k = 0; k < 3; ++k) {
    if (lo[k] > -r) ++cuts, a = lo[k];
    if (hi[k] < r) ++cuts, a = -hi[k];
  }
  if (cuts == 0) return sphere_volume(2.0 * r);
  if (cuts == 1) return cap_volume(r, a);

  // Integrate the disc-rectangle area along the axis where the box is
  // thinnest (z below), so a thin slab is a short integral. The area is
  // analytic in z except where the slice radius rho passes the distance
  // from the axis to a side or corner of the rectangle, with (z - z*)^(k/2)
  // behaviour there.
  Vec3 w;
  for (int k = 0; k < 3; ++k) w[k] = std::min(hi[k], r) - std::max(lo[k], -r);
  int ax = 0;
  w.minCoeff(&ax);
  const int p[3] = {(ax + 1) % 3, (ax + 2) % 3, ax};
  const Vec3 l(lo[p[0]], lo[p[1]], lo[p[2]]), h(hi[p[0]], hi[p[1]], hi[p[2]]);
  // The rounding noise of the area is about 1e-16 r times the rectangle's
  // width; below that no quadrature can go.
  const double noise = 1e-16 * r * std::max(w[p[0]], w[p[1]]);
  const double za = std::max(l[2], -r), zb = std::min(h[2], r);
  std::vector<double> zs = {za, zb};
  const double d2[8] = {l[0] * l[0],
                        h[0] * h[0],
                        l[1] * l[1],
                        h[1] * h[1],
                        l[0] * l[0] + l[1] * l[1],
                        l[0] * l[0] + h[1] * h[1],
                        h[0] * h[0] + l[1] * l[1],
                        h[0] * h[0] + h[1] * h[1]};
  for (double d : d2)
    if (d < r * r) {
      const double w = std::sqrt(r * r - d);
      for (double z : {-w, w})
        if (z > za && z < zb) zs.push_back(z);
    }
  std::sort(zs.begin(), zs.end());
  auto area = [&](double z) {
    return disc_rectangle_area(std::sqrt(std::max(0.0, r * r - z * z)), l[0],
                               h[0], l[1], h[1]);
  };
  // z = z0 + L (3t^2 - 2t^3) turns the (z - z*)^(k/2) ends of a piece
  // into analytic ones, so Gauss-Legendre converges fast again.
  double v = 0.0;
  for (std::size_t i = 0; i + 1 < zs.size(); ++i) {
    const double z0 = zs[i], L = zs[i + 1] - zs[i];
    if (L <= 0.0) continue;
    auto f = [&](double t) {
      return area(z0 + L * t * t * (3.0 - 2.0 * t)) * 6.0 * L * t * (1.0 - t);
    };
    // Relative tolerance, so that a sliver is as exact as a whole sphere.
    const double whole = gauss(f, 0.0, 1.0);
    v += adaptive(f, 0.0, 1.0, whole, std::max(1e-14 * whole, noise * L), 20);
  }
  return v;
}

// --- PackingMeasure ---------------------------------------------------------

PackingMeasure::PackingMeasure(const std::vector<Vec3>& centre,
                               const std::vector<double>& radius,
                               const Box& container)
    : c_(centre), r_(radius), box_(container) {
  if (c_.size() != r_.size())
    throw std::invalid_argument("PackingMeasure: centre and radius differ in size");
  bins_ = bin(0.0);
}

std::array<long, 3> PackingMeasure::Bins::cell(const Vec3& p) const {
  std::array<long, 3> k;
  for (int d = 0; d < 3; ++d) {
    const double f = std::floor((p[d] - origin[d]) / h);
    k[d] = f <= 0.0 ? 0 : f >= n[d] - 1 ? n[d] - 1 : static_cast<long>(f);
  }
  return k;
}

PackingMeasure::Bins PackingMeasure::bin(double inflate) const {
  Bins b;
  b.inflate = inflate;
  const long N = size();
  if (N == 0) {
    b.start.assign(2, 0);
    return b;
  }
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (long i = 0; i < N; ++i) {
    const double R = r_[i] * (1.0 + inflate);
    lo = lo.array().min(c_[i].array() - R).matrix();
    hi = hi.array().max(c_[i].array() + R).matrix();
  }
  const Vec3 ext = (hi - lo).cwiseMax(1e-300);
  // About one cell per sphere; a flat or long cloud may need coarser cells
  // to keep the cell count O(N).
  b.origin = lo;
  b.h = std::cbrt(ext.prod() / N);
  for (;;) {
    long cells = 1;
    for (int d = 0; d < 3; ++d) {
      b.n[d] = std::max(1L, static_cast<long>(std::ceil(ext[d] / b.h)));
      cells *= b.n[d];
    }
    if (cells <= 4 * N + 64) break;
    b.h *= 1.25;
  }
  const long cells = b.n[0] * b.n[1] * b.n[2];
  b.start.assign(cells + 1, 0);
  // Two passes (count, fill) over the cells each sphere's box meets.
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<long> fill;
    if (pass == 1) {
      std::partial_sum(b.start.begin(), b.start.end(), b.start.begin());
      b.item.resize(b.start[cells]);
      fill.assign(b.start.begin(), b.start.end() - 1);
    }
    for (long i = 0; i < N; ++i) {
      const double R = r_[i] * (1.0 + inflate);
      const auto k0 = b.cell((c_[i].array() - R).matrix()),
                 k1 = b.cell((c_[i].array() + R).matrix());
      for (long z = k0[2]; z <= k1[2]; ++z)
        for (long y = k0[1]; y <= k1[1]; ++y)
          for (long x = k0[0]; x <= k1[0]; ++x) {
            const long cell = b.index({x, y, z});
            if (pass == 0)
              ++b.start[cell + 1];
            else
              b.item[fill[cell]++] = static_cast<int>(i);
          }
    }
  }
  return b;
}

// Calls f(i, j), i < j, once for every pair whose inflated boxes meet.
template <class F>
void PackingMeasure::for_each_pair(const Bins& b, F&& f) const {
  const double g = 1.0 + b.inflate;
  const long cells = static_cast<long>(b.start.size()) - 1;
  for (long cell = 0; cell < cells; ++cell)
    for (long p = b.start[cell]; p < b.start[cell + 1]; ++p)
      for (long q = p + 1; q < b.start[cell + 1]; ++q) {
        const int i = b.item[p], j = b.item[q];
        const Vec3 lo = (c_[i].array() - g * r_[i]).max(c_[j].array() - g * r_[j]).matrix();
        const Vec3 hi = (c_[i].array() + g * r_[i]).min(c_[j].array() + g * r_[j]).matrix();
        if ((lo.array() > hi.array()).any()) continue;
        if (b.index(b.cell(lo)) != cell) continue;
        f(i, j);
      }
}

RegionPorosity PackingMeasure::measure(const Box& region) const {
  RegionPorosity out{kNaN, 0.0, region.volume(), kNaN};
  if (!(out.region_volume > 0.0)) return out;
  double diameter_volume = 0.0;
  const auto k0 = bins_.cell(region.lo), k1 = bins_.cell(region.hi);
  for (long z = k0[2]; z <= k1[2]; ++z)
    for (long y = k0[1]; y <= k1[1]; ++y)
      for (long x = k0[0]; x <= k1[0]; ++x) {
        const long cell = bins_.index({x, y, z});
        for (long p = bins_.start[cell]; p < bins_.start[cell + 1]; ++p) {
          const int i = bins_.item[p];
          const Vec3 lo = region.lo.array().max(c_[i].array() - r_[i]).matrix();
          const Vec3 hi = region.hi.array().min(c_[i].array() + r_[i]).matrix();
          if ((lo.array() > hi.array()).any()) continue;
          if (bins_.index(bins_.cell(lo)) != cell) continue;
          const double v = sphere_box_volume(c_[i], r_[i], region);
          out.solid_volume += v;
          diameter_volume += 2.0 * r_[i] * v;
        }
      }
  out.porosity = 1.0 - out.solid_volume / out.region_volume;
  if (out.solid_volume > 0.0) out.mean_diameter = diameter_volume / out.solid_volume;
  return out;
}

std::vector<double> PackingMeasure::subcube_porosity(int n) const {
  if (n < 1) throw std::invalid_argument("subcube_porosity: n < 1");
  // One formula for both sides of a shared face, so the sub-cubes tile the
  // container exactly.
  auto at = [&](int d, int i) {
    return i == n ? box_.hi[d] : box_.lo[d] + (box_.hi[d] - box_.lo[d]) * i / n;
  };
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(n) * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        out.push_back(porosity(Box{Vec3(at(0, i), at(1, j), at(2, k)),
                                   Vec3(at(0, i + 1), at(1, j + 1), at(2, k + 1))}));
  return out;
}

Box PackingMeasure::interior(double layer) const {
  if (!(layer >= 0.0) || 2.0 * layer >= (box_.hi - box_.lo).minCoeff())
    throw std::invalid_argument("interior: layer outside [0, half the smallest edge)");
  return Box{(box_.lo.array() + layer).matrix(), (box_.hi.array() - layer).matrix()};
}

double PackingMeasure::interior_porosity(double layer) const {
  return porosity(interior(layer));
}

double PackingMeasure::wall_layer_porosity(double layer) const {
  const RegionPorosity in = measure(interior(layer)), all = measure(box_);
  return 1.0 - (all.solid_volume - in.solid_volume) /
                   (all.region_volume - in.region_volume);
}

double PackingMeasure::radius_distance_spearman() const {
  const Vec3 mid = 0.5 * (box_.lo + box_.hi);
  std::vector<double> dist(c_.size());
  for (std::size_t i = 0; i < c_.size(); ++i) dist[i] = (c_[i] - mid).norm();
  return pearson(average_ranks(r_), average_ranks(dist));
}

const std::vector<std::pair<int, int>>& PackingMeasure::pairs(double tol) const {
  if (pairs_tol_ == tol) return pairs_;
  pairs_.clear();
  for_each_pair(bin(std::max(tol, 0.0)), [&](int i, int j) {
    const double gap = (c_[i] - c_[j]).norm() - r_[i] - r_[j];
    if (gap < tol * std::min(r_[i], r_[j])) pairs_.emplace_back(i, j);
  });
  std::sort(pairs_.begin(), pairs_.end());
  pairs_tol_ = tol;
  return pairs_;
}

std::vector<std::pair<int, int>> PackingMeasure::touching_pairs(double tol) const {
  return pairs(tol);
}

std::vector<int> PackingMeasure::contact_counts(double tol) const {
  std::vector<int> n(c_.size(), 0);
  for (const auto& [i, j] : pairs(tol)) ++n[i], ++n[j];
  for (std::size_t i = 0; i < c_.size(); ++i)
    for (int a = 0; a < 3; ++a) {
      const double reach = r_[i] * (1.0 + tol);
      if (c_[i][a] - box_.lo[a] < reach) ++n[i];
      if (box_.hi[a] - c_[i][a] < reach) ++n[i];
    }
  return n;
}

double PackingMeasure::size_assortativity(double tol) const {
  return size_assortativity(box_, tol);
}

double PackingMeasure::size_assortativity(const Box& region, double tol) const {
  auto in = [&](int i) {
    return (c_[i].array() >= region.lo.array()).all() &&
           (c_[i].array() <= region.hi.array()).all();
  };
  std::vector<double> x, y;
  for (const auto& [i, j] : pairs(tol)) {
    if (!in(i) || !in(j)) continue;
    const double a = std::log(r_[i]), b = std::log(r_[j]);
    x.push_back(a), y.push_back(b);
    x.push_back(b), y.push_back(a);
  }
  return pearson(x, y);
}

double PackingMeasure::cu_of(const std::vector<int>& ids) const {
  if (ids.size() < 2) return kNaN;
  std::vector<double> d;
  for (int i : ids) d.push_back(2.0 * r_[i]);
  std::sort(d.begin(), d.end());
  std::vector<double> P(d.size());
  double total = 0.0;
  for (std::size_t k = 0; k < d.size(); ++k) P[k] = total += d[k] * d[k] * d[k];
  for (double& p : P) p /= total;
  auto d_at = [&](double p) {
    const std::size_t k = std::lower_bound(P.begin(), P.end(), p) - P.begin();
    if (k == 0) return d[0];
    if (k == P.size()) return d.back();
    return d[k - 1] + (d[k] - d[k - 1]) * (p - P[k - 1]) / (P[k] - P[k - 1]);
  };
  return d_at(0.6) / d_at(0.1);
}

double PackingMeasure::local_cu(const Box& region) const {
  std::vector<int> ids;
  for (int i = 0; i < size(); ++i)
    if ((c_[i].array() >= region.lo.array()).all() &&
        (c_[i].array() <= region.hi.array()).all())
      ids.push_back(i);
  return cu_of(ids);
}

double PackingMeasure::cu() const {
  std::vector<int> ids(size());
  std::iota(ids.begin(), ids.end(), 0);
  return cu_of(ids);
}

double PackingMeasure::mean_local_cu_ratio(int n, int min_grains) const {
  if (n < 1) throw std::invalid_argument("mean_local_cu_ratio: n < 1");
  std::vector<std::vector<int>> in_cell(static_cast<std::size_t>(n) * n * n);
  const Vec3 ext = box_.hi - box_.lo;
  for (int i = 0; i < size(); ++i) {
    int idx[3];
    for (int a = 0; a < 3; ++a)
      idx[a] = std::clamp(
          static_cast<int>(std::floor((c_[i][a] - box_.lo[a]) / ext[a] * n)), 0,
          n - 1);
    in_cell[idx[0] + n * (idx[1] + n * idx[2])].push_back(i);
  }
  double sum = 0.0;
  int cells = 0;
  for (const std::vector<int>& ids : in_cell) {
    if (static_cast<int>(ids.size()) < min_grains) continue;
    const double c = cu_of(ids);
    if (std::isfinite(c)) sum += c, ++cells;
  }
  return cells > 0 ? sum / cells / cu() : kNaN;
}

std::vector<RegionPorosity> PackingMeasure::layer_profile(int layers,
                                                          int axis) const {
  if (layers < 1 || axis < 0 || axis > 2)
    throw std::invalid_argument(
        "layer_profile: needs layers >= 1 and an axis 0, 1 or 2");
  std::vector<RegionPorosity> out;
  const double lo = box_.lo[axis], h = box_.hi[axis] - lo;
  for (int l = 0; l < layers; ++l) {
    Box slab = box_;
    slab.lo[axis] = lo + h * l / layers;
    slab.hi[axis] = l + 1 == layers ? box_.hi[axis] : lo + h * (l + 1) / layers;
    out.push_back(measure(slab));
  }
  return out;
}

double PackingMeasure::worst_overlap() const {
  double worst = 0.0;
  for_each_pair(bins_, [&](int i, int j) {
    const double depth = r_[i] + r_[j] - (c_[i] - c_[j]).norm();
    worst = std::max(worst, depth / std::min(r_[i], r_[j]));
  });
  return worst;
}

bool PackingMeasure::all_inside(double tol) const {
  for (int i = 0; i < size(); ++i) {
    const double m = (1.0 - tol) * r_[i];
    if ((c_[i].array() - m < box_.lo.array()).any() ||
        (c_[i].array() + m > box_.hi.array()).any())
      return false;
  }
  return true;
}

}  // namespace fabric
