// The sky side of a case as plan steps: see sky_coefficient_steps.h.
#include "sky_coefficient_steps.h"

#include <algorithm>
#include <memory>

#include "dayphoton/engine/port_emission.h"
#include "dayphoton/study/accuracy_policy.h"
#include "dayphoton/study/artifact_codec.h"
#include "dayphoton/study/cache_keys.h"
#include "dayphoton/study/photon_range_step.h"
#include "dayphoton/study/point_in_time.h"
#include "dayphoton/study/sensor_blocks.h"
#include "lazy_value.h"
#include "photon_pass_notes.h"
#include "photon_step_cost.h"
#include "sky_steps.h"

namespace dayphoton::study {

std::vector<std::string> sky_photon_keys(const CaseScene& cs, const sky::PatchBasis& basis, std::size_t sources,
                                         const engine::TracingOptions& tracing) {
  std::vector<std::string> keys(sources);
  for (std::size_t p = 0; p < sources; ++p)
    keys[p] = photon_source_key(cs.scene_hash, cs.planes_hash, basis, p, tracing);
  return keys;
}

void sky_coefficients(const CaseScene& cs, const engine::SourceSet& sources, const engine::TracingOptions& tracing,
                      const std::vector<std::string>& photon_keys, const std::string& prefix, RunContext& ctx,
                      std::vector<std::optional<engine::DaylightCoefficients>>& coefficients) {
  const SimulationPlan& plan = ctx.plan;
  Progress& progress = ctx.progress;
  RunReport& report = ctx.report;
  const std::vector<SensorGrid>& grids = cs.description.grids;

  // The coefficient steps first: the photons are needed only if one of them is missing.
  engine::TracedPhotons photons;
  std::vector<Step> grid_steps;
  bool all_grids_cached = true;
  for (std::size_t g = 0; g < grids.size(); ++g) {
    const SensorGrid& grid = grids[g];
    grid_steps.push_back(make_step(
        StepKind::SkyCoefficients, g, {"coefficients", coefficients_key(photon_keys, grid, plan.sky_estimating,
                                                                 near_cut_count(cs.layout.plane_of_grid, &cs.layout.near_cut_sensors, g))},
        coefficients[g],
        [&cs, &sources, &photons, &plan, &grid, g] {
          const engine::GridPhotons grid_photons =
              grid_photons_for(g, cs.layout, photons, sources.size(), plan.point_estimate);
          return std::optional<engine::DaylightCoefficients>(engine::daylight_coefficients(
              cs.scene, cs.materials, sources, grid_photons, grid.points, plan.sky_estimating));
        },
        [](const std::optional<engine::DaylightCoefficients>& c) { return encode_coefficients(*c); },
        [](const std::string& bytes) { return std::optional<engine::DaylightCoefficients>(decode_coefficients(bytes)); },
        [](const std::optional<engine::DaylightCoefficients>&) { return true; }));
    // By sensor blocks over the ranks of an MPI run (plan_step.h); the grid's photon maps
    // built once on each rank that estimates a block.
    SensorBlocks blocks;
    blocks.sensors = grid.points.size();
    blocks.compute_rows = [&cs, &sources, &photons, &plan, &grid, g,
                           maps = std::make_shared<LazyValue<engine::GridPhotons>>()](std::size_t begin, std::size_t end) {
      const engine::GridPhotons& grid_photons = maps->get(
          [&] { return grid_photons_for(g, cs.layout, photons, sources.size(), plan.point_estimate); });
      return std::vector<std::string>{encode_coefficients(engine::daylight_coefficients(
          cs.scene, cs.materials, sources, grid_photons, grid.points, plan.sky_estimating, {begin, end}))};
    };
    blocks.join = [](const std::vector<std::vector<std::string>>& b) {
      return std::vector<std::string>{join_coefficient_blocks(output_of_blocks(b, 0))};
    };
    grid_steps.back().blocks = std::move(blocks);
    if (!ctx.executor.lookup(grid_steps.back())) coefficients[g].reset();
    all_grids_cached = all_grids_cached && coefficients[g].has_value();
  }

  // Photons (only if some grid needs estimating), one step per source, one batch.
  report.sources += sources.size();
  if (all_grids_cached) {
    progress.cached(prefix + "photons");
    report.sources_cached += sources.size();
    ctx.log.line(prefix + "photons: traced 0 of " + std::to_string(sources.size()) +
                 " sources (not needed: every grid's coefficients are cached)");
  } else {
    progress.start(prefix + "photons", sources.size(), "sources");
    const engine::PortEmitter emitter(cs.scene, sources);
    std::vector<engine::TracedPhotons> per_source(sources.size());
    // One batch of photon steps: the sources `which`, traced with `options` under `keys`.
    auto trace_batch = [&](const engine::TracingOptions& options, const std::vector<std::size_t>& which,
                           const std::vector<std::string>& keys) {
      std::vector<Step> steps;
      for (std::size_t p : which) {
        steps.push_back(make_step(
            StepKind::SourcePhotons, p, {"photons", keys[p]}, per_source[p],
            [&cs, &emitter, &options, p] {
              return engine::trace_source_photons(cs.scene, cs.materials, emitter, cs.layout.planes, options, p);
            },
            encode_photons, decode_photons, [](const engine::TracedPhotons&) { return true; }));
        steps.back().ranges = sky_source_ranges(cs.scene, cs.materials, emitter, cs.layout.planes, options, p);
        // Costs for an MPI run: a short pilot of each source (photon_step_cost.h).
        steps.back().cost = [&cs, &emitter, &options, p] {
          return photon_step_cost(cs.scene, cs.materials, emitter, cs.layout.planes, options, p);
        };
      }
      const std::vector<char> traced =
          ctx.executor.run_batch(steps, [&](std::size_t, bool) { progress.advance(1); });
      return static_cast<std::size_t>(std::count(traced.begin(), traced.end(), 1));
    };
    std::vector<std::size_t> all(sources.size());
    for (std::size_t p = 0; p < sources.size(); ++p) all[p] = p;
    const std::size_t n_traced = trace_batch(tracing, all, photon_keys);
    progress.end();
    report.sources_traced += n_traced;
    report.sources_cached += sources.size() - n_traced;
    ctx.log.line(prefix + "photons: traced " + std::to_string(n_traced) + " of " + std::to_string(sources.size()) +
                 " sources (" + std::to_string(sources.size() - n_traced) + " cached)");
    // Where the scaled cap starved the sources that carry the light, they are traced again
    // with the cap in raw attempts (photon_pass_notes.h, lifted_cap_sources).
    const std::size_t bandwidth = plan.sky_estimating.density.bandwidth;
    const LiftedCap lifted = lifted_cap_sources(per_source, bandwidth, !cs.scene.outdoor_scatterers().empty());
    if (!lifted.sources.empty()) {
      ctx.log.line(prefix + "photons: " + lifted_cap_note(lifted, tracing, bandwidth, "sources"));
      engine::TracingOptions raw = tracing;
      raw.raw_attempt_cap.assign(sources.size(), 1);
      const std::vector<std::string> raw_keys = sky_photon_keys(cs, plan.basis, sources.size(), raw);
      progress.start(prefix + "photons, raw cap", lifted.sources.size(), "sources");
      trace_batch(raw, lifted.sources, raw_keys);
      progress.end();
    }
    photons = engine::merge_traced_photons(std::move(per_source));
    for (const std::string& note : {capped_note(photons, tracing, "sources"), nothing_stored_note(photons, "sources")})
      if (!note.empty()) ctx.log.line(prefix + "photons: " + note);
    if (const std::string w = capped_warning(photons, tracing, bandwidth, "sources"); !w.empty())
      ctx.log.line(prefix + "warning: " + plan.cap_location.to_string() + ": " + w);
    for (const engine::SourceTally& t : photons.tallies) report.sources_capped += t.capped ? 1 : 0;
  }

  // Coefficients per grid: the missing ones estimated and stored.
  for (std::size_t g = 0; g < grids.size(); ++g) {
    const SensorGrid& grid = grids[g];
    if (coefficients[g]) {
      ++report.grids_cached;
      progress.cached(prefix + "coefficients " + grid.name);
      ctx.log.line(prefix + "coefficients " + grid.name + ": cached");
      continue;
    }
    progress.start(prefix + "coefficients " + grid.name, grid.points.size(), "sensors");
    ctx.executor.run(grid_steps[g]);
    grid_steps[g] = Step{};  // frees the photon maps its blocks may have built
    progress.advance(grid.points.size());
    progress.end();
    ++report.grids_estimated;
    ctx.log.line(prefix + "coefficients " + grid.name + ": estimated at " + std::to_string(grid.points.size()) +
                 " sensors");
  }
}

namespace {

/// The point-in-time cases whose sky part the rounds hold to the target (AccuracyCase::
/// case_skies): every case but the cie_overcast ones, whose sky has the daylight factor's shape
/// and so its relative error.
std::vector<CaseSky> point_in_time_case_skies(const project::Project& project, RunContext& ctx) {
  const std::vector<project::PointInTimeSpec>& cases = project.points_in_time;
  const bool measured = std::any_of(cases.begin(), cases.end(), [](const project::PointInTimeSpec& c) {
    return c.sky != project::PointSky::CieOvercast;
  });
  if (!measured) return {};
  const bool weather_cases = std::any_of(cases.begin(), cases.end(), [](const project::PointInTimeSpec& c) {
    return c.sky == project::PointSky::Weather;
  });
  const SkyAndSuns* annual = weather_cases ? &sky_and_suns(project, ctx) : nullptr;
  const SkyAndSuns skies = point_in_time_skies(cases, point_in_time_site(project, ctx.sun_site), ctx.plan.basis,
                                               project.simulation.ground_reflectance, annual);
  std::vector<CaseSky> out;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    if (cases[k].sky == project::PointSky::CieOvercast) continue;
    CaseSky sky;
    sky.name = cases[k].name;
    sky.vector = point_in_time_sky_column(skies, k);
    const int index = k < ctx.plan.point_in_time_sky.size() ? ctx.plan.point_in_time_sky[k] : -1;
    if (index >= 0) sky.direct_sky = static_cast<std::size_t>(index);
    out.push_back(std::move(sky));
  }
  return out;
}

}  // namespace

