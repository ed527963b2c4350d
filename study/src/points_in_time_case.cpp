// The point-in-time cases of a case: see points_in_time_case.h.
#include "points_in_time_case.h"

#include <algorithm>
#include <optional>

#include "dayphoton/engine/sun_bins.h"
#include "dayphoton/study/annual_illuminance.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/daylight_factor.h"
#include "dayphoton/study/point_in_time.h"
#include "dayphoton/study/result_files.h"
#include "dayphoton/study/results_model_builder.h"
#include "dayphoton/study/sub_patch_shares.h"
#include "sky_steps.h"
#include "sun_bin_steps.h"

namespace dayphoton::study {

/// The point-in-time cases of one case (point_in_time.h) at every grid: point_in_time.csv per
/// grid and each grid's summary.json `point_in_time` entries (`grids_json[g]`).
void run_points_in_time(const project::Project& project, const std::string& prefix, const CaseScene& cs,
                        const std::vector<RadianceMatrix>& sky_coefficients,
                        const std::vector<engine::DaylightCoefficients>& direct_parts,
                        const std::vector<SubPatchShares>& shares, const std::vector<SubPatchShares>& photon_shares,
                        const std::vector<std::vector<double>>& df_photon_corrections_lux,
                        const std::vector<std::string>& folders, nlohmann::json& grids_json, RunContext& ctx) {
  const project::Simulation& sim = project.simulation;
  const std::vector<project::PointInTimeSpec>& cases = project.points_in_time;
  const bool weather_cases = std::any_of(cases.begin(), cases.end(), [](const project::PointInTimeSpec& c) {
    return c.sky == project::PointSky::Weather;
  });
  const SceneDescription& description = cs.description;
  const sky::PatchBasis& basis = ctx.plan.basis;
  const SkyAndSuns* annual = weather_cases ? &sky_and_suns(project, ctx) : nullptr;
  const sky::SolarSite site = point_in_time_site(project, ctx.sun_site);
  const SkyAndSuns skies = point_in_time_skies(cases, site, basis, sim.ground_reflectance, annual);
  const RadianceMatrix cie_deltas = point_in_time_cie_quadrant_deltas(cases, site, basis, sim.ground_reflectance);
  for (const std::string& line : describe_points_in_time(cases, skies)) ctx.log.line(prefix + "point in time " + line);
  std::vector<GridSun> sun;
  std::optional<engine::SunBins> bins;
  if (!skies.suns.empty()) {
    std::vector<Vec3> directions;
    for (const sky::SunRecord& s : skies.suns) directions.push_back(s.direction);
    bins = engine::SunBins::for_suns(directions, sim.sun_mf);
    sun = run_sun_bins(project, prefix + "point in time ", cs, skies, *bins, ctx);
  }
  // The rest makes the files: not on the other ranks of an MPI run (they write nothing).
  if (!ctx.executor.writes_results()) return;
  const std::vector<double> df_luminance = sky_vector_luminance(ctx.plan.daylight_factor_sky());
  std::vector<std::string> names;
  for (const project::PointInTimeSpec& c : cases) names.push_back(c.name);
  for (std::size_t g = 0; g < description.grids.size(); ++g) {
    const SensorGrid& grid = description.grids[g];
    // A weather case with the annual table's sub-patch correction (direct and photon parts).
    metrics::IlluminanceTable table = annual_illuminance(sky_coefficients[g], skies.sky.matrix, skies.sky.steps, 0,
                                                         &shares.at(g), &skies.sky.quadrant_deltas);
    if (bins) {
      const metrics::IlluminanceTable direct = direct_sun_table(sun[g].direct, skies.suns, skies.sky.steps);
      const metrics::IlluminanceTable indirect =
          indirect_sun_table(sun[g].bin_coefficients, *bins, skies.suns, skies.sky.steps);
      for (std::size_t k = 0; k < table.step_count(); ++k)
        for (std::size_t i = 0; i < table.sensor_count(); ++i)
          table.lux(k, i) = static_cast<float>(double(table.lux(k, i)) + double(direct.lux(k, i)) +
                                               double(indirect.lux(k, i)));
    }
    // The CIE cases' direct part from their continuous skies, as the daylight factor's.
    for (std::size_t k = 0; k < cases.size(); ++k) {
      const int sky_index = k < ctx.plan.point_in_time_sky.size() ? ctx.plan.point_in_time_sky[k] : -1;
      if (sky_index < 0) continue;
      RadianceMatrix column(skies.sky.matrix.rows(), 1, skies.sky.matrix.components());
      for (std::size_t p = 0; p < column.rows(); ++p)
        for (int c = 0; c < column.components(); ++c) column.at(p, 0, c) = skies.sky.matrix.at(p, k, c);
      std::vector<double> correction =
          continuous_sky_direct_correction_lux(direct_parts.at(g), column, static_cast<std::size_t>(sky_index));
      // A cie_overcast case's photon part: the DF's miss scaled to its sky (the ratio of
      // the two vectors' sky bins, equal for every bin; ground bin 0 left out).
      if (cases[k].sky == project::PointSky::CieOvercast) {
        const std::vector<double> case_luminance = sky_vector_luminance(column);
        double case_sky = 0, df_sky = 0;
        for (std::size_t p = 1; p < column.rows(); ++p) {
          case_sky += case_luminance[p];
          df_sky += df_luminance.at(p);
        }
        const double scale = df_sky > 0 ? case_sky / df_sky : 0.0;
        const std::vector<double>& miss = df_photon_corrections_lux.at(g);
        for (std::size_t i = 0; i < correction.size(); ++i) correction[i] += scale * miss.at(i);
      }
      // A cie (general) case's photon part on the sub-patches of its sky.
      if (cases[k].sky == project::PointSky::CieGeneral) {
        const std::vector<double> photon = sub_patch_correction_lux(photon_shares.at(g), cie_deltas, k);
        for (std::size_t i = 0; i < correction.size(); ++i) correction[i] += photon.at(i);
      }
      for (std::size_t i = 0; i < table.sensor_count(); ++i)
        table.lux(k, i) = static_cast<float>(double(table.lux(k, i)) + correction.at(i));
    }
    const std::string path = join_path(folders[g], "point_in_time.csv");
    write_point_in_time_csv(description.world_points(grid.points), names, table, path);  // world coordinates
    ctx.outputs.record(path);
    nlohmann::json entries = nlohmann::json::array();
    for (std::size_t k = 0; k < cases.size(); ++k) {
      std::vector<double> values(table.sensor_count());
      for (std::size_t i = 0; i < values.size(); ++i) values[i] = table.lux(k, i);
      const GridStatistics st = grid_statistics(values, {});
      add_point_in_time(ctx.results->grids[g], cases[k].name, project::point_sky_name(cases[k].sky), st);
      entries.push_back({{"name", cases[k].name}, {"sky", project::point_sky_name(cases[k].sky)},
                         {"illuminance_lux", {{"mean", st.mean}, {"median", st.median}, {"min", st.min},
                                              {"max", st.max}, {"uniformity", st.uniformity}}}});
    }
    grids_json[g]["point_in_time"] = entries;
    ctx.log.line(prefix + "point in time " + grid.name + ": " + std::to_string(cases.size()) + " case(s) at " +
                 std::to_string(grid.points.size()) + " sensors");
  }
}

}  // namespace dayphoton::study
