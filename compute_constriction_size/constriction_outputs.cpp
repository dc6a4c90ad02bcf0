// The global vector of compute constriction/size (constriction_outputs.h).
#include "constriction_outputs.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "height_slices.h"
#include "suffusion_criteria.h"

namespace fabric {

GradingCriteria grading_criteria(const ParticleSizeDistribution& psd) {
  const BurenkovaResult bu = burenkova(psd);
  const WanFellResult wf = wan_fell(psd);
  GradingCriteria c;
  c.kezdi_max_ratio = kezdi(psd).max_ratio;
  c.kenney_lau_min_ratio = kenney_lau(psd).min_ratio;
  c.burenkova_h1 = bu.h1;
  c.burenkova_h2 = bu.h2;
  c.burenkova_stable = bu.stable() ? 1.0 : 0.0;
  c.wan_fell_probability = wf.probability;
  c.wan_fell_sand_gravel_probability = wf.probability_sand_gravel;
  return c;
}

std::vector<ConstrictionSlice> constriction_slices(
    const ConstrictionNetwork& net, const std::vector<Sphere>& pore_forming,
    const VerdictGrains& grains, int count, double control_percent,
    CsdWeight control_weight) {
  const auto fail = [](const std::string& m) {
    throw std::invalid_argument("constriction/size: " + m);
  };
  if (count < 1) fail("slices must be >= 1, got " + std::to_string(count));
  const std::size_t nloose = grains.loose_diameter.size();
  if (grains.loose_mass.size() != nloose || grains.loose_z.size() != nloose)
    fail("the loose grains have " + std::to_string(nloose) + " diameters, " +
         std::to_string(grains.loose_mass.size()) + " masses and " +
         std::to_string(grains.loose_z.size()) + " heights");
  // The extent over the grains at a finite height (the others are in no
  // slice).
  HeightExtent e{std::numeric_limits<double>::infinity(),
                 -std::numeric_limits<double>::infinity()};
  const auto extend = [&e](double z, double r) {
    if (!std::isfinite(z) || !std::isfinite(r)) return;
    e.bottom = std::min(e.bottom, z - r);
    e.top = std::max(e.top, z + r);
  };
  for (const Sphere& s : pore_forming) extend(s.centre.z(), s.radius);
  for (std::size_t k = 0; k < nloose; ++k)
    extend(grains.loose_z[k], 0.5 * grains.loose_diameter[k]);
  if (!(e.top >= e.bottom)) fail("no grain at a finite height: no slices");
  const HeightSlices slices(e, count);

  std::vector<std::vector<ConstrictionDisc>> discs(count);
  for (const ConstrictionDisc& d : net.discs) {
    const int k = slices.of(d.face_centroid.z());
    if (k >= 0) discs[k].push_back(d);
  }
  // the loose grains of each slice, in their given order (so that one slice
  // sums them as constriction_vector does)
  std::vector<std::vector<double>> diameter(count), mass(count);
  for (std::size_t g = 0; g < nloose; ++g) {
    const int k = slices.of(grains.loose_z[g]);
    if (k < 0) continue;
    diameter[k].push_back(grains.loose_diameter[g]);
    mass[k].push_back(grains.loose_mass[g]);
  }
  std::vector<ConstrictionSlice> rows(count);
  for (int k = 0; k < count; ++k) {
    ConstrictionSlice& r = rows[k];
    r.lower = slices.lower(k);
    r.upper = slices.upper(k);
    r.constrictions = static_cast<double>(discs[k].size());
    r.control =
        csd_percentiles(discs[k], {control_percent}, control_weight)[0];
    for (double m : mass[k]) r.loose_mass += m;
    r.loose_finer_control_percent =
        mass_percent_finer(diameter[k], mass[k], r.control);
  }
  return rows;
}

std::vector<double> constriction_vector(
    const ConstrictionNetwork& net, double control_percent,
    CsdWeight control_weight, const VerdictGrains& grains,
    const GradingCriteria& criteria,
    const std::vector<ConstrictionSlice>& slices) {
  using E = ConstrictionEntry;
  std::vector<double> v(kConstrictionVectorEntries, 0.0);
  std::vector<double> p;
  for (int k = 1; k <= kCsdPercentiles; ++k) p.push_back(5.0 * k);
  const std::vector<double> by_number = csd_percentiles(net.discs, p, false);
  const std::vector<double> by_cubic = csd_percentiles(net.discs, p, true);
  v[at(E::constrictions)] = static_cast<double>(net.discs.size());
  for (int k = 0; k < kCsdPercentiles; ++k) {
    v[at(E::dc5_number) + k] = by_number[k];
    v[at(E::dc5_cubed) + k] = by_cubic[k];
  }
  v[at(E::percolation)] = net.percolation_diameter;
  const double control =
      csd_percentiles(net.discs, {control_percent}, control_weight)[0];
  v[at(E::control)] = control;
  // The verdict: loose grains finer than the controlling constriction and
  // than the percolation opening, by mass.
  v[at(E::loose_finer_control_percent)] =
      mass_percent_finer(grains.loose_diameter, grains.loose_mass, control);
  v[at(E::loose_finer_percolation_percent)] = mass_percent_finer(
      grains.loose_diameter, grains.loose_mass, net.percolation_diameter);
  double loose = 0.0;
  for (double m : grains.loose_mass) loose += m;
  const double all = loose + grains.pore_forming_mass;
  v[at(E::loose_mass_percent)] = all > 0.0 ? 100.0 * loose / all : 0.0;
  v[at(E::pores)] = net.pores;
  v[at(E::grains)] = net.spheres;
  v[at(E::hidden)] = net.hidden;
  v[at(E::wall_excluded)] = net.wall_excluded;
  v[at(E::on_edge)] = net.on_edge;
  v[at(E::unsolved)] = net.unsolved;
  v[at(E::wall_margin)] = net.wall_margin;
  v[at(E::kezdi_max_ratio)] = criteria.kezdi_max_ratio;
  v[at(E::kenney_lau_min_ratio)] = criteria.kenney_lau_min_ratio;
  v[at(E::burenkova_h1)] = criteria.burenkova_h1;
  v[at(E::burenkova_h2)] = criteria.burenkova_h2;
  v[at(E::burenkova_stable)] = criteria.burenkova_stable;
  v[at(E::wan_fell_probability)] = criteria.wan_fell_probability;
  v[at(E::wan_fell_sand_gravel_probability)] =
      criteria.wan_fell_sand_gravel_probability;
  using S = ConstrictionSliceEntry;
  for (const ConstrictionSlice& r : slices) {
    std::vector<double> row(kConstrictionSliceEntries, 0.0);
    row[static_cast<int>(S::slice_bottom)] = r.lower;
    row[static_cast<int>(S::slice_top)] = r.upper;
    row[static_cast<int>(S::slice_constrictions)] = r.constrictions;
    row[static_cast<int>(S::slice_control)] = r.control;
    row[static_cast<int>(S::slice_loose_mass)] = r.loose_mass;
    row[static_cast<int>(S::slice_loose_finer_control_percent)] =
        r.loose_finer_control_percent;
    v.insert(v.end(), row.begin(), row.end());
  }
  return v;
}

}  // namespace fabric
