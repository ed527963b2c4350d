// The point-in-time cases of a case: see points_in_time_case.h.
#include "points_in_time_case.h"

#include <algorithm>
#include <optional>

#include "dayphoton/engine/sun_bins.h"
#include "dayphoton/study/annual_illuminance.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/daylight_factor.h"
#include "dayphoton/study/point_in_time.h"
#include "dayphoton/study/point_in_time_accuracy.h"
#include "dayphoton/study/point_in_time_uncertainty.h"
#include "dayphoton/study/result_files.h"
#include "dayphoton/study/results_model_builder.h"
#include "dayphoton/study/sub_patch_shares.h"
#include "sky_steps.h"
#include "sun_bin_steps.h"

namespace dayphoton::study {

namespace {

/// A cie_overcast case's sky over the DF's (both of the CIE overcast shape): the ratio of the
/// two vectors' sky bins, equal for every bin (ground bin 0 left out).
double overcast_scale(const RadianceMatrix& column, const std::vector<double>& df_luminance) {
  const std::vector<double> case_luminance = sky_vector_luminance(column);
  double case_sky = 0, df_sky = 0;
  for (std::size_t p = 1; p < column.rows(); ++p) {
    case_sky += case_luminance[p];
    df_sky += df_luminance.at(p);
  }
  return df_sky > 0 ? case_sky / df_sky : 0.0;
}

}  // namespace

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
    // The exact direct sun's shadow-ray variance (point_in_time_uncertainty.h): the same rays
    // as the cached direct sun step's (the same seed and random streams), traced again with
    // their variance for the cases' few suns.
    std::vector<double> direct_sun_variance;
    if (bins)
      direct_sun_coefficients(cs.scene, cs.materials, grid.points, skies.suns, ctx.plan.sun_direct_samples,
                              ctx.plan.seed, DirectSunValues::Luminance, {}, &direct_sun_variance);
    // Per case, the standard error of every sensor's illuminance (point_in_time_uncertainty.h).
    std::vector<std::vector<double>> stderr_lux(cases.size());
    std::vector<PointInTimeVarianceParts> parts(cases.size());
    for (std::size_t k = 0; k < cases.size(); ++k) {
      const int sky_index = k < ctx.plan.point_in_time_sky.size() ? ctx.plan.point_in_time_sky[k] : -1;
      RadianceMatrix column(skies.sky.matrix.rows(), 1, skies.sky.matrix.components());
      for (std::size_t p = 0; p < column.rows(); ++p)
        for (int c = 0; c < column.components(); ++c) column.at(p, 0, c) = skies.sky.matrix.at(p, k, c);
      // The sky part's variance as the value is made: the direct part from the case's
      // continuous sky (the CIE cases), the photon part from the DF's continuous sky scaled to
      // the case's (cie_overcast, below), else the sums over the basis.
      const std::optional<std::size_t> direct_sky =
          sky_index >= 0 ? std::optional<std::size_t>(static_cast<std::size_t>(sky_index)) : std::nullopt;
      std::optional<double> photon_sky_scale;
      if (sky_index >= 0 && cases[k].sky == project::PointSky::CieOvercast && !direct_parts.at(g).photon_on_sky.empty())
        photon_sky_scale = overcast_scale(column, df_luminance);
      const SkyIlluminanceVariance sky_variance =
          sky_illuminance_variance(direct_parts.at(g), column, 1.0, direct_sky, photon_sky_scale);
      std::optional<PointInTimeSunVariance> sun_variance;
      for (std::size_t i = 0; i < skies.suns.size(); ++i) {
        if (skies.suns[i].step != k) continue;
        PointInTimeSunVariance v;
        v.disc_radiance = skies.suns[i].disc_radiance;
        v.direct.resize(grid.points.size());
        for (std::size_t s = 0; s < v.direct.size(); ++s) v.direct[s] = direct_sun_variance.at(s * skies.suns.size() + i);
        v.bins = &sun[g].bin_variance;
        v.bin_count = bins->size();
        v.stencil = bins->weights(skies.suns[i].direction);
        sun_variance = std::move(v);
      }
      parts[k] = point_in_time_variance_parts(sky_variance, sun_variance ? &*sun_variance : nullptr);
      stderr_lux[k] = parts[k].stderr_lux();
      if (sky_index < 0) continue;
      // The CIE cases' direct part from their continuous skies, as the daylight factor's.
      std::vector<double> correction =
          continuous_sky_direct_correction_lux(direct_parts.at(g), column, static_cast<std::size_t>(sky_index));
      // A cie_overcast case's photon part: the DF's miss scaled to its sky (the ratio of
      // the two vectors' sky bins, equal for every bin; ground bin 0 left out).
      if (cases[k].sky == project::PointSky::CieOvercast) {
        const double scale = overcast_scale(column, df_luminance);
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
    write_point_in_time_csv(description.world_points(grid.points), names, table, path,  // world coordinates
                            stderr_lux);
    ctx.outputs.record(path);
    nlohmann::json entries = nlohmann::json::array();
    for (std::size_t k = 0; k < cases.size(); ++k) {
      std::vector<double> values(table.sensor_count());
      for (std::size_t i = 0; i < values.size(); ++i) values[i] = table.lux(k, i);
      const GridStatistics st = grid_statistics(values, {});
      // The case's relative standard error over the sensors with light, as the DF's.
      const DaylightFactorUncertainty u = daylight_factor_uncertainty(values, stderr_lux[k]);
      const PointInTimeAccuracy accuracy = assess_point_in_time(
          values, parts[k], sim.accuracy ? sim.accuracy->target_df_relative_stderr_percent : 0.0);
      ctx.log.line(prefix + "point in time " + grid.name + " " + cases[k].name + ": " +
                   point_in_time_accuracy_sentence(accuracy) + " (RMS " + std::to_string(u.rms_relative_stderr_percent) + " %)");
      add_point_in_time(ctx.results->grids[g], cases[k].name, project::point_sky_name(cases[k].sky), st, u);
      entries.push_back({{"name", cases[k].name}, {"sky", project::point_sky_name(cases[k].sky)},
                         {"illuminance_lux", {{"mean", st.mean}, {"median", st.median}, {"min", st.min},
                                              {"max", st.max}, {"uniformity", st.uniformity}}},
                         {"uncertainty", {{"rms_relative_stderr_percent", u.rms_relative_stderr_percent},
                                          {"max_relative_stderr_percent", u.max_relative_stderr_percent},
                                          {"sensors_with_light", u.sensors_with_light}}}});
    }
    grids_json[g]["point_in_time"] = entries;
    ctx.log.line(prefix + "point in time " + grid.name + ": " + std::to_string(cases.size()) + " case(s) at " +
                 std::to_string(grid.points.size()) + " sensors");
  }
}

}  // namespace dayphoton::study
