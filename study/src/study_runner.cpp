// run_study: see study_runner.h for the steps, their cache and the run log.
#include "dayphoton/study/study_runner.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>
#include <tbb/parallel_invoke.h>

#include "dayphoton/core/atomic_file.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/engine/sun_bins.h"
#include "dayphoton/metrics/annual_metrics.h"
#include "dayphoton/study/accuracy_rounds.h"
#include "dayphoton/study/radiance_sun_matrix.h"
#include "dayphoton/study/annual_study.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/cache_folder.h"
#include "dayphoton/study/cache_keys.h"
#include "dayphoton/study/case_cost.h"
#include "dayphoton/study/case_units.h"
#include "dayphoton/study/daylight_factor.h"
#include "dayphoton/study/daylight_openings.h"
#include "dayphoton/study/direct_sun_file.h"
#include "dayphoton/study/output_lock.h"
#include "dayphoton/study/output_manifest.h"
#include "dayphoton/study/placement_check.h"
#include "dayphoton/study/point_in_time.h"
#include "dayphoton/study/sunlight_exposure.h"
#include "dayphoton/study/project_metric_settings.h"
#include "dayphoton/study/result_files.h"
#include "dayphoton/study/compliance_verdicts.h"
#include "dayphoton/study/results_model_builder.h"
#include "dayphoton/study/run_inputs.h"
#include "dayphoton/study/run_timings.h"
#include "dayphoton/study/sun_site.h"
#include "dayphoton/study/verdict_uncertainty.h"
#include "dayphoton/weather/hourly_weather.h"
#include "dayphoton/study/annual_blocks.h"
#include "gather_accuracy_json.h"
#include "json_text.h"
#include "json_values.h"
#include "operated_case.h"
#include "points_in_time_case.h"
#include "run_context.h"
#include "sky_coefficient_steps.h"
#include "sky_steps.h"
#include "sun_bin_steps.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

/// Each coefficient's variance, direct and photon parts together (sensors x sources).
std::vector<double> sky_variance_of(const engine::DaylightCoefficients& c) {
  std::vector<double> v(c.sensors * c.sources);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = c.direct_variance[i] + c.photon_variance[i];
  return v;
}

/// summary.json `uncertainty` of a grid, the annual part (docs/metrics.md, "Uncertainty of
/// the verdicts"). ASE comes from the exact direct sun, whose shadow rays' variance is not
/// estimated: its count is null.
void add_verdict_uncertainty(nlohmann::json& grid, const VerdictUncertainty& u, bool ase) {
  nlohmann::json& j = grid["uncertainty"];
  j["da_verdicts_within_2_sigma"] = u.da_verdicts_uncertain;
  if (u.da_verdicts_uncertain_area_percent)
    j["da_verdicts_within_2_sigma_area_percent"] = *u.da_verdicts_uncertain_area_percent;
  j["illuminance_rms_stderr_lux"] = u.mean_occupied_stderr_lux;
  j["ase_verdicts_within_2_sigma"] = nullptr;
  if (ase) j["ase_note"] = "the exact direct sun's standard error is not estimated";
}

/// summary.json `site` (docs/outputs.md): the site the sun is computed for (the project's, or
/// the weather file header's with from_weather), the sentence every output prints about it,
/// the station's distance and the hours with direct light and the sun below the horizon.
nlohmann::json site_json(const project::Site& project_site, const SunSite* sun_site,
                         const sky::BelowHorizonDirect* below, bool sun_bins) {
  nlohmann::json j = {{"name", project_site.name}, {"from_weather", project_site.from_weather}};
  const sky::SolarSite solar = sun_site ? sun_site->solar
                                        : sky::SolarSite{project_site.latitude_deg, project_site.longitude_deg,
                                                         project_site.time_zone_h, project_site.elevation_m};
  j["latitude_deg"] = solar.latitude_deg;
  j["longitude_deg"] = solar.longitude_deg;
  j["time_zone_h"] = solar.time_zone_h;
  j["elevation_m"] = solar.elevation_m;
  if (!sun_site) {
    j["sun"] = nullptr;
    return j;
  }
  j["sun"] = sun_site_sentence(*sun_site);
  j["station"] = sun_site->station;
  j["station_distance_km"] = sun_site->station_distance_km;
  j["below_horizon_direct"] = {{"hours", below->records},
                               {"hours_over_20_W_m2", below->records_over_20_W_m2},
                               {"direct_normal_kWh_m2", below->direct_normal_Wh_m2 / 1000.0},
                               {"largest_W_m2", below->largest_W_m2},
                               {"their_sun", sun_bins ? "left out" : "spread into the nearest sky patches"}};
  return j;
}

/// summary.json's "sunlight_exposure" of a case: per room its hours, level and spells.
nlohmann::json sunlight_summary(const std::vector<RoomSunlight>& rooms) {
  nlohmann::json a = nlohmann::json::array();
  for (const RoomSunlight& r : rooms) {
    nlohmann::json windows = nlohmann::json::array();
    for (const WindowSunlight& w : r.windows)
      windows.push_back({{"name", w.name}, {"hours", w.hours}, {"intervals", intervals_text(w.intervals)},
                         {"not_assessed", w.not_assessed}});
    a.push_back({{"room", r.room}, {"hours", r.hours}, {"level", r.level}, {"intervals", intervals_text(r.intervals)},
                 {"windows", windows}});
  }
  return a;
}

