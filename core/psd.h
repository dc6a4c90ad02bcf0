// Particle size distribution (PSD) from a sieve analysis, as a value type.
//
// Plain C++ (no LIGGGHTS include). A PSD is a cumulative curve "percent of
// mass passing" against diameter. Between sieve points the percentage is
// interpolated linearly in log(diameter), the convention of semi-log
// grading charts; flat segments (gap grading) carry no mass and are valid.
//
// The paper (section 2.2) splits the curve into N intervals of equal mass
// (20 x 5 %), each represented by its mean diameter; here the mean is the
// mass-weighted mean diameter of the interval, so an interval that spans a
// gap is represented by sizes that exist in the soil.
#ifndef FABRIC_PSD_H
#define FABRIC_PSD_H

#include <string>
#include <vector>

namespace fabric {

struct SievePoint {
  double diameter;        // length unit of the input script
  double percent_passing; // 0..100, by mass
};

struct SizeInterval {
  double d_lower;       // diameter at the interval's lower mass bound
  double d_upper;       // diameter at the interval's upper mass bound
  double d_mean;        // mass-weighted mean diameter (the representative)
  double mass_fraction; // share of the total mass, 0..1
};

class ParticleSizeDistribution {
 public:
  // Validates the points; throws std::invalid_argument with a message that
  // names the offending value and what is allowed.
  explicit ParticleSizeDistribution(std::vector<SievePoint> points);

  // Reads "diameter percent_passing" lines; '#' starts a comment.
  static ParticleSizeDistribution read(const std::string& path);
  static ParticleSizeDistribution parse(const std::string& text,
                                        const std::string& source_name);

  const std::vector<SievePoint>& points() const { return points_; }
  double d_min() const { return points_.front().diameter; }
  double d_max() const { return points_.back().diameter; }

  // Diameter below which `percent` of the mass passes (inverse of the curve).
  // On a flat segment the smallest such diameter is returned.
  double diameter_at_percent(double percent) const;
  double percent_passing(double diameter) const;
  double d10() const { return diameter_at_percent(10.0); }
  double d60() const { return diameter_at_percent(60.0); }
  double uniformity_coefficient() const { return d60() / d10(); }

  // N intervals of equal mass (1 <= N <= 100), finest first.
  std::vector<SizeInterval> equal_mass_intervals(int n) const;

 private:
  std::vector<SievePoint> points_;
};

// How many spheres of each interval fill a container of `container_volume`
// at `porosity`: count_k = round(m_k (1 - n) V / (pi/6 d_k^3)).
struct ParticleList {
  std::vector<double> diameter;     // per interval, finest first
  std::vector<double> target_count; // real-valued count before rounding
  std::vector<long long> count;     // rounded count
  long long total() const;
  double solid_volume() const;      // sum of count * sphere volume
};
ParticleList particle_list(const std::vector<SizeInterval>& intervals,
                           double container_volume, double porosity);

double sphere_volume(double diameter);

}  // namespace fabric

#endif
