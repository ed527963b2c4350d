// The estimated cost of a case: see case_cost.h.
#include "dayphoton/study/case_cost.h"

#include "dayphoton/engine/sun_bins.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/simulation_plan.h"

namespace dayphoton::study {

SunYear sun_year_of(const project::Project& project, const weather::HourlyWeather* weather, const SunSite* sun_site) {
  SunYear year;
  if (project.study != project::StudyKind::Annual || !weather || !sun_site) return year;
  year.hours = weather->records.size();
  if (project.simulation.sun != project::SunMode::Bins) return year;
  // The suns of build_sky_matrix (the same instants and formulas) whose record has direct light.
  std::vector<Vec3> directions;
  for (const sky::SunRecord& sun : sky::daytime_sun_positions(
           *weather, sun_site->solar, sun_excluded_sky_options(project.simulation.ground_reflectance))) {
    const std::optional<double>& direct = weather->records.at(sun.step).direct_normal_w_m2;
    if (direct && *direct > 0) directions.push_back(sun.direction);
  }
  year.sun_hours = directions.size();
  year.sun_bins = directions.empty() ? 0 : engine::SunBins::for_suns(directions, project.simulation.sun_mf).size();
  return year;
}

double case_cost_seconds(const project::Project& case_project, const SunYear& year) {
  namespace c = case_cost;
  const SimulationPlan plan = SimulationPlan::of(case_project);
  const SceneDescription description = project::build_scene_description(case_project);
  double sensors = 0;
  for (const SensorGrid& grid : description.grids) sensors += static_cast<double>(grid.points.size());
  const double sky_sources = plan.basis.bin_count();  // the sky's bins and the ground (bin 0)
  const double sky_photons =
      static_cast<double>(plan.sky_tracing.photons_per_source) * (sky_sources - 1 + plan.ground_photon_factor);
  double seconds = c::SceneSeconds + sky_photons * c::SkyPhotonSeconds + sensors * sky_sources * c::SkyEstimateSeconds;
  const double bins = static_cast<double>(year.sun_bins);
  seconds += bins * static_cast<double>(plan.sun_tracing.photons_per_source) * c::SunPhotonSeconds +
             sensors * bins * c::SunEstimateSeconds +
             sensors * static_cast<double>(year.sun_hours) * c::DirectSunSeconds;
  if (case_project.outputs.annual_illuminance || case_project.outputs.metrics)
    seconds += sensors * static_cast<double>(year.hours) * c::AnnualMultiplySeconds;
  return seconds;
}

std::vector<double> case_costs_seconds(const project::Project& project, const SunYear& year) {
  std::vector<double> costs{case_cost_seconds(project, year)};
  for (const project::VariantSpec& v : project.variants)
    costs.push_back(case_cost_seconds(project::apply_variant(project, v), year));
  return costs;
}

}  // namespace dayphoton::study