/// One case: photons, coefficients, daylight factor, annual results, into `dir`/<grid>/.
/// Returns the grids' part of summary.json. `label` prefixes log lines of variants. `keep`
/// (optional) receives the annual tables of every grid for the operated result.
nlohmann::json run_case(const project::Project& project, const std::string& label,
                        const std::string& dir, RunContext& ctx, CaseTables* keep = nullptr) {
  const project::Simulation& sim = project.simulation;
  Progress& progress = ctx.progress;
  RunLog& log = ctx.log;
  RunReport& report = ctx.report;
  const std::string prefix = label.empty() ? "" : label + ": ";
  // The executor's notes (split sources) into the log, under this case's label.
  ctx.executor.set_note_sink([&log, prefix](const std::string& line) { log.line(prefix + line); });

  // 1. Scene, materials, sources, receiver planes.
  progress.start(prefix + "scene", 1, "model");
  SceneDescription description = project::build_scene_description(project);
  // What an imported RADIANCE scene left out or approximated (docs/radiance-import.md).
  for (const Diagnostic& w : description.warnings)
    if (ctx.scene_warnings_logged.insert(w.location.to_string() + ": " + w.message).second)
      log.line(prefix + (w.severity == Severity::Note ? "note: " : "warning: ") + w.location.to_string() + ": " +
               w.message);
  const engine::Scene scene = engine::Scene::build(description);
  // No port, no sensor, a port that faces no decidable way, sensors outside every room or in
  // a solid: located errors; sets with drop_occluded lose those sensors (placement_check.h).
  const PlacementCheck placement =
      check_placement(scene, description.grids, project);
  for (const SensorSetPlacement& set : placement.sets)
    if (set.dropped) {
      log.line(prefix + set.description);
      report.notes.push_back(prefix + set.description);
    }
  // Where the numbers read low without an error (placement_check.h): in the log and the report.
  for (const Diagnostic& w : placement.warnings) {
    log.line(prefix + "warning: " + w.location.to_string() + ": " + w.message);
    report.notes.push_back(prefix + "warning: " + w.message);
  }
  for (const Diagnostic& n : placement.notes) log.line(prefix + "note: " + n.location.to_string() + ": " + n.message);
  // EN 17037's rule for horizontal daylight openings, per sensor set (daylight_openings.h).
  ctx.openings.clear();
  for (std::size_t g = 0; g < placement.openings.size() && g < description.grids.size(); ++g)
    ctx.openings[description.grids[g].name] = placement.openings[g].kind;
  const std::vector<engine::Material> materials = engine::materials_of(description.materials);
  const SimulationPlan& plan = ctx.plan;
  const sky::PatchBasis& basis = plan.basis;
  set_plan_geometry(*ctx.results, description);  // in world coordinates
  set_building(*ctx.results, project, description);
  // EN 17037 exposure to sunlight: shadow rays through this case's scene (sunlight_exposure.h).
  if (project.sunlight_exposure) {
    const project::SunlightExposureSpec& se = *project.sunlight_exposure;
    SunlightDay day{point_in_time_site(project, ctx.sun_site), PointInTimeSolarYear, se.month, se.day,
                    se.min_altitude_deg, se.time_step_min};
    ctx.results->sunlight_exposure = assess_sunlight_exposure(project, description, scene, day);
    for (const std::string& line : sunlight_log_lines(ctx.results->sunlight_exposure)) log.line(prefix + line);
  }
  const engine::SourceSet sources = engine::SourceSet::sky_bins(basis);
  const CaseLayout layout = CaseLayout::of(description.grids, scene, materials);
  const CaseScene cs{description, scene, materials, layout, scene_key(description), planes_key(description.grids)};
  // The grids as the user reads them: in world coordinates (SceneDescription::world_origin_m,
  // project/local_origin.h); the engine and the cache keep the description's own.
  std::vector<SensorGrid> world_grids;
  for (const SensorGrid& g : description.grids) world_grids.push_back(description.world_grid(g));
  progress.advance(1);
  progress.end();

  // 2-3. Photons, one cached step per source, and coefficients, one cached step per grid
  // (sky_coefficient_steps.h); or, with an accuracy target, rounds until the daylight factors
  // reach it (accuracy_rounds.h).
  const engine::TracingOptions tracing = plan.tracing_for(plan.sky_tracing, layout);
  const std::vector<std::string> photon_keys = sky_photon_keys(cs, basis, sources.size(), tracing);
  std::vector<std::optional<engine::DaylightCoefficients>> coefficients(description.grids.size());
  std::optional<AccuracyOutcome> accuracy;
  if (sim.accuracy) {
    accuracy = accuracy_sky_coefficients(project, cs, sources, tracing, photon_keys, prefix, ctx, coefficients);
  } else {
    sky_coefficients(cs, sources, tracing, photon_keys, prefix, ctx, coefficients);
  }

  // 4. Daylight factor and coefficient export per grid.
  const RadianceMatrix overcast_vector = plan.daylight_factor_sky();
  const MatrixFormat matrix_format = parse_matrix_format(project.outputs.matrix_format);
  nlohmann::json grids_json = nlohmann::json::array();
  std::vector<RadianceMatrix> coefficient_matrices;
  // Per grid, the direct part's sub-patch shares for the annual product (sub_patch_shares.h).
  std::vector<SubPatchShares> sub_patches;
  const bool annual_product = project.study != project::StudyKind::DaylightFactor &&
                              (project.outputs.annual_illuminance || project.outputs.metrics);
  std::vector<std::vector<double>> sky_variances;  // sensors x sources per grid (sky_variance_of)
  // Per grid, for the point-in-time cases: the direct part (with its continuous skies) and the
  // photon part's variances (by bin and on the DF sky), not the photon part's values.
  std::vector<engine::DaylightCoefficients> point_direct_parts;
  std::vector<std::vector<double>> point_photon_corrections;  // per grid, lux under the DF sky
  // Per grid, the whole coefficients' and the photon part's sub-patch shares (sub_patch_shares.h).
  std::vector<SubPatchShares> point_shares, point_photon_shares;
  std::vector<std::string> folders;
  for (std::size_t g = 0; g < description.grids.size(); ++g) {
    const SensorGrid& grid = description.grids[g];
    const std::string folder = join_path(dir, grid.name);
    if (ctx.executor.writes_results()) fs::create_directories(folder);  // not by the other ranks of an MPI run
    folders.push_back(folder);
    report.grids.push_back({label.empty() ? grid.name : label + "/" + grid.name, grid.points.size(), folder});
    coefficient_matrices.push_back(coefficients[g]->to_matrix());
    sub_patches.push_back(annual_product || project.outputs.coefficients ? sub_patch_shares(*coefficients[g])
                                                                         : SubPatchShares{});
    const RadianceMatrix& c = coefficient_matrices.back();
    if (ctx.executor.writes_results()) {
      write_sensors_csv(world_grids[g].points, world_grids[g].area_m2, join_path(folder, "sensors.csv"));
      ctx.outputs.record(join_path(folder, "sensors.csv"));
    }
    nlohmann::json gj = {{"name", grid.name}, {"sensors", grid.points.size()}, {"folder", folder}};
    ctx.results->grids.push_back(results_grid(world_grids[g], relative_folder(report.output_dir, folder), *ctx.results,
                                              placement.sets[g].dropped ? placement.sets[g].outside : 0,
                                              placement.sets[g].dropped ? placement.sets[g].inside_solid : 0,
                                              placement.sets[g].dropped ? placement.sets[g].on_cut : 0,
                                              placement.sets[g].dropped ? placement.sets[g].enclosed : 0));
    if (placement.sets[g].dropped) {
      gj["dropped_sensors"] = {{"outside_rooms", placement.sets[g].outside},
                               {"inside_solid", placement.sets[g].inside_solid}};
      if (placement.sets[g].on_cut > 0) gj["dropped_sensors"]["on_cut_surface"] = placement.sets[g].on_cut;
      if (placement.sets[g].enclosed > 0) gj["dropped_sensors"]["enclosed"] = placement.sets[g].enclosed;
    }
    if (project.outputs.coefficients && ctx.executor.writes_results()) {  // not by the other ranks of an MPI run
      c.write_file(join_path(folder, "coefficients_sky.mtx"), matrix_format);
      ctx.outputs.record(join_path(folder, "coefficients_sky.mtx"));
      if (!sub_patches.back().empty()) {  // for dayphoton annual (sub_patch_shares.h)
        sub_patch_shares_matrix(sub_patches.back()).write_file(join_path(folder, SubPatchSharesFileName), matrix_format);
        ctx.outputs.record(join_path(folder, SubPatchSharesFileName));
      }
    }
    if (project.outputs.daylight_factor) {
      // The sky component from the continuous sky, the rest over the basis, with the Monte
      // Carlo standard error beside each value (daylight_factor.h, engine/estimate_variance.h).
      const DaylightFactorParts parts = daylight_factor_parts(*coefficients[g], overcast_vector,
                                                              plan.overcast_horizontal_lux, DaylightFactorSkyIndex);
      // Rows whose photon part stayed on the basis sum (gathered without the sky ratios,
      // engine/photon_part_on_sky.h; every row without a photon part on the sky): none in a
      // run of the plan; said where any are.
      const engine::PhotonOnSky& on_sky = coefficients[g]->photon_on_sky;
      const std::size_t basis_rows = on_sky.empty() ? coefficients[g]->sensors : on_sky.basis_rows;
      if (basis_rows > 0) {
        gj["daylight_factor_photon_part_basis_rows"] = basis_rows;
        log.line(prefix + "grid " + grid.name + ": " + std::to_string(basis_rows) +
                 " sensor(s)' photon part on the sky basis, not on the continuous overcast sky");
      }
      const std::vector<double>& df = parts.df_percent;
      const std::vector<double> df_stderr = parts.stderr_percent();
      if (ctx.executor.writes_results()) {
        write_daylight_factor_csv(world_grids[g].points, df, join_path(folder, "daylight_factor.csv"), df_stderr);
        ctx.outputs.record(join_path(folder, "daylight_factor.csv"));
      }
      const GridStatistics st = grid_statistics(df, project.metrics.daylight_factor_thresholds_percent, grid.area_m2);
      nlohmann::json areas = nlohmann::json::array();
      for (const auto& [threshold, area] : st.area_at_or_above_percent)
        areas.push_back({{"threshold_percent", threshold}, {"area_percent", area}});
      gj["daylight_factor_percent"] = {{"mean", st.mean}, {"median", st.median}, {"min", st.min},
                                       {"max", st.max}, {"uniformity", st.uniformity},
                                       {"area_at_or_above", areas}};
      const DaylightFactorUncertainty u = daylight_factor_uncertainty(df, df_stderr);
      gj["uncertainty"] = {{"df_rms_relative_stderr_percent", u.rms_relative_stderr_percent},
                           {"df_max_relative_stderr_percent", u.max_relative_stderr_percent},
                           {"sensors_with_daylight", u.sensors_with_light}};
      if (accuracy) gj["uncertainty"]["df_p95_relative_stderr_percent"] = accuracy->reached_percent[g];
      add_daylight_factor(ctx.results->grids.back(), st, u);
      if (accuracy) {
        DaylightFactorSummary::AccuracyReached reached{accuracy->target_percent, accuracy->reached_percent[g],
                                                       accuracy->rounds,         accuracy->photons,
                                                       accuracy->stop_reason,    accuracy->grid_status[g]};
        if (g < accuracy->gather.size() && accuracy->gather[g].gathered) {
          reached.gather_rays = accuracy->gather[g].rays;
          reached.gather_rounds = accuracy->gather[g].rounds;
          reached.gather_stop_reason = accuracy->gather[g].stop_reason;
        }
        reached.direct_samples_per_bin = accuracy->direct_samples_per_bin.at(g);
        if (g < accuracy->near_cut.size() && accuracy->near_cut[g].sensors > 0) {
          reached.near_cut_sensors = accuracy->near_cut[g].sensors;
          reached.near_cut_gather_rays = accuracy->near_cut[g].gather_rays;
          reached.near_cut_largest_percent = accuracy->near_cut[g].largest_percent;
          reached.near_cut_gather_rounds = accuracy->near_cut[g].rounds;
          reached.near_cut_stop_reason = accuracy->near_cut[g].stop_reason;
        }
        ctx.results->grids.back().daylight_factor->accuracy = reached;
      }
    }
    if (accuracy)
      gj["accuracy"] = {{"target_df_relative_stderr_percent", accuracy->target_percent},
                        {"reached_df_relative_stderr_percent", accuracy->reached_percent[g]},
                        {"measure", "95th percentile (nearest rank) of the sensors' relative standard error of DF"},
                        {"rounds", accuracy->rounds},
                        {"photons", accuracy->photons},
                        {"attempts", accuracy->attempts},
                        {"stop_reason", accuracy->stop_reason},
                        {"status", accuracy->grid_status[g]},
                        {"direct_samples_per_bin", accuracy->direct_samples_per_bin.at(g)}};
    if (accuracy && g < accuracy->gather.size() && accuracy->gather[g].gathered) {
      gj["accuracy"]["gather"] = gather_accuracy_json(accuracy->gather[g]);
      gj["accuracy"]["gather"].erase("gathered");
    }
    if (accuracy && g < accuracy->near_cut.size() && accuracy->near_cut[g].sensors > 0)
      gj["accuracy"]["near_cut"] = near_cut_reached_json(accuracy->near_cut[g], accuracy->target_percent);
    grids_json.push_back(gj);
    // Of the sky coefficients' parts only the matrix and the variances are needed from here on.
    sky_variances.push_back(sky_variance_of(*coefficients[g]));
    if (!project.points_in_time.empty()) {
      point_photon_corrections.push_back(continuous_sky_photon_correction_lux(*coefficients[g], overcast_vector));
      point_shares.push_back(annual_product || project.outputs.coefficients ? sub_patches.back()
                                                                            : sub_patch_shares(*coefficients[g]));
      point_photon_shares.push_back(sub_patch_shares(*coefficients[g], SharesOf::PhotonPart));
      engine::DaylightCoefficients part;
      part.sensors = coefficients[g]->sensors;
      part.sources = coefficients[g]->sources;
      part.direct = std::move(coefficients[g]->direct);
      part.direct_variance = std::move(coefficients[g]->direct_variance);
      part.direct_on_skies = std::move(coefficients[g]->direct_on_skies);
      // The photon part's variances, for the cases' standard errors (point_in_time_uncertainty.h).
      part.photon_variance = std::move(coefficients[g]->photon_variance);
      part.photon_on_sky = std::move(coefficients[g]->photon_on_sky);
      point_direct_parts.push_back(std::move(part));
    }
    coefficients[g].reset();
  }

  // 5-6. Annual illuminance and metrics.
  const bool annual = project.outputs.annual_illuminance || project.outputs.metrics;
  // The annual multiply (not cached) only where its result is kept: not by a unit executor
  // (case_units.h), which writes nothing and shares no blocks; its steps still run.
  const bool multiply = annual && (ctx.executor.writes_results() || ctx.executor.shares_sensor_blocks());
  const bool sun_bins = sim.sun == project::SunMode::Bins;
  const AnnualOutputs which = annual_outputs_of(project);
  // The schedule the metrics of each grid use (docs/metrics.md "Occupancy schedules").
  auto log_occupancy = [&](const std::string& grid, const AnnualStudy& study, const AnnualStudySettings& settings) {
    log.line(prefix + "occupancy " + grid + ": " + settings.occupancy.description() + "; " +
             std::to_string(study.occupied_hours) + " occupied hours of " +
             std::to_string(study.illuminance.step_count()));
  };
  if (project.study == project::StudyKind::DaylightFactor) {
    // Nothing annual: no sky matrix, no sun (the loader turned the annual outputs off).
  } else if (sun_bins && (annual || project.outputs.coefficients)) {
    // Sun bins: sky-only matrix + exact direct sun + interpolated indirect sun.
    const SkyAndSuns& ss = sky_and_suns(project, ctx);
    std::vector<Vec3> directions;
    for (const sky::SunRecord& sun : ss.suns) directions.push_back(sun.direction);
    const engine::SunBins bins = engine::SunBins::for_suns(directions, sim.sun_mf);
    std::optional<SunAccuracyOutcome> sun_accuracy;
    std::vector<GridSun> sun =
        run_sun_bins(project, prefix, cs, ss, bins, ctx,
                     project.outputs.coefficients ? SunBinsDirect::TracedAndExported : SunBinsDirect::Traced,
                     &sun_accuracy);
    if (sun_accuracy)
      for (std::size_t g = 0; g < description.grids.size(); ++g) {
        ctx.results->grids[g].sun_accuracy = SunAccuracyReached{
            sun_accuracy->target_percent, sun_accuracy->reached_percent[g], sun_accuracy->hourly_percent[g],
            sun_accuracy->rounds,         sun_accuracy->photons,            sun_accuracy->stop_reason,
            sun_accuracy->grid_status[g]};
        if (g < sun_accuracy->gather.size() && sun_accuracy->gather[g].gathered) {
          SunAccuracyReached& r = *ctx.results->grids[g].sun_accuracy;
          r.gather_rays = sun_accuracy->gather[g].rays;
          r.gather_rounds = sun_accuracy->gather[g].rounds;
          r.gather_stop_reason = sun_accuracy->gather[g].stop_reason;
        }
        if (g < sun_accuracy->near_cut.size() && sun_accuracy->near_cut[g].sensors > 0) {
          SunAccuracyReached& r = *ctx.results->grids[g].sun_accuracy;
          r.near_cut_sensors = sun_accuracy->near_cut[g].sensors;
          r.near_cut_gather_rays = sun_accuracy->near_cut[g].gather_rays;
          r.near_cut_largest_percent = sun_accuracy->near_cut[g].largest_percent;
          r.near_cut_gather_rounds = sun_accuracy->near_cut[g].rounds;
          r.near_cut_stop_reason = sun_accuracy->near_cut[g].stop_reason;
        }
        grids_json[g]["accuracy"]["sun"] = {
            {"target_relative_stderr_percent", sun_accuracy->target_percent},
            {"reached_relative_stderr_percent", sun_accuracy->reached_percent[g]},
            {"measure", "95th percentile (nearest rank) of the sensors' relative standard error of the annual "
                        "sun-bin illuminance"},
            {"hourly_relative_stderr_percent", sun_accuracy->hourly_percent[g]},
            {"status", sun_accuracy->grid_status[g]},
            {"rounds", sun_accuracy->rounds},
            {"photons", sun_accuracy->photons},
            {"attempts", sun_accuracy->attempts},
            {"stop_reason", sun_accuracy->stop_reason}};
        if (g < sun_accuracy->gather.size() && sun_accuracy->gather[g].gathered) {
          grids_json[g]["accuracy"]["sun"]["gather"] = gather_accuracy_json(sun_accuracy->gather[g]);
          grids_json[g]["accuracy"]["sun"]["gather"].erase("gathered");
        }
        if (g < sun_accuracy->near_cut.size() && sun_accuracy->near_cut[g].sensors > 0)
          grids_json[g]["accuracy"]["sun"]["near_cut"] =
              near_cut_reached_json(sun_accuracy->near_cut[g], sun_accuracy->target_percent);
      }
    for (std::size_t g = 0; g < description.grids.size(); ++g) {
      const SensorGrid& grid = description.grids[g];
      if (project.outputs.coefficients && ctx.executor.writes_results()) {  // not by the other ranks of an MPI run
        // Independent files, each written by one thread: the two at once.
        tbb::parallel_invoke(
            [&] {
              // The header line on the matrix itself for the file (no copy of sensors x bins x RGB).
              RadianceMatrix& c = sun[g].bin_coefficients;
              c.header_lines().push_back("dayphoton sun-bin coefficients: caustic + global irradiance per unit "
                                         "disc radiance; columns = rows of sun_bins.csv");
              c.write_file(join_path(folders[g], "coefficients_sun.mtx"), matrix_format);
              c.header_lines().pop_back();
              write_sun_bins_csv(bins, ss.suns, join_path(folders[g], "sun_bins.csv"));
            },
            [&] {
              DirectSunExport exported =
                  make_direct_sun_export({{&sun[g].direct, &ss.suns}, {&sun[g].direct_other, &sun[g].other_suns}});
              exported.sun_bins_mf = bins.multiplication_factor();
              exported.seed = sim.seed;
              exported.samples = plan.sun_direct_samples;
              exported.site = sun_site_sentence(*ctx.sun_site);
              exported.weather = project.weather.path;
              write_direct_sun_file(exported, join_path(folders[g], DirectSunFileName));
            });
        ctx.outputs.record({join_path(folders[g], "coefficients_sun.mtx"), join_path(folders[g], "sun_bins.csv"),
                            join_path(folders[g], DirectSunFileName)});
      }
      if (project.outputs.coefficients && project.outputs.radiance_sun_matrix) {
        // The same sun on RADIANCE's patch basis, for gendaymtx -d (radiance_sun_matrix.h):
        // its direct sun is a step of every rank, the file rank 0's.
        std::vector<sky::SunRecord> daytime = ss.suns;
        daytime.insert(daytime.end(), sun[g].other_suns.begin(), sun[g].other_suns.end());
        const std::string d_path = join_path(folders[g], radiance_sun_matrix_name(bins.multiplication_factor()));
        progress.start(prefix + "sun matrix for RADIANCE " + grid.name, grid.points.size(), "sensors");
        const std::string line = write_radiance_sun_matrix(scene, materials, grid, cs.scene_hash, bins,
                                                           sun[g].bin_coefficients, daytime, plan.sun_direct_samples,
                                                           sim.seed, ctx.executor, d_path, matrix_format);
        progress.advance(grid.points.size());
        progress.end();
        if (ctx.executor.writes_results()) {
          log.line(prefix + line);
          ctx.outputs.record(d_path);
        }
      }
      // The other daytime suns' direct sun served the exports alone.
      sun[g].direct_other = RadianceMatrix{};
      sun[g].other_suns = {};
      if (!multiply) continue;
      progress.start(prefix + "annual " + grid.name, ss.sky.steps.size(), "hours");
      AnnualStudySettings annual_settings = annual_settings_of(project, ctx.weather, ctx.openings_of(grid.name), grid.name);
      annual_settings.sensor_area_m2 = grid.area_m2;
      GridSunCoefficients grid_sun{&sun[g].direct, &ss.suns, &sun[g].bin_coefficients, &bins};
      // The direct sun held sparse from here on, where nothing else reads it (the operated
      // result reads its hourly table, the blocks of an MPI run their dense rows).
      SparseSunRows direct_rows;
      if (!keep && !ctx.executor.shares_sensor_blocks()) {
        direct_rows = SparseSunRows::of(sun[g].direct);
        sun[g].direct = RadianceMatrix{};
        grid_sun.direct_rows = &direct_rows;
      }
      std::optional<AnnualStudy> computed;
      if (ctx.executor.shares_sensor_blocks()) {
        // By sensor blocks over the ranks; rank 0 alone gets the study and writes it (annual_blocks.h).
        computed = annual_study_in_blocks(ctx.executor, prefix + grid.name, coefficient_matrices[g], ss.sky,
                                          annual_settings, &grid_sun, &sub_patches[g]);
      } else {
        // The sun added to the sky's table in place (no hourly direct and indirect tables held).
        computed =
            compute_annual_study_with_sun(coefficient_matrices[g], ss.sky, grid_sun, annual_settings, &sub_patches[g]);
      }
      if (computed && keep)  // operated shading picks hours by the direct sun's table
        keep->grids.push_back(
            {grid.name, world_grids[g].points, grid.area_m2, computed->illuminance, direct_sun_table(sun[g].direct, ss.suns, ss.sky.steps)});
      // The hourly table holds the sun now: its direct sun (sensors x suns) and sun-bin
      // coefficients (sensors x bins x RGB) are released before the outputs and the verdicts,
      // which read the table and the bins' variances alone (docs/photon-tracing.md "Scale").
      sun[g].direct = RadianceMatrix{};
      direct_rows = SparseSunRows{};
      sun[g].bin_coefficients = RadianceMatrix{};
      if (!computed) {  // another rank than 0
        progress.end();
        continue;
      }
      const AnnualStudy& study = *computed;
      log_occupancy(grid.name, study, annual_settings);
      const SunBinVariance sun_variance{&sun[g].bin_variance, &bins, &ss.suns};
      VerdictUncertainty verdicts;
      ctx.outputs.record(write_annual_outputs_beside(study, world_grids[g].points, annual_settings, folders[g], which, [&] {
        verdicts = verdict_uncertainty(study, ss.sky, sky_variances[g], &sun_variance, annual_settings);
      }));
      sun[g].bin_variance = {};
      add_verdict_uncertainty(grids_json[g], verdicts, true);
      add_annual(ctx.results->grids[g], study, annual_settings, which);
      add_verdict_uncertainty(ctx.results->grids[g], verdicts);
      progress.advance(ss.sky.steps.size());
      progress.end();
      grids_json[g]["annual"] = grid_metrics_value(study, annual_settings);
    }
  } else if (annual) {
    const AnnualSky& sky = annual_sky(project, ctx);
    for (std::size_t g = 0; g < description.grids.size() && multiply; ++g) {
      const SensorGrid& grid = description.grids[g];
      progress.start(prefix + "annual " + grid.name, sky.steps.size(), "hours");
      AnnualStudySettings annual_settings = annual_settings_of(project, ctx.weather, ctx.openings_of(grid.name), grid.name);
      annual_settings.sensor_area_m2 = grid.area_m2;
      // By sensor blocks over the ranks of an MPI run; rank 0 alone gets the study and writes it.
      const std::optional<AnnualStudy> computed =
          ctx.executor.shares_sensor_blocks()
              ? annual_study_in_blocks(ctx.executor, prefix + grid.name, coefficient_matrices[g], sky, annual_settings,
                                       nullptr, &sub_patches[g])
              : std::optional<AnnualStudy>(
                    compute_annual_study(coefficient_matrices[g], sky, annual_settings, nullptr, &sub_patches[g]));
      if (!computed) {  // another rank than 0
        progress.end();
        continue;
      }
      const AnnualStudy& study = *computed;
      log_occupancy(grid.name, study, annual_settings);
      VerdictUncertainty verdicts;
      ctx.outputs.record(write_annual_outputs_beside(study, world_grids[g].points, annual_settings, folders[g], which, [&] {
        verdicts = verdict_uncertainty(study, sky, sky_variances[g], nullptr, annual_settings);
      }));
      add_verdict_uncertainty(grids_json[g], verdicts, false);
      add_annual(ctx.results->grids[g], study, annual_settings, which);
      add_verdict_uncertainty(ctx.results->grids[g], verdicts);
      progress.advance(sky.steps.size());
      progress.end();
      grids_json[g]["annual"] = grid_metrics_value(study, annual_settings);
    }
  }
  // 7. Point-in-time cases.
  if (!project.points_in_time.empty()) {
    // Per grid, the sky rounds' stop, for the cases the sky part keeps above the target: the
    // rounds measure the cases' skies too (AccuracyCase::case_skies), so a grid whose daylight
    // factor met the target has the rounds' own stop unless they met every measure.
    std::vector<std::string> sky_stop;
    for (std::size_t g = 0; accuracy && g < description.grids.size(); ++g) {
      const bool all_met = accuracy->stop_reason == "target met" || accuracy->stop_reason == "not reachable by photons";
      sky_stop.push_back(accuracy->grid_status.at(g) == "met" && all_met ? "target met" : accuracy->stop_reason);
    }
    run_points_in_time(project, prefix, cs, coefficient_matrices, point_direct_parts, point_shares, point_photon_shares,
                       point_photon_corrections, sky_stop, folders, grids_json, ctx);
  }
  return grids_json;
}

}  // namespace

