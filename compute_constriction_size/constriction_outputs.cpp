// The global vector of compute constriction/size (constriction_outputs.h).
#include "constriction_outputs.h"

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

std::vector<double> constriction_vector(const ConstrictionNetwork& net,
                                        double control_percent,
                                        CsdWeight control_weight,
                                        const VerdictGrains& grains,
                                        const GradingCriteria& criteria) {
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
  return v;
}

}  // namespace fabric
