// The point-in-time cases of a case: see points_in_time_case.h.
#include "points_in_time_case.h"

#include <algorithm>
#include <optional>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/sun_bins.h"
#include "dayphoton/study/plan_policy.h"
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

namespace {

/// One grid's cases before their indirect sun (every rank computes it: the sun rounds measure
/// each case with it, point_in_time_accuracy.h).
struct GridCaseParts {
  metrics::IlluminanceTable sky;                    ///< cases x sensors: the sky over the basis
  std::vector<std::vector<double>> correction_lux;  ///< per case: the continuous skies' corrections (or empty)
  std::vector<SkyIlluminanceVariance> sky_variance; ///< per case
  RadianceMatrix direct;                            ///< sensors x suns x 1: the exact direct sun
  std::vector<double> direct_variance;              ///< sensors x suns, per unit disc radiance squared
  std::vector<int> direct_samples;                  ///< per sun: shadow rays over its disc
  std::vector<std::string> direct_stop;             ///< per sun: "direct rays limit" when it was raised to it
};

/// Sensor s's direct sun of `sun` in lux (direct_sun_table's sum).
double direct_lux(const RadianceMatrix& direct, std::size_t s, std::size_t sun, double disc_radiance) {
  return RadianceWhiteEfficacy_lm_per_W * double(direct.at(s, sun, 0)) * disc_radiance;
}

}  // namespace