std::string run_cache_folder(const project::Project& project, const RunSettings& settings) {
  const std::string output_dir = settings.output_dir.empty() ? project.outputs.folder : settings.output_dir;
  return settings.cache_dir.empty() ? default_cache_folder(output_dir) : settings.cache_dir;
}

void run_case_steps(const project::Project& project, const RunInputs& inputs, std::size_t case_index,
                    const RunSettings& settings, const ArtifactStore& store, StepExecutor& executor,
                    Progress& progress) {
  if (case_index > project.variants.size())
    throw std::logic_error("run_case_steps: case " + std::to_string(case_index) + " of a project of " +
                           std::to_string(1 + project.variants.size()) + " cases");
  const std::string output_dir = settings.output_dir.empty() ? project.outputs.folder : settings.output_dir;
  const SimulationPlan plan = SimulationPlan::of(project, inputs.sun_site ? &*inputs.sun_site : nullptr);
  OutputManifest outputs = OutputManifest::none(output_dir);
  RunReport report;
  report.output_dir = output_dir;
  RunLog log(progress, std::string());
  RunContext ctx{settings, progress, log, report, store, outputs, plan, executor, std::nullopt, std::nullopt,
                 inputs.weather ? &*inputs.weather : nullptr, inputs.sun_site ? &*inputs.sun_site : nullptr};
  CaseResult unused = results_case("base", "", "", {});
  ctx.results = &unused;
  if (case_index == 0) {
    run_case(project, "", output_dir, ctx);
  } else {
    const project::VariantSpec& v = project.variants[case_index - 1];
    run_case(project::apply_variant(project, v), v.name, join_path(join_path(output_dir, "variants"), v.name), ctx);
  }
}

