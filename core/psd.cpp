#include "psd.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fabric {

namespace {

std::string num(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

// Diameter on segment i (points i, i+1; percentages differ) at `percent`.
double segment_diameter(const SievePoint& a, const SievePoint& b,
                        double percent) {
  double t = (percent - a.percent_passing) /
             (b.percent_passing - a.percent_passing);
  return std::exp(std::log(a.diameter) +
                  t * (std::log(b.diameter) - std::log(a.diameter)));
}

// Mass-weighted mean diameter between diameters u < v on a segment where
// the percentage is linear in log(d): integral of d dP / integral of dP.
double log_mean(double u, double v) {
  double l = std::log(v / u);
  return l < 1e-12 ? 0.5 * (u + v) : (v - u) / l;
}

}  // namespace

ParticleSizeDistribution::ParticleSizeDistribution(
    std::vector<SievePoint> points)
    : points_(std::move(points)) {
  if (points_.size() < 2)
    throw std::invalid_argument(
        "PSD needs at least 2 points (diameter percent_passing), got " +
        std::to_string(points_.size()));
  for (size_t i = 0; i < points_.size(); ++i) {
    const SievePoint& p = points_[i];
    std::string where = "PSD point " + std::to_string(i + 1) + ": ";
    if (!std::isfinite(p.diameter) || p.diameter <= 0.0)
      throw std::invalid_argument(where + "diameter " + num(p.diameter) +
                                  " must be positive");
    if (!std::isfinite(p.percent_passing) || p.percent_passing < 0.0 ||
        p.percent_passing > 100.0)
      throw std::invalid_argument(where + "percent passing " +
                                  num(p.percent_passing) +
                                  " must lie in 0..100");
    if (i > 0 && p.diameter <= points_[i - 1].diameter)
      throw std::invalid_argument(
          where + "diameter " + num(p.diameter) +
          " must be larger than the previous diameter " +
          num(points_[i - 1].diameter) + " (diameters strictly increasing)");
    if (i > 0 && p.percent_passing < points_[i - 1].percent_passing)
      throw std::invalid_argument(
          where + "percent passing " + num(p.percent_passing) +
          " is below the previous value " +
          num(points_[i - 1].percent_passing) +
          " (percentages must not decrease)");
  }
  if (points_.front().percent_passing != 0.0)
    throw std::invalid_argument(
        "PSD must start at 0 percent passing (its finest diameter), first "
        "point has " + num(points_.front().percent_passing));
  if (points_.back().percent_passing != 100.0)
    throw std::invalid_argument(
        "PSD must end at 100 percent passing, last point has " +
        num(points_.back().percent_passing));
}

ParticleSizeDistribution ParticleSizeDistribution::parse(
    const std::string& text, const std::string& source_name) {
  std::istringstream in(text);
  std::string line;
  std::vector<SievePoint> pts;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream ls(line);
    std::string a, b, extra;
    if (!(ls >> a)) continue;  // blank or comment line
    std::string where = source_name + " line " + std::to_string(lineno) + ": ";
    if (!(ls >> b))
      throw std::invalid_argument(where + "expected 'diameter percent_passing',"
                                  " got only '" + a + "'");
    if (ls >> extra)
      throw std::invalid_argument(where + "expected 2 numbers, found extra '" +
                                  extra + "'");
    SievePoint p{};
    size_t ia = 0, ib = 0;
    try {
      p.diameter = std::stod(a, &ia);
      p.percent_passing = std::stod(b, &ib);
    } catch (const std::exception&) {
      ia = ib = 0;
    }
    if (ia != a.size() || ib != b.size())
      throw std::invalid_argument(where + "'" + a + " " + b +
                                  "' is not two numbers");
    pts.push_back(p);
  }
  try {
    return ParticleSizeDistribution(std::move(pts));
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(source_name + ": " + e.what());
  }
}

ParticleSizeDistribution ParticleSizeDistribution::read(
    const std::string& path) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) &&
      !std::filesystem::is_regular_file(path, ec))
    throw std::invalid_argument("PSD file '" + path +
                                "' is not a regular file (a directory?)");
  std::ifstream f(path);
  if (!f)
    throw std::invalid_argument("cannot open PSD file '" + path + "'");
  std::stringstream ss;
  ss << f.rdbuf();
  if (f.bad())
    throw std::invalid_argument("cannot read PSD file '" + path + "'");
  return parse(ss.str(), path);
}

double ParticleSizeDistribution::percent_passing(double d) const {
  if (d <= d_min()) return 0.0;
  if (d >= d_max()) return 100.0;
  for (size_t i = 0; i + 1 < points_.size(); ++i) {
    const SievePoint &a = points_[i], &b = points_[i + 1];
    if (d <= b.diameter) {
      double t = std::log(d / a.diameter) / std::log(b.diameter / a.diameter);
      return a.percent_passing + t * (b.percent_passing - a.percent_passing);
    }
  }
  return 100.0;
}

double ParticleSizeDistribution::diameter_at_percent(double percent) const {
  if (percent <= 0.0) return d_min();
  for (size_t i = 0; i + 1 < points_.size(); ++i) {
    const SievePoint &a = points_[i], &b = points_[i + 1];
    if (b.percent_passing >= percent && b.percent_passing > a.percent_passing)
      return segment_diameter(a, b, percent);
  }
  return d_max();
}

std::vector<SizeInterval> ParticleSizeDistribution::equal_mass_intervals(
    int n) const {
  if (n < 1 || n > 100)
    throw std::invalid_argument("number of intervals " + std::to_string(n) +
                                " must lie in 1..100");
  std::vector<SizeInterval> out;
  out.reserve(n);
  for (int k = 0; k < n; ++k) {
    double q0 = 100.0 * k / n, q1 = 100.0 * (k + 1) / n;
    double weighted = 0.0, mass = 0.0;
    for (size_t i = 0; i + 1 < points_.size(); ++i) {
      const SievePoint &a = points_[i], &b = points_[i + 1];
      double lo = std::max(q0, a.percent_passing);
      double hi = std::min(q1, b.percent_passing);
      if (hi <= lo) continue;  // no overlap, or a flat (gap) segment
      double u = segment_diameter(a, b, lo), v = segment_diameter(a, b, hi);
      weighted += (hi - lo) * log_mean(u, v);
      mass += hi - lo;
    }
    SizeInterval iv;
    iv.d_lower = diameter_at_percent(q0);
    iv.d_upper = diameter_at_percent(q1);
    iv.d_mean = weighted / mass;
    iv.mass_fraction = 1.0 / n;
    out.push_back(iv);
  }
  return out;
}

double sphere_volume(double d) { return M_PI / 6.0 * d * d * d; }

long long ParticleList::total() const {
  long long t = 0;
  for (long long c : count) t += c;
  return t;
}

double ParticleList::solid_volume() const {
  double v = 0.0;
  for (size_t k = 0; k < count.size(); ++k)
    v += count[k] * sphere_volume(diameter[k]);
  return v;
}

ParticleList particle_list(const std::vector<SizeInterval>& intervals,
                           double container_volume, double porosity) {
  ParticleList list;
  double solid = (1.0 - porosity) * container_volume;
  for (const SizeInterval& iv : intervals) {
    double target = iv.mass_fraction * solid / sphere_volume(iv.d_mean);
    list.diameter.push_back(iv.d_mean);
    list.target_count.push_back(target);
    list.count.push_back(std::llround(target));
  }
  return list;
}

}  // namespace fabric