/// The point-in-time cases of one case (point_in_time.h) at every grid: point_in_time.csv per
/// grid and each grid's summary.json `point_in_time` entries (`grids_json[g]`).
void run_points_in_time(const project::Project& project, const std::string& prefix, const CaseScene& cs,
                        const std::vector<RadianceMatrix>& sky_coefficients,
                        const std::vector<engine::DaylightCoefficients>& direct_parts,
                        const std::vector<SubPatchShares>& shares, const std::vector<SubPatchShares>& photon_shares,
                        const std::vector<std::vector<double>>& df_photon_corrections_lux,
                        const std::vector<std::string>& sky_stop, const std::vector<std::string>& folders,
                        nlohmann::json& grids_json, RunContext& ctx) {
  const project::Simulation& sim = project.simulation;
  const double target_percent = sim.accuracy ? sim.accuracy->target_df_relative_stderr_percent : 0.0;
  const std::vector<project::PointInTimeSpec>& cases = project.points_in_time;
  const bool weather_cases = std::any_of(cases.begin(), cases.end(), [](const project::PointInTimeSpec& c) {
    return c.sky == project::PointSky::Weather;
  });
  const SceneDescription& description = cs.description;
  const std::vector<SensorGrid>& grids = description.grids;
  const sky::PatchBasis& basis = ctx.plan.basis;
  const SkyAndSuns* annual = weather_cases ? &sky_and_suns(project, ctx) : nullptr;
  const sky::SolarSite site = point_in_time_site(project, ctx.sun_site);
  const SkyAndSuns skies = point_in_time_skies(cases, site, basis, sim.ground_reflectance, annual);
  const RadianceMatrix cie_deltas = point_in_time_cie_quadrant_deltas(cases, site, basis, sim.ground_reflectance);
  for (const std::string& line : describe_points_in_time(cases, skies)) ctx.log.line(prefix + "point in time " + line);
  const std::vector<double> df_luminance = sky_vector_luminance(ctx.plan.daylight_factor_sky());
  // The sun of case k, or -1.
  std::vector<int> sun_of_case(cases.size(), -1);
  for (std::size_t i = 0; i < skies.suns.size(); ++i) sun_of_case[skies.suns[i].step] = static_cast<int>(i);

  // Every grid's cases without their indirect sun: the sky part (value and variance) and the
  // exact direct sun, its shadow rays over the disc raised where its penumbra keeps a case above
  // the target (next_direct_sun_samples).
  std::vector<GridCaseParts> parts_of(grids.size());
  for (std::size_t g = 0; g < grids.size(); ++g) {
    const SensorGrid& grid = grids[g];
    GridCaseParts& gp = parts_of[g];
    // A weather case with the annual table's sub-patch correction (direct and photon parts).
    gp.sky = annual_illuminance(sky_coefficients[g], skies.sky.matrix, skies.sky.steps, 0, &shares.at(g),
                                &skies.sky.quadrant_deltas);
    gp.correction_lux.resize(cases.size());
    for (std::size_t k = 0; k < cases.size(); ++k) {
      const int sky_index = k < ctx.plan.point_in_time_sky.size() ? ctx.plan.point_in_time_sky[k] : -1;
      const RadianceMatrix column = point_in_time_sky_column(skies, k);
      // The sky part's variance as the value is made: the direct part from the case's
      // continuous sky (the CIE cases), the photon part from the DF's continuous sky scaled to
      // the case's (cie_overcast, below), else the sums over the basis.
      const std::optional<std::size_t> direct_sky =
          sky_index >= 0 ? std::optional<std::size_t>(static_cast<std::size_t>(sky_index)) : std::nullopt;
      std::optional<double> photon_sky_scale;
      if (sky_index >= 0 && cases[k].sky == project::PointSky::CieOvercast && !direct_parts.at(g).photon_on_sky.empty())
        photon_sky_scale = overcast_scale(column, df_luminance);
      gp.sky_variance.push_back(sky_illuminance_variance(direct_parts.at(g), column, 1.0, direct_sky, photon_sky_scale));
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
      gp.correction_lux[k] = std::move(correction);
    }
    if (skies.suns.empty()) continue;
    // The exact direct sun with its shadow-ray variance (point_in_time_uncertainty.h), each sun
    // traced alone (a sun's rays do not depend on the other suns: direct_sun_coefficients), at
    // the plan's count and raised while its penumbra keeps its case above the target.
    const std::size_t n_suns = skies.suns.size(), sensors = grid.points.size();
    gp.direct = RadianceMatrix(sensors, n_suns, 1);
    gp.direct_variance.assign(sensors * n_suns, 0.0);
    gp.direct_samples.assign(n_suns, ctx.plan.sun_direct_samples);
    gp.direct_stop.assign(n_suns, "");
    for (std::size_t i = 0; i < n_suns; ++i) {
      const sky::SunRecord& sun = skies.suns[i];
      const std::size_t k = sun.step;
      std::vector<double> other_lux(sensors), other_variance = gp.sky_variance[k].total();
      for (std::size_t s = 0; s < sensors; ++s)
        other_lux[s] = double(gp.sky.lux(k, s)) + (gp.correction_lux[k].empty() ? 0.0 : gp.correction_lux[k][s]);
      const double scale = std::pow(RadianceWhiteEfficacy_lm_per_W * sun.disc_radiance, 2);
      int samples = ctx.plan.sun_direct_samples;
      for (;;) {
        std::vector<double> variance;
        const RadianceMatrix d = direct_sun_coefficients(cs.scene, cs.materials, grid.points, {sun}, samples,
                                                         ctx.plan.seed, DirectSunValues::Luminance, {}, &variance);
        std::vector<double> value(sensors), direct_variance(sensors);
        for (std::size_t s = 0; s < sensors; ++s) {
          gp.direct.at(s, i, 0) = d.at(s, 0, 0);
          gp.direct_variance[s * n_suns + i] = variance[s];
          value[s] = other_lux[s] + direct_lux(d, s, 0, sun.disc_radiance);
          direct_variance[s] = scale * variance[s];
        }
        gp.direct_samples[i] = samples;
        const int next = next_direct_sun_samples(value, other_variance, direct_variance, samples, target_percent);
        if (next == samples) break;
        ctx.log.line(prefix + "point in time " + grid.name + " " + cases[k].name + ": the direct sun's penumbra: " +
                     std::to_string(samples) + " -> " + std::to_string(next) + " shadow rays over the sun's disc");
        samples = next;
      }
      if (samples >= MaxDirectSamplesPerBin) gp.direct_stop[i] = "direct rays limit";
    }
  }

  std::vector<GridSun> sun;
  std::optional<engine::SunBins> bins;
  std::optional<SunAccuracyOutcome> sun_outcome;
  if (!skies.suns.empty()) {
    std::vector<Vec3> directions;
    for (const sky::SunRecord& s : skies.suns) directions.push_back(s.direction);
    bins = engine::SunBins::for_suns(directions, sim.sun_mf);
    // With the target, the sun rounds measure each case's illuminance (SunRoundCase): the other
    // parts' values and variances are this run's.
    std::vector<SunRoundCase> round_cases;
    for (std::size_t i = 0; i < skies.suns.size(); ++i) {
      const std::size_t k = skies.suns[i].step;
      SunRoundCase rc;
      rc.name = cases[k].name;
      rc.sun = i;
      for (std::size_t g = 0; g < grids.size(); ++g) {
        const GridCaseParts& gp = parts_of[g];
        const std::size_t sensors = grids[g].points.size();
        std::vector<double> lux(sensors), variance = gp.sky_variance[k].total();
        const double scale = std::pow(RadianceWhiteEfficacy_lm_per_W * skies.suns[i].disc_radiance, 2);
        for (std::size_t s = 0; s < sensors; ++s) {
          lux[s] = double(gp.sky.lux(k, s)) + (gp.correction_lux[k].empty() ? 0.0 : gp.correction_lux[k][s]) +
                   direct_lux(gp.direct, s, i, skies.suns[i].disc_radiance);
          variance[s] += scale * gp.direct_variance[s * skies.suns.size() + i];
        }
        rc.other_lux.push_back(std::move(lux));
        rc.other_variance.push_back(std::move(variance));
      }
      round_cases.push_back(std::move(rc));
    }
    sun = run_sun_bins(project, prefix + "point in time ", cs, skies, *bins, ctx, SunBinsDirect::ByTheCaller,
                       &sun_outcome, &round_cases);
  }
  // The rest makes the files: not on the other ranks of an MPI run (they write nothing).
  if (!ctx.executor.writes_results()) return;
  std::vector<std::string> names;
  for (const project::PointInTimeSpec& c : cases) names.push_back(c.name);
  for (std::size_t g = 0; g < grids.size(); ++g) {
    const SensorGrid& grid = grids[g];
    GridCaseParts& gp = parts_of[g];
    metrics::IlluminanceTable& table = gp.sky;
    if (bins) {
      const metrics::IlluminanceTable direct = direct_sun_table(gp.direct, skies.suns, skies.sky.steps);
      const metrics::IlluminanceTable indirect =
          indirect_sun_table(sun[g].bin_coefficients, *bins, skies.suns, skies.sky.steps);
      for (std::size_t k = 0; k < table.step_count(); ++k)
        for (std::size_t i = 0; i < table.sensor_count(); ++i)
          table.lux(k, i) = static_cast<float>(double(table.lux(k, i)) + double(direct.lux(k, i)) +
                                               double(indirect.lux(k, i)));
    }
    // Per case, the standard error of every sensor's illuminance (point_in_time_uncertainty.h).
    std::vector<std::vector<double>> stderr_lux(cases.size());
    std::vector<PointInTimeVarianceParts> parts(cases.size());
    for (std::size_t k = 0; k < cases.size(); ++k) {
      std::optional<PointInTimeSunVariance> sun_variance;
      if (sun_of_case[k] >= 0) {
        const std::size_t i = static_cast<std::size_t>(sun_of_case[k]);
        PointInTimeSunVariance v;
        v.disc_radiance = skies.suns[i].disc_radiance;
        v.direct.resize(grid.points.size());
        for (std::size_t s = 0; s < v.direct.size(); ++s) v.direct[s] = gp.direct_variance.at(s * skies.suns.size() + i);
        v.bins = &sun[g].bin_variance;
        v.bin_count = bins->size();
        v.stencil = bins->weights(skies.suns[i].direction);
        sun_variance = std::move(v);
      }
      parts[k] = point_in_time_variance_parts(gp.sky_variance[k], sun_variance ? &*sun_variance : nullptr);
      stderr_lux[k] = parts[k].stderr_lux();
      if (gp.correction_lux[k].empty()) continue;
      for (std::size_t i = 0; i < table.sensor_count(); ++i)
        table.lux(k, i) = static_cast<float>(double(table.lux(k, i)) + gp.correction_lux[k].at(i));
    }
    const std::string path = join_path(folders[g], "point_in_time.csv");
    write_point_in_time_csv(description.world_points(grid.points), names, table, path,  // world coordinates
                            stderr_lux);
    ctx.outputs.record(path);
    nlohmann::json entries = nlohmann::json::array();
    for (std::size_t k = 0; k < cases.size(); ++k) {
      std::vector<double> values(table.sensor_count());
      for (std::size_t i = 0; i < values.size(); ++i) values[i] = table.lux(k, i);
      const GridStatistics st = grid_statistics(values, {}, grid.area_m2);
      // The case's relative standard error over the sensors with light, as the DF's, and
      // against the target: met, or the stop of the part that keeps it above.
      const DaylightFactorUncertainty u = daylight_factor_uncertainty(values, stderr_lux[k]);
      PointInTimeAccuracy accuracy = assess_point_in_time(values, parts[k], target_percent);
      const int i = sun_of_case[k];
      if (i >= 0) accuracy.direct_sun_samples = gp.direct_samples.at(static_cast<std::size_t>(i));
      accuracy.stop_reason = point_in_time_stop_reason(
          accuracy, g < sky_stop.size() ? sky_stop[g] : std::string(),
          sun_outcome ? sun_outcome->stop_reason : std::string(),
          i >= 0 ? gp.direct_stop.at(static_cast<std::size_t>(i)) : std::string());
      ctx.log.line(prefix + "point in time " + grid.name + " " + cases[k].name + ": " +
                   point_in_time_accuracy_sentence(accuracy));
      add_point_in_time(ctx.results->grids[g], cases[k].name, project::point_sky_name(cases[k].sky), st, u,
                        target_percent > 0 ? &accuracy : nullptr);
      nlohmann::json uncertainty = {{"rms_relative_stderr_percent", u.rms_relative_stderr_percent},
                                    {"max_relative_stderr_percent", u.max_relative_stderr_percent},
                                    {"sensors_with_light", u.sensors_with_light}};
      uncertainty["p95_relative_stderr_percent"] = accuracy.reached_percent;
      uncertainty["variance_shares"] = {{"sky", accuracy.sky_share},
                                        {"indirect_sun", accuracy.indirect_sun_share},
                                        {"direct_sun", accuracy.direct_sun_share}};
      if (i >= 0) uncertainty["direct_sun_samples"] = accuracy.direct_sun_samples;
      if (target_percent > 0) {
        uncertainty["target_percent"] = accuracy.target_percent;
        uncertainty["status"] = accuracy.status;
        uncertainty["stop_reason"] = accuracy.stop_reason;
        uncertainty["limiting_part"] = accuracy.status == "met" ? nlohmann::json(nullptr)
                                                                : nlohmann::json(accuracy.limiting_part);
      }
      entries.push_back({{"name", cases[k].name}, {"sky", project::point_sky_name(cases[k].sky)},
                         {"illuminance_lux", {{"mean", st.mean}, {"median", st.median}, {"min", st.min},
                                              {"max", st.max}, {"uniformity", st.uniformity}}},
                         {"uncertainty", uncertainty}});
    }
    grids_json[g]["point_in_time"] = entries;
    ctx.log.line(prefix + "point in time " + grid.name + ": " + std::to_string(cases.size()) + " case(s) at " +
                 std::to_string(grid.points.size()) + " sensors");
  }
}

}  // namespace dayphoton::study