RunReport run_study(const project::Project& project, const RunSettings& settings,
                    Progress& progress) {
  // The run's own clock, for timings.json (the history of the run, not a result).
  const auto run_start = std::chrono::steady_clock::now();
  const double run_cpu_start = Progress::process_cpu_seconds();
  RunReport report;
  const project::Simulation& sim = project.simulation;
  // The weather file, the site of its sun, the points in time (run_inputs.h): input errors,
  // reported before anything is written. Read here unless the caller read them already.
  const bool annual_study = project.study == project::StudyKind::Annual;
  const project::OperationSpec* op = project.operation ? &*project.operation : nullptr;
  std::optional<RunInputs> read_inputs;
  std::exception_ptr input_failure;
  if (!settings.inputs) {
    try {
      read_inputs = read_run_inputs(project);
    } catch (...) {
      input_failure = std::current_exception();
    }
  }
  if (settings.inputs_checked) settings.inputs_checked(input_failure);
  if (input_failure) std::rethrow_exception(input_failure);
  const RunInputs& inputs = settings.inputs ? *settings.inputs : *read_inputs;
  const std::optional<weather::HourlyWeather>& weather = inputs.weather;
  const std::optional<SunSite>& sun_site = inputs.sun_site;
  const std::optional<sky::BelowHorizonDirect>& below_horizon = inputs.below_horizon;
  report.output_dir = settings.output_dir.empty() ? project.outputs.folder : settings.output_dir;
  // The cache beside the output folder (cache_folder.h), and the executor every cached step
  // goes through (step_executor.h). Neither touches the disk before a step runs.
  const std::string cache_dir = run_cache_folder(project, settings);
  const ArtifactStore store = settings.store ? *settings.store : ArtifactStore(cache_dir);
  if (store.directory() != cache_dir)
    throw std::logic_error("run_study: the store of " + store.directory() + " for the cache " + cache_dir);
  const std::unique_ptr<StepExecutor> executor =
      settings.make_executor ? settings.make_executor(store, settings.force) : make_local_executor(store, settings.force);
  // The writer flag: the ranks other than 0 of an MPI run write nothing at all (no lock, no
  // manifest, no run.log, no result file, nothing in the cache); they take part in every step.
  const bool writer = executor->writes_results();
  std::optional<OutputLock> lock;
  bool adopted = false;
  std::size_t temporaries = 0;
  std::string this_run;
  if (writer) {
    fs::create_directories(report.output_dir);
    // One run per folder (output_lock.h); then what earlier runs left: temporaries of killed
    // writers, and the outputs of the previous run, which this one replaces (output_manifest.h).
    lock.emplace(OutputLock::acquire(report.output_dir, settings.command));
    // An earlier version's cache inside the output folder moves to the cache folder.
    adopted = adopt_legacy_cache(report.output_dir, cache_dir);
    temporaries = remove_dead_temporaries(report.output_dir) + remove_dead_temporaries(cache_dir);
    this_run = lock->owner().describe();
  }
  OutputManifest outputs = writer ? OutputManifest::begin(report.output_dir, this_run) : OutputManifest::none(report.output_dir);
  if (writer) {
    // The previous run's times go with its outputs: a report of this folder must not show them.
    std::error_code no_timings;
    fs::remove(join_path(report.output_dir, TimingsFileName), no_timings);
  }
  RunLog log(progress, writer ? join_path(report.output_dir, "run.log") : std::string());
  log.line("project " + project.path + " -> " + report.output_dir);
  log.quiet_line("run: " + this_run);
  log.quiet_line("cache: " + cache_dir);
  if (adopted)
    log.line("moved the cache of an earlier version from " + legacy_cache_folder(report.output_dir) + " to " + cache_dir);
  // What the weather reader accepted with a warning (ignored fields, filled gaps, variants).
  if (weather)
    for (const Diagnostic& w : weather->warnings) log.line("weather: " + w.format().substr(0, w.format().find('\n')));
  if (lock && lock->taken_over())
    log.line("took over the lock of a run that no longer exists: " + lock->taken_over()->describe());
  if (temporaries > 0)
    log.line("removed " + std::to_string(temporaries) + " temporary file(s) of interrupted writes");
  if (outputs.stale_removed() > 0)
    log.line("removed " + std::to_string(outputs.stale_removed()) + " output file(s) of the previous run");
  if (!annual_study)
    report.notes.push_back(
        "study: daylight factors under the CIE overcast sky (study: daylight_factor): no weather file read, no "
        "sun traced, no annual results");
  else if (sim.sun == project::SunMode::Bins)
    report.notes.push_back(
        "sun: sun bins (Reinhart MF " + std::to_string(sim.sun_mf) +
        " patch centres on the sun path, indirect light interpolated) and the direct sun traced "
        "exactly every hour; the sky matrix excludes the sun; ASE from the direct sun");
  else
    report.notes.push_back(
        "sun: spread into the 4 nearest sky patches as RADIANCE's gendaymtx does (RADIANCE-compatible "
        "mode); no ASE");
  if (sun_site) {
    report.notes.push_back("site: " + sun_site_sentence(*sun_site));
    if (const std::string w = station_distance_warning(*sun_site); !w.empty()) report.notes.push_back("site: " + w);
    report.notes.push_back(below_horizon_note(*below_horizon, sim.sun == project::SunMode::Bins));
  }
  for (const project::SystemSpec& system : project.geometry.systems)
    report.notes.push_back("system: " + project::describe_system_light(system));
  for (const std::string& n : report.notes) log.line(n);

  CaseTables open_tables, shaded_tables;
  auto keep = [&](const std::string& name) -> CaseTables* {
    if (!op) return nullptr;
    if (name == op->open.value) return &open_tables;
    if (name == op->shaded.value) return &shaded_tables;
    return nullptr;
  };

  // The plan, built once (simulation_plan.h).
  const SimulationPlan plan = SimulationPlan::of(project, sun_site ? &*sun_site : nullptr);
  RunContext ctx{settings, progress, log, report, store, outputs, plan, *executor, std::nullopt, std::nullopt,
                 weather ? &*weather : nullptr, sun_site ? &*sun_site : nullptr};
  // With at least as many cases as MPI ranks, whole cases are the units (case_units.h), dealt
  // out by their estimated cost (case_cost.h): each rank first runs the steps of the cases it
  // owns alone, writing nothing (a log to the progress output only); join() stores them all
  // in rank 0's cache; then every case runs below as always, its steps from the cache.
  const auto case_costs = [&] {
    return case_costs_seconds(project, sun_year_of(project, weather ? &*weather : nullptr, sun_site ? &*sun_site : nullptr));
  };
  if (!settings.units_line.empty()) log.line(settings.units_line);
  if (const std::unique_ptr<CaseUnits> units =
          settings.cases_as_units ? executor->case_units(1 + project.variants.size(), case_costs) : nullptr) {
    for (std::size_t c = 0; c <= project.variants.size(); ++c)
      if (units->mine(c)) run_case_steps(project, inputs, c, settings, store, units->executor(0), progress);
    log.line(units->join());
  }
  // The project as written is the base case, in <output>/<grid>/; each variant is studied
  // in addition, in <output>/variants/<variant>/<grid>/ (a folder no grid name can clash with).
  std::vector<CaseResult> cases{results_case("base", "", "", {})};
  ctx.results = &cases.back();
  nlohmann::json grids = run_case(project, "", report.output_dir, ctx, keep(project::BaseCaseName));
  nlohmann::json variants = nlohmann::json::array();
  for (const project::VariantSpec& v : project.variants) {
    const std::string dir = join_path(join_path(report.output_dir, "variants"), v.name);
    const std::vector<std::string> changes = project::variant_changes(v);
    std::string listed;
    for (const std::string& c : changes) listed += (listed.empty() ? "" : ", ") + c;
    log.line("variant " + v.name + ": " + listed);
    nlohmann::json vj = {{"name", v.name}, {"folder", dir}, {"changes", changes}};
    CaseResult variant = results_case("variant", v.name, relative_folder(report.output_dir, dir), changes);
    ctx.results = &variant;
    vj["grids"] = run_case(project::apply_variant(project, v), v.name, dir, ctx, keep(v.name));
    if (project.sunlight_exposure) vj["sunlight_exposure"] = sunlight_summary(variant.sunlight_exposure);
    cases.push_back(std::move(variant));
    variants.push_back(vj);
  }
  // The operated result, in <output>/operated/<grid>/, from the two cases' tables.
  nlohmann::json operated;
  if (op && !open_tables.grids.empty() && open_tables.grids.size() == shaded_tables.grids.size()) {
    CaseResult shading = operated_case(cases.front(), "operated (" + op->open.value + "/" + op->shaded.value + ")",
                                       "operated");
    // Its ASE and its 2 % rule are the open case's direct sun: LM-83 takes them without blinds.
    for (const CaseResult& c : cases)
      if ((c.kind == "base" && op->open.value == project::BaseCaseName) ||
          (c.kind == "variant" && c.name == op->open.value)) {
        shading.blinds_in_place = c.blinds_in_place;
        shading.shading_materials_in_place = c.shading_materials_in_place;
      }
    ctx.results = &shading;
    operated = run_operated(project, *op, open_tables, shaded_tables, join_path(report.output_dir, "operated"), ctx);
    cases.push_back(std::move(shading));
  } else if (op && writer) {  // the other ranks of an MPI run have no annual tables
    log.line("operated: skipped (no annual results)");
  }

  // 7. summary.json and the run log.
  nlohmann::json summary = {
      {"project", project.path},
      {"versions", {{"dayphoton", settings.version}, {"compiler", __VERSION__}}},
      {"output", report.output_dir},
      {"site", site_json(project.site, sun_site ? &*sun_site : nullptr, below_horizon ? &*below_horizon : nullptr,
                         sim.sun == project::SunMode::Bins)},
      {"study", project::study_kind_name(project.study)},
      {"weather", annual_study ? project.weather.path : std::string()},
      {"simulation", {{"basis", sim.basis == project::SkyBasis::Tregenza ? "tregenza" : "reinhart"},
                      {"reinhart_mf", sim.basis == project::SkyBasis::Tregenza ? 1 : sim.reinhart_mf},
                      {"photons_per_bin", sim.photons_per_bin},
                      {"ground_photon_factor", plan.ground_photon_factor},
                      {"bandwidth", sim.bandwidth},
                      {"direct_samples_per_bin", sim.direct_samples_per_bin},
                      {"caustic_photons_per_bin", sim.caustic_photons_per_bin},
                      {"caustic_bandwidth", sim.caustic_bandwidth},
                      {"max_attempts_per_photon", sim.max_attempts_per_photon},
                      {"seed", sim.seed},
                      {"ground_reflectance", sim.ground_reflectance},
                      {"sun", sim.sun == project::SunMode::Bins ? "bins" : "spread"},
                      {"annual_sky", sim.sun == project::SunMode::Bins
                                         ? "RADIANCE-compatible Perez sky matrix (gendaymtx conventions) without "
                                           "the sun; direct sun traced exactly every hour, indirect sun "
                                           "interpolated from sun bins"
                                         : "RADIANCE-compatible Perez sky matrix (gendaymtx conventions), sun "
                                           "spread into patches"}}},
      {"grids", grids},
      {"variants", variants},
      {"notes", report.notes}};
  if (!operated.is_null()) summary["operated"] = operated;
  if (project.sunlight_exposure) {
    const project::SunlightExposureSpec& se = *project.sunlight_exposure;
    summary["sunlight_exposure"] = {{"date", {se.month, se.day}},
                                    {"min_altitude_deg", se.min_altitude_deg},
                                    {"time_step_min", se.time_step_min},
                                    {"clock", "local standard time"},
                                    {"rooms", sunlight_summary(cases.front().sunlight_exposure)}};
  }
  if (sim.accuracy)
    summary["simulation"]["accuracy"] = {
        {"preset", sim.accuracy->preset.empty() ? nlohmann::json() : nlohmann::json(sim.accuracy->preset)},
        {"defaulted", sim.accuracy->defaulted},
        {"target_df_relative_stderr_percent", sim.accuracy->target_df_relative_stderr_percent},
        {"max_photons", sim.accuracy->max_photons > 0 ? std::uint64_t(sim.accuracy->max_photons) : project.limits.photons},
        {"max_seconds", sim.accuracy->max_seconds},
        {"reference_photons_per_bin", sim.photons_per_bin}};
  if (!annual_study) {
    summary["simulation"].erase("sun");
    summary["simulation"].erase("annual_sky");
  } else if (sim.sun == project::SunMode::Bins) {
    summary["simulation"]["sun_mf"] = sim.sun_mf;
    summary["simulation"]["sun_photons_per_bin"] = plan.sun_tracing.photons_per_source;
    summary["simulation"]["sun_bandwidth"] = plan.sun_estimating.density.bandwidth;
    summary["simulation"]["sun_direct_samples"] = plan.sun_direct_samples;
  }
  // 7b. The run's history goes to the log only (a repeated run must write the same results).
  log.quiet_line("cache: traced " + std::to_string(report.sources_traced) + " of " + std::to_string(report.sources) +
                 " sources (" + std::to_string(report.sources_cached) + " cached); estimated " +
                 std::to_string(report.grids_estimated) + " grid(s), " + std::to_string(report.grids_cached) +
                 " cached; sun bins " + std::to_string(report.sun_bins) + ", lit " + std::to_string(report.sun_bins_lit) +
                 ", traced " + std::to_string(report.sun_bins_traced));
  log.quiet_line("photon cap: " + std::to_string(report.sources_capped) + " source(s), " +
                 std::to_string(report.sun_bins_capped) + " sun bin(s) capped (of those traced or read in this run)");
  // What follows is files only: a process that writes nothing is done.
  if (!writer) {
    progress.end();
    return report;
  }
  // 8. results.json, the typed results model, then the images and report.html made from it
  // alone (report/, docs/report.md).
  ResultsModel model = results_model_header(project, settings.version, sun_site ? &*sun_site : nullptr,
                                            below_horizon ? &*below_horizon : nullptr, summary["simulation"], report.notes);
  model.cases = std::move(cases);
  assess_compliance(model);
  outputs.record(write_results_model(model, report.output_dir));
  // timings.json (run_timings.h): every step so far, before the report that shows them. Like
  // run.log it is the run's history, so summary.json does not list it.
  progress.end();
  write_run_timings(
      run_timings_of(progress.steps(),
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - run_start).count(),
                     std::max(0.0, Progress::process_cpu_seconds() - run_cpu_start),
                     static_cast<unsigned>(
                         tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism))),
      report.output_dir);
  if ((project.outputs.images || project.outputs.report) && settings.write_views) {
    progress.start("images and report", 1, "report");
    outputs.record(settings.write_views(report.output_dir, model, project.outputs.images, project.outputs.report));
    progress.advance(1);
    progress.end();
  }
  for (const Progress::StepTime& st : progress.steps()) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.2f s", st.seconds);
    log.quiet_line("time: " + st.name + ": " +
                   (st.cached ? std::string("cached") : std::string(seconds) + " (" + std::to_string(st.work) + " " + st.unit + ")"));
  }
  // 9. summary.json last, with the size and hash of every output: the folder is complete.
  nlohmann::json files = nlohmann::json::array();
  for (const ManifestEntry& e : outputs.entries())
    files.push_back({{"path", e.path}, {"bytes", e.bytes}, {"sha256", e.sha256}});
  summary["files"] = files;
  write_used_list(store);  // what `dayphoton clean` keeps (cache_folder.h)
  write_file_atomically(join_path(report.output_dir, OutputManifest::SummaryName), json_text(summary) + "\n");
  outputs.finish();
  log.quiet_line("complete: " + std::string(OutputManifest::SummaryName) + " lists " + std::to_string(files.size()) +
                 " output files");
  return report;
}

}  // namespace dayphoton::study
