// The annual sky steps: see sky_steps.h.
#include "sky_steps.h"

#include <functional>
#include <string>

#include "dayphoton/study/artifact_codec.h"
#include "dayphoton/study/cache_keys.h"

namespace dayphoton::study {
namespace {

/// The sky matrix step from the cache, or built with its progress bar; `built_line` (called
/// once the step ran) is the run log's line for a built sky.
void run_sky_step(const Step& step, std::size_t hours, RunContext& ctx,
                  const std::function<std::string()>& built_line) {
  if (ctx.executor.lookup(step)) {
    ctx.report.sky_matrix_cached = true;
    ctx.progress.cached("sky matrix");
    ctx.log.line("sky matrix: cached");
    return;
  }
  ctx.progress.start("sky matrix", hours, "hours");
  ctx.executor.run(step);
  ctx.progress.advance(hours);
  ctx.progress.end();
  ctx.log.line(built_line());
}

}  // namespace

const AnnualSky& annual_sky(const project::Project& project, RunContext& ctx) {
  if (ctx.sky) return *ctx.sky;
  const weather::HourlyWeather& weather = *ctx.weather;
  const sky::SolarSite& site = ctx.sun_site->solar;
  const sky::PatchBasis& basis = ctx.plan.basis;
  const double rho_g = project.simulation.ground_reflectance;
  AnnualSky sky;
  Step step = make_step(
      StepKind::SkyMatrix, 0, {"sky", sky_matrix_key(project.weather.path, site, basis, rho_g, false)}, sky,
      [&] { return annual_sky_from_weather(weather, site, basis, radiance_compatible_sky_options(rho_g)); },
      [](const AnnualSky& s) { return encode_matrix(s.matrix); },
      // The matrix from bytes (the cache's, or another rank's), the rest from the weather.
      [&](const std::string& bytes) {
        AnnualSky s;
        s.matrix = decode_matrix(bytes);
        s.steps = time_stamps(weather);
        s.daylight_hours_quantity = daylight_hours_quantity(weather, s.daylight_hours_source);
        s.description = annual_sky_description(weather, basis, radiance_compatible_sky_options(rho_g));
        return s;
      },
      [](const AnnualSky&) { return true; });
  run_sky_step(step, weather.records.size(), ctx,
               [&] { return "sky matrix: built from " + project.weather.path; });
  // The quadrant deltas are not cached: from the weather where the matrix came from bytes.
  if (sky.quadrant_deltas.rows() == 0)
    sky.quadrant_deltas = annual_quadrant_deltas(weather, site, basis, radiance_compatible_sky_options(rho_g));
  ctx.sky = std::move(sky);
  return *ctx.sky;
}

const SkyAndSuns& sky_and_suns(const project::Project& project, RunContext& ctx) {
  if (ctx.sky_and_suns) return *ctx.sky_and_suns;
  const weather::HourlyWeather& weather = *ctx.weather;
  const sky::SolarSite& site = ctx.sun_site->solar;
  const sky::PatchBasis& basis = ctx.plan.basis;
  const double rho_g = project.simulation.ground_reflectance;
  const std::string key = sky_matrix_key(project.weather.path, site, basis, rho_g, true);
  SkyAndSuns result;
  Step step;
  step.kind = StepKind::SkyMatrix;
  step.outputs = {{"sky", key}, {"suns", key}};
  step.compute = [&]() -> std::vector<std::string> {
    result = annual_sky_and_suns(weather, site, basis, sun_excluded_sky_options(rho_g));
    const RadianceMatrix suns = suns_to_matrix(result.suns);
    // Use the suns as the cache stores them (single precision), so that a later run from the
    // cache gives byte-identical results.
    result.suns = suns_from_matrix(suns);
    return {encode_matrix(result.sky.matrix), encode_matrix(suns)};
  };
  // The matrices from bytes (the cache's, or another rank's), the rest from the weather.
  step.take = [&](const std::vector<std::string>& bytes) {
    result.sky.matrix = decode_matrix(bytes.at(0));
    result.suns = suns_from_matrix(decode_matrix(bytes.at(1)));
    result.sky.steps = time_stamps(weather);
    result.sky.daylight_hours_quantity = daylight_hours_quantity(weather, result.sky.daylight_hours_source);
    result.sky.description = sky_and_suns_description(weather, basis);
    return true;
  };
  run_sky_step(step, weather.records.size(), ctx, [&] {
    return "sky matrix: built from " + project.weather.path + " (sun excluded; " +
           std::to_string(result.suns.size()) + " sun hours)";
  });
  // The quadrant deltas are not cached: from the weather where the matrices came from bytes.
  if (result.sky.quadrant_deltas.rows() == 0) {
    sky::SkyMatrixOptions options = sun_excluded_sky_options(rho_g);
    options.sun = sky::SunInMatrix::None;
    result.sky.quadrant_deltas = annual_quadrant_deltas(weather, site, basis, options);
  }
  ctx.sky_and_suns = std::move(result);
  return *ctx.sky_and_suns;
}

}  // namespace dayphoton::study