AccuracyOutcome accuracy_sky_coefficients(const project::Project& project, const CaseScene& cs,
                                          const engine::SourceSet& sources, const engine::TracingOptions& tracing,
                                          const std::vector<std::string>& photon_keys, const std::string& prefix,
                                          RunContext& ctx,
                                          std::vector<std::optional<engine::DaylightCoefficients>>& coefficients) {
  const project::Simulation& sim = project.simulation;
  const std::vector<SensorGrid>& grids = cs.description.grids;
  const RadianceMatrix overcast_vector = ctx.plan.daylight_factor_sky();
  AccuracyCase c;
  c.scene = &cs.scene;
  c.materials = &cs.materials;
  c.sources = &sources;
  c.planes = &cs.layout.planes;
  c.plane_of_grid = &cs.layout.plane_of_grid;
  c.near_cut_sensors = &cs.layout.near_cut_sensors;
  c.grids = &grids;
  c.gather = ctx.plan.point_estimate == project::PointEstimate::Gather;
  c.tracing = tracing;
  c.estimating = ctx.plan.sky_estimating;
  c.overcast_vector = &overcast_vector;
  c.horizontal_illuminance_lux = ctx.plan.overcast_horizontal_lux;
  c.case_skies = point_in_time_case_skies(project, ctx);
  AccuracyGoal goal;
  goal.target_percent = sim.accuracy->target_df_relative_stderr_percent;
  goal.max_photons = sim.accuracy->max_photons > 0 ? std::uint64_t(sim.accuracy->max_photons) : project.limits.photons;
  goal.max_seconds = sim.accuracy->max_seconds;
  ctx.report.sources += sources.size();
  ctx.progress.start(prefix + "photons (accuracy rounds)", 1, "runs");
  CaseAccuracy r = accuracy_coefficients(c, goal, ctx.executor, photon_keys,
                                         [&](const std::string& line) { ctx.log.line(prefix + line); });
  ctx.progress.advance(1);
  ctx.progress.end();
  if (r.cached) {
    ctx.report.sources_cached += sources.size();
    ctx.report.grids_cached += grids.size();
  } else {
    ctx.report.sources_traced += sources.size();
    ctx.report.grids_estimated += grids.size();
  }
  for (std::size_t g = 0; g < grids.size(); ++g) {
    coefficients[g] = std::move(r.coefficients[g]);
    ctx.log.line(prefix + "accuracy " + grids[g].name + ": " + accuracy_sentence(r.outcome, g));
  }
  return r.outcome;
}

}  // namespace dayphoton::study
