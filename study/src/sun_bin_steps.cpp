// The sun side of a case as plan steps: see sun_bin_steps.h.
#include "sun_bin_steps.h"

#include <algorithm>
#include <memory>

#include "dayphoton/engine/port_emission.h"
#include "dayphoton/study/accuracy_policy.h"
#include "dayphoton/study/direct_sun_file.h"
#include "dayphoton/study/artifact_codec.h"
#include "dayphoton/study/cache_keys.h"
#include "dayphoton/study/photon_range_step.h"
#include "dayphoton/study/sensor_blocks.h"
#include "dayphoton/study/sun_accuracy_rounds.h"
#include "lazy_value.h"
#include "photon_pass_notes.h"
#include "sun_accuracy_step.h"

namespace dayphoton::study {
namespace {

/// The exact direct sun of a grid for `suns`, one step.
Step direct_sun_step(const CaseScene& cs, const SensorGrid& grid, std::size_t g, const std::vector<sky::SunRecord>& suns,
                     const SimulationPlan& plan, RadianceMatrix& slot) {
  std::vector<std::size_t> steps;
  std::vector<Vec3> directions;
  for (const sky::SunRecord& sun : suns) {
    steps.push_back(sun.step);
    directions.push_back(sun.direction);
  }
  Step step = make_step(
      StepKind::DirectSun, g,
      {"sun-direct", direct_sun_key(cs.scene_hash, grid, steps, directions, plan.sun_direct_samples, plan.seed,
                                    DirectSunValues::Luminance)},
      slot,
      [&cs, &grid, &suns, &plan] {
        return direct_sun_coefficients(cs.scene, cs.materials, grid.points, suns, plan.sun_direct_samples, plan.seed,
                                       DirectSunValues::Luminance);
      },
      encode_matrix, decode_matrix,
      [&grid, &suns](const RadianceMatrix& m) {
        return m.rows() == grid.points.size() && m.columns() == suns.size() && m.components() == 1;
      });
  step.blocks = matrix_sensor_blocks(grid.points.size(), [&cs, &grid, &suns, &plan](engine::SensorRange rows) {
    return direct_sun_coefficients(cs.scene, cs.materials, grid.points, suns, plan.sun_direct_samples, plan.seed,
                                   DirectSunValues::Luminance, rows);
  });
  return step;
}

/// The count-controlled sun: one photon step per lit bin (one batch, traced only when some
/// grid's sun coefficients are missing), then one coefficient step per grid. A grid estimated
/// by final gather is estimated with `estimating` (the sun's, with the year's gather weights:
/// run_sun_bins); the others, which the weights do not change, with the plan's sun options, so
/// that their keys do not hold the weather file's irradiances (docs/sun.md, "Sun bins").
void count_sun_coefficients(const std::string& prefix, const CaseScene& cs, const engine::SunBins& bins,
                            const engine::SourceSet& sources, const std::vector<char>& to_trace,
                            const std::vector<std::string>& keys, const engine::TracingOptions& tracing,
                            const engine::CoefficientOptions& estimating, RunContext& ctx,
                            std::vector<GridSun>& result) {
  const SimulationPlan& plan = ctx.plan;
  Progress& progress = ctx.progress;
  RunLog& log = ctx.log;
  RunReport& report = ctx.report;
  const std::vector<SensorGrid>& grids = cs.description.grids;
  const std::size_t n_grids = grids.size();
  const std::size_t n_lit = static_cast<std::size_t>(std::count(to_trace.begin(), to_trace.end(), 1));
  // The sun-coefficient steps first: the bins' photons are needed only if one is missing.
  engine::TracedPhotons photons;
  std::vector<Step> grid_steps(n_grids);
  std::vector<char> have(n_grids, 0);
  bool all_cached = true;
  for (std::size_t g = 0; g < n_grids; ++g) {
    const SensorGrid& grid = grids[g];
    const bool gathered = !grid_chased_by_photons(cs.layout.plane_of_grid,
                                                  plan.point_estimate == project::PointEstimate::Gather, g);
    // A plane's sensors next to a cut are gathered with the gathered grids' weights of the
    // rays' variance (the year's: sun_annual_estimating).
    auto near_cut_options = std::make_shared<engine::CoefficientOptions>(plan.sun_estimating);
    near_cut_options->gather = estimating.gather;
    const engine::CoefficientOptions* options =
        gathered ? &estimating : cs.layout.grid_gathers_near_cuts(g) ? near_cut_options.get() : &plan.sun_estimating;
    const std::string key = sun_coefficients_key(keys, plan.sun_bin_minimum_bound_fraction, grid, *options,
                                                 near_cut_count(cs.layout.plane_of_grid, &cs.layout.near_cut_sensors, g));
    GridSun& out = result[g];
    Step& s = grid_steps[g];
    s.kind = StepKind::SunCoefficients;
    s.index = g;
    s.outputs = {{"sun-coefficients", key}, {"sun-coefficients-variance", key}};
    s.compute = [&, g, options, near_cut_options]() -> std::vector<std::string> {
      {
        const engine::GridPhotons grid_photons =
            grid_photons_for(g, cs.layout, photons, bins.size(), plan.point_estimate);
        // The variances as the cache keeps them (single precision), so a cached run gives the
        // same verdicts.
        out.bin_coefficients = sun_bin_coefficients(cs.scene, cs.materials, sources, grid_photons, grid.points,
                                                    *options, &out.bin_variance);
      }  // the grid's photon maps released before the artefacts are encoded
      std::vector<std::string> bytes{encode_matrix(out.bin_coefficients)};
      RadianceMatrix variance(grid.points.size(), bins.size(), 1);
      std::copy(out.bin_variance.begin(), out.bin_variance.end(), variance.data().begin());
      bytes.push_back(encode_matrix(variance));
      return bytes;
    };
    // By sensor blocks over the ranks of an MPI run (plan_step.h): the same two matrices.
    SensorBlocks blocks;
    blocks.sensors = grid.points.size();
    blocks.compute_rows = [&, g, options, near_cut_options, maps = std::make_shared<LazyValue<engine::GridPhotons>>()](
                              std::size_t begin, std::size_t end) {
      const engine::GridPhotons& grid_photons =
          maps->get([&] { return grid_photons_for(g, cs.layout, photons, bins.size(), plan.point_estimate); });
      std::vector<double> block_variance;
      const RadianceMatrix c = sun_bin_coefficients(cs.scene, cs.materials, sources, grid_photons, grid.points,
                                                    *options, &block_variance, {begin, end});
      RadianceMatrix variance(end - begin, bins.size(), 1);
      for (std::size_t i = 0; i < block_variance.size(); ++i)
        variance.data()[i] = static_cast<float>(block_variance[i]);
      return std::vector<std::string>{encode_matrix(c), encode_matrix(variance)};
    };
    blocks.join = [](const std::vector<std::vector<std::string>>& b) {
      return std::vector<std::string>{join_matrix_blocks(output_of_blocks(b, 0)),
                                      join_matrix_blocks(output_of_blocks(b, 1))};
    };
    s.blocks = std::move(blocks);
    s.take = [&](const std::vector<std::string>& bytes) {
      out.bin_coefficients = decode_matrix(bytes.at(0));
      const RadianceMatrix v = decode_matrix(bytes.at(1));
      out.bin_variance.assign(v.data().begin(), v.data().end());
      return out.bin_coefficients.rows() == grid.points.size() && out.bin_coefficients.columns() == bins.size() &&
             out.bin_variance.size() == grid.points.size() * bins.size();
    };
    have[g] = ctx.executor.lookup(s) ? 1 : 0;
    all_cached = all_cached && have[g];
  }

  // The lit bins' photons, one step per bin, one batch; the others give no photons.
  if (all_cached) {
    progress.cached(prefix + "sun photons");
    log.line(prefix + "sun photons: traced 0 of " + std::to_string(n_lit) +
             " sun bins (not needed: every grid's sun coefficients are cached)");
  } else {
    progress.start(prefix + "sun photons", n_lit, "sun bins");
    std::vector<engine::TracedPhotons> per_bin(bins.size());
    // One batch of photon steps: the bins `which`, traced with `options` under `bin_keys`.
    auto trace_batch = [&](const engine::TracingOptions& options, const std::vector<std::size_t>& which,
                           const std::vector<std::string>& bin_keys) {
      std::vector<Step> steps;
      for (std::size_t i : which) {
        steps.push_back(make_step(
            StepKind::SunBinPhotons, i, {"sun-photons", bin_keys[i]}, per_bin[i],
            [&cs, &bins, &options, i] { return trace_sun_bin(cs.scene, cs.materials, bins, i, cs.layout.planes, options); },
            encode_photons, decode_photons, [](const engine::TracedPhotons&) { return true; }));
        steps.back().ranges = sun_bin_ranges(cs.scene, cs.materials, bins, i, cs.layout.planes, options);
      }
      const std::vector<char> traced = ctx.executor.run_batch(steps, [&](std::size_t k, bool) {
        const std::size_t bin = steps[k].index;
        relabel_photons(per_bin[bin], static_cast<std::uint32_t>(bin));
        progress.advance(1);
      });
      return static_cast<std::size_t>(std::count(traced.begin(), traced.end(), 1));
    };
    std::vector<std::size_t> lit;
    for (std::size_t i = 0; i < bins.size(); ++i) {
      if (to_trace[i]) {
        lit.push_back(i);
        continue;
      }
      per_bin[i].planes.resize(cs.layout.planes.size());
      per_bin[i].tallies.resize(1);
    }
    const std::size_t n_traced = trace_batch(tracing, lit, keys);
    progress.end();
    report.sun_bins_traced += n_traced;
    log.line(prefix + "sun photons: traced " + std::to_string(n_traced) + " of " + std::to_string(n_lit) +
             " sun bins (" + std::to_string(n_lit - n_traced) + " cached)");
    // Where the scaled cap starved the bins that carry the light, they are traced again with
    // the cap in raw attempts (photon_pass_notes.h, lifted_cap_sources).
    const std::size_t bandwidth = plan.sun_estimating.density.bandwidth;
    const LiftedCap lifted = lifted_cap_sources(per_bin, bandwidth, !cs.scene.outdoor_scatterers().empty());
    if (!lifted.sources.empty()) {
      log.line(prefix + "sun photons: " + lifted_cap_note(lifted, tracing, bandwidth, "sun bins"));
      engine::TracingOptions raw = tracing;
      raw.raw_attempt_cap.assign(1, 1);  // each bin is source 0 of its own emitter (trace_sun_bin)
      std::vector<std::string> raw_keys(bins.size());
      for (std::size_t i : lifted.sources)
        raw_keys[i] = sun_photon_key(cs.scene_hash, cs.planes_hash, bins.multiplication_factor(), bins.patch(i),
                                     sky::SunHalfAngle_rad, raw);
      progress.start(prefix + "sun photons, raw cap", lifted.sources.size(), "sun bins");
      trace_batch(raw, lifted.sources, raw_keys);
      progress.end();
    }
    photons = engine::merge_traced_photons(std::move(per_bin));
    for (const std::string& note : {capped_note(photons, tracing, "sun bins"), nothing_stored_note(photons, "sun bins")})
      if (!note.empty()) log.line(prefix + "sun photons: " + note);
    if (const std::string w = capped_warning(photons, tracing, bandwidth, "sun bins"); !w.empty())
      log.line(prefix + "warning: " + plan.cap_location.to_string() + ": " + w);
    for (const engine::SourceTally& t : photons.tallies) report.sun_bins_capped += t.capped ? 1 : 0;
  }

  for (std::size_t g = 0; g < n_grids; ++g) {
    const SensorGrid& grid = grids[g];
    if (have[g]) {
      progress.cached(prefix + "sun coefficients " + grid.name);
      log.line(prefix + "sun coefficients " + grid.name + ": cached");
    } else {
      progress.start(prefix + "sun coefficients " + grid.name, grid.points.size(), "sensors");
      ctx.executor.run(grid_steps[g]);
      grid_steps[g] = Step{};  // frees the photon maps its blocks may have built
      progress.advance(grid.points.size());
      progress.end();
      log.line(prefix + "sun coefficients " + grid.name + ": estimated at " + std::to_string(grid.points.size()) +
               " sensors");
    }
  }
  // Nothing after the coefficients reads the bins' photons: released before the direct sun.
  photons = engine::TracedPhotons{};
}

}  // namespace

std::vector<GridSun> run_sun_bins(const project::Project& project, const std::string& prefix, const CaseScene& cs,
                                  const SkyAndSuns& ss, const engine::SunBins& bins, RunContext& ctx,
                                  SunBinsDirect direct_sun, std::optional<SunAccuracyOutcome>* accuracy_outcome,
                                  const std::vector<SunRoundCase>* cases) {
  const project::Simulation& sim = project.simulation;
  const SimulationPlan& plan = ctx.plan;
  Progress& progress = ctx.progress;
  RunLog& log = ctx.log;
  RunReport& report = ctx.report;
  const std::vector<SensorGrid>& grids = cs.description.grids;
  const std::size_t n_grids = grids.size();
  const engine::TracingOptions tracing = plan.tracing_for(plan.sun_tracing, cs.layout);
  // A gathered grid's rays' variance split over the bins by the year's weights A_k, as the
  // accuracy rounds split it (sun_annual_estimating): the annual value's variance is then that
  // of its own rays, and the hours' variances (verdict_uncertainty.h) come nearer the spread
  // of seeds than with unit weights (SunAccuracy.GatherWeightsOfARunWithPhotonCountsAgainst-
  // TheSpreadOfSeeds); a run with photon counts and one with a target state them alike.
  const engine::CoefficientOptions estimating =
      sun_annual_estimating(plan.sun_estimating, sun_year_weights(bins, ss.suns));

  const engine::SourceSet sources = bins.sources(sky::SunHalfAngle_rad);
  const std::vector<char> to_trace = sun_bins_to_trace(engine::PortEmitter(cs.scene, sources), bins.size());
  const std::size_t n_lit = static_cast<std::size_t>(std::count(to_trace.begin(), to_trace.end(), 1));
  std::vector<std::string> keys(bins.size());
  for (std::size_t i = 0; i < bins.size(); ++i)
    keys[i] = sun_photon_key(cs.scene_hash, cs.planes_hash, bins.multiplication_factor(), bins.patch(i),
                             sky::SunHalfAngle_rad, tracing);
  log.line(prefix + "sun bins: " + std::to_string(bins.size()) + " on Reinhart MF " +
           std::to_string(bins.multiplication_factor()) + " for " + std::to_string(ss.suns.size()) +
           " sun hours; " + std::to_string(n_lit) + " send light through the ports, " +
           std::to_string(tracing.photons_per_source) +
           (sim.accuracy ? " photons each at the reference of the accuracy rounds, bandwidth " : " photons each, bandwidth ") +
           std::to_string(estimating.density.bandwidth));

  std::vector<GridSun> result(n_grids);
  report.sun_bins += bins.size();
  report.sun_bins_lit += n_lit;
  std::optional<SunAccuracyOutcome> accuracy;
  if (sim.accuracy) {
    // The accuracy target's sun rounds (sun_accuracy_step.h) instead of the count's steps.
    accuracy = accuracy_sun_coefficients(project, prefix, cs, ss.suns, bins, estimating, ctx, result, cases);
  } else {
    count_sun_coefficients(prefix, cs, bins, sources, to_trace, keys, tracing, estimating, ctx, result);
  }
  if (accuracy_outcome) *accuracy_outcome = accuracy;
  if (direct_sun == SunBinsDirect::ByTheCaller) return result;

  for (std::size_t g = 0; g < n_grids; ++g) {
    const SensorGrid& grid = grids[g];

    // The exact direct sun of every hour.
    const Step direct = direct_sun_step(cs, grid, g, ss.suns, plan, result[g].direct);
    if (ctx.executor.lookup(direct)) {
      progress.cached(prefix + "direct sun " + grid.name);
      log.line(prefix + "direct sun " + grid.name + ": cached");
    } else {
      progress.start(prefix + "direct sun " + grid.name, grid.points.size(), "sensors");
      ctx.executor.run(direct);
      progress.advance(grid.points.size());
      progress.end();
      log.line(prefix + "direct sun " + grid.name + ": traced for " + std::to_string(ss.suns.size()) +
               " sun hours at " + std::to_string(grid.points.size()) + " sensors");
    }
    // The export for `annual` (direct_sun.bin.gz): the daytime positions without direct light
    // in this weather file too, so another file of the site finds every sun it needs.
    if (direct_sun == SunBinsDirect::TracedAndExported) {
      GridSun& out = result[g];
      out.other_suns = daytime_suns_without_direct(*ctx.weather, ctx.sun_site->solar,
                                                   sun_excluded_sky_options(sim.ground_reflectance), ss.suns);
      const Step other = direct_sun_step(cs, grid, g, out.other_suns, plan, out.direct_other);
      const bool other_cached = ctx.executor.lookup(other);
      if (!other_cached) {
        progress.start(prefix + "direct sun " + grid.name + " (export)", grid.points.size(), "sensors");
        ctx.executor.run(other);
        progress.advance(grid.points.size());
        progress.end();
      }
      log.line(prefix + "direct sun " + grid.name + " for the export: " + std::to_string(out.other_suns.size()) +
               " further daytime sun positions" + (other_cached ? " (cached)" : " traced"));
    }
  }
  return result;
}

}  // namespace dayphoton::study
