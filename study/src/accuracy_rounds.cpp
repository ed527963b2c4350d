// The accuracy target's rounds: see accuracy_rounds.h.
#include "dayphoton/study/accuracy_rounds.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/direct_component.h"
#include "dayphoton/engine/photon_rounds.h"
#include "dayphoton/engine/port_emission.h"
#include "dayphoton/study/accuracy_policy.h"
#include "dayphoton/study/artifact_codec.h"
#include "dayphoton/study/artifact_store.h"
#include "dayphoton/study/cache_keys.h"
#include "dayphoton/study/content_hash.h"
#include "dayphoton/study/daylight_factor.h"
#include "dayphoton/study/gather_accuracy_rounds.h"
#include "dayphoton/study/plan_policy.h"
#include "gather_accuracy_json.h"
#include "dayphoton/study/round_work.h"
#include "dayphoton/study/round_grid_maps.h"
#include "dayphoton/study/sensor_blocks.h"
#include "dayphoton/study/simulation_plan.h"
#include "dayphoton/study/step_executor.h"
#include "accuracy_round_loop.h"
#include <nlohmann/json.hpp>

namespace dayphoton::study {
namespace {

using Clock = std::chrono::steady_clock;

/// What the sky's rounds measure (the log lines and the outcome's sentence).
constexpr const char* DfMeasure = "DF relative standard error";

std::string number(double x, const char* format = "%.3g") { return round_number(x, format); }

/// Grid g's coefficients of one round, estimated by sensor blocks through `work` (round_work.h):
/// the direct part given (`direct`, the whole grid's), the photon part from
/// the round's maps (`maps`: built once in a process that estimates some block). Every block's
/// rows are the whole grid's (sensor_range.h), so the joined coefficients are those of the grid
/// estimated at once.
engine::DaylightCoefficients round_coefficients(const AccuracyCase& c, std::size_t g, RoundGridMaps& maps,
                                                const engine::DaylightCoefficients& direct, RoundWork& work,
                                                const std::string& name) {
  const std::size_t n = c.sources->size();
  const SensorGrid& grid = (*c.grids)[g];
  const std::vector<std::string> blocks = work.estimate(
      grid.points.size(),
      [&](std::size_t begin, std::size_t end) {
        const engine::GridPhotons& gp = maps.of_grid(g);
        engine::DaylightCoefficients dc;
        copy_direct_rows(direct, begin, end, n, dc);
        dc.caustic.assign(dc.sensors * n, Vec3{0, 0, 0});
        dc.global.assign(dc.sensors * n, Vec3{0, 0, 0});
        // With the photon part under the daylight factor's continuous sky, which the round's
        // measure reads (daylight_factor_parts) as the outputs do.
        engine::photon_coefficients(*c.scene, *c.materials, *c.sources, gp, grid.points, c.estimating, dc,
                                    {begin, end});
        return encode_coefficients(dc);
      },
      name);
  return decode_coefficients(join_coefficient_blocks(blocks));
}

/// Grid g's direct component at `samples_per_bin` shadow rays per bin (the same every round
/// until a round raises them: next_direct_round), its variance and its values on the
/// continuous skies, by sensor blocks through `work`.
engine::DaylightCoefficients grid_direct(const AccuracyCase& c, std::size_t g, int samples_per_bin, RoundWork& work) {
  engine::DirectOptions options = c.estimating.direct;
  options.samples_per_source = samples_per_bin;
  const std::size_t n = c.sources->size();
  const SensorGrid& grid = (*c.grids)[g];
  const std::vector<std::string> blocks = work.estimate(
      grid.points.size(),
      [&](std::size_t begin, std::size_t end) {
        engine::DaylightCoefficients dc;
        dc.sensors = end - begin;
        dc.sources = n;
        dc.direct = engine::direct_coefficients(*c.scene, *c.materials, *c.sources, grid.points, options,
                                                &dc.direct_variance, {begin, end}, &dc.direct_on_skies,
                                                &dc.direct_quadrants);
        dc.caustic.assign(dc.sensors * n, Vec3{0, 0, 0});
        dc.global.assign(dc.sensors * n, Vec3{0, 0, 0});
        dc.photon_variance.assign(dc.sensors * n, 0.0);
        return encode_coefficients(dc);
      },
      "accuracy rounds: direct component of grid " + grid.name + " at " + std::to_string(samples_per_bin) +
          " shadow rays per bin");
  engine::DaylightCoefficients joined = decode_coefficients(join_coefficient_blocks(blocks));
  joined.caustic.clear();
  joined.global.clear();
  joined.photon_variance.clear();
  return joined;
}

}  // namespace

void copy_direct_rows(const engine::DaylightCoefficients& whole, const std::vector<std::size_t>& which,
                      std::size_t sources, engine::DaylightCoefficients& out) {
  out.sensors = which.size();
  out.sources = sources;
  out.direct.clear();
  out.direct_variance.clear();
  out.direct_on_skies = {};
  out.direct_quadrants.clear();
  if (whole.direct.empty()) {
    out.direct.assign(out.sensors * sources, Vec3{});
    out.direct_variance.assign(out.sensors * sources, 0.0);
    return;
  }
  const engine::DirectOnSkies& skies = whole.direct_on_skies;
  const std::size_t k = skies.skies;
  out.direct_on_skies.skies = k;
  auto append_row = [](auto& to, const auto& from, std::size_t i, std::size_t per_row) {
    to.insert(to.end(), from.begin() + std::ptrdiff_t(i * per_row), from.begin() + std::ptrdiff_t((i + 1) * per_row));
  };
  for (const std::size_t i : which) {
    append_row(out.direct, whole.direct, i, sources);
    append_row(out.direct_variance, whole.direct_variance, i, sources);
    append_row(out.direct_on_skies.irradiance, skies.irradiance, i, k);
    append_row(out.direct_on_skies.variance, skies.variance, i, k);
    if (!whole.direct_quadrants.empty())
      append_row(out.direct_quadrants, whole.direct_quadrants, i, sources * engine::StoredQuadrants);
  }
}

void copy_direct_rows(const engine::DaylightCoefficients& whole, std::size_t begin, std::size_t end,
                      std::size_t sources, engine::DaylightCoefficients& out) {
  std::vector<std::size_t> which(end - begin);
  for (std::size_t r = 0; r < which.size(); ++r) which[r] = begin + r;
  copy_direct_rows(whole, which, sources, out);
}

std::vector<std::size_t> sensors_at_or_below_percentile(const std::vector<double>& relative, const std::vector<double>& df,
                                                        double percentile) {
  std::vector<std::size_t> lit;
  for (std::size_t i = 0; i < df.size(); ++i)
    if (df[i] > 0) lit.push_back(i);
  std::stable_sort(lit.begin(), lit.end(), [&](std::size_t a, std::size_t b) { return relative[a] < relative[b]; });
  const std::size_t keep = static_cast<std::size_t>(std::ceil(percentile / 100.0 * double(lit.size())));
  lit.resize(std::min(lit.size(), keep));
  return lit;
}

double percentile_relative_stderr_percent(const std::vector<double>& df_percent,
                                          const std::vector<double>& stderr_percent, double percentile) {
  std::vector<double> r;
  for (std::size_t i = 0; i < df_percent.size() && i < stderr_percent.size(); ++i)
    if (df_percent[i] > 0) r.push_back(100.0 * stderr_percent[i] / df_percent[i]);
  if (r.empty()) return 0.0;
  std::sort(r.begin(), r.end());
  const std::size_t rank = static_cast<std::size_t>(std::ceil(percentile / 100.0 * double(r.size())));
  return r[std::min(r.size(), std::max<std::size_t>(1, rank)) - 1];
}

RoundPlan next_round_scale(const std::vector<GridVariance>& grids, const std::vector<double>& cost,
                           double aim_percent, double percentile, double max_growth) {
  const std::size_t n = cost.size();
  RoundPlan plan;
  plan.scale.assign(n, 1.0);
  for (const GridVariance& g : grids) {
    const std::size_t sensors = g.df_percent.size();
    std::vector<double> relative(sensors, 0.0);
    for (std::size_t i = 0; i < sensors; ++i) {
      double v = g.direct_variance[i];
      for (std::size_t p = 0; p < n; ++p) v += g.photon_variance[i * n + p];
      relative[i] = g.df_percent[i] > 0 ? 100.0 * std::sqrt(std::max(0.0, v)) / g.df_percent[i] : 0.0;
    }
    for (std::size_t i : sensors_at_or_below_percentile(relative, g.df_percent, percentile)) {
      if (!g.left_out.empty() && g.left_out[i]) {  // whatever its plan's error: not these photons' to chase
        ++plan.sensors_left_out;
        continue;
      }
      if (!(relative[i] > aim_percent)) continue;
      ++plan.sensors_constrained;
      const double allowed = aim_percent / 100.0 * g.df_percent[i];
      const double budget = allowed * allowed - g.direct_variance[i];
      if (!(budget > 0)) {
        ++plan.sensors_direct_limited;
        continue;
      }
      raise_to_neyman_scale(&g.photon_variance[i * n], cost, budget, plan.scale);
    }
  }
  for (double& s : plan.scale) s = std::min(s, max_growth);
  return plan;
}

double direct_rays_per_sensor(int samples_per_bin, std::size_t sources, bool port_sampling) {
  const double k = std::ceil(std::sqrt(double(std::max(1, samples_per_bin))));
  const double port_k = double(engine::PortStrataFactor) * k;
  return k * k * double(sources) + (port_sampling ? 2.0 * port_k * port_k : 0.0);
}

namespace {

/// Rays a photon plan adds: each source's rays so far times its growth.
double photon_plan_rays(const RoundPlan& plan, const std::vector<double>& cost) {
  double rays = 0;
  for (std::size_t p = 0; p < cost.size() && p < plan.scale.size(); ++p) rays += cost[p] * (plan.scale[p] - 1.0);
  return rays;
}

}  // namespace

DirectRoundPlan next_direct_round(const std::vector<GridVariance>& grids, const std::vector<int>& samples_per_bin,
                                  const std::vector<std::size_t>& sensors, const std::vector<double>& cost,
                                  const RoundPlan& photons, double aim_percent, double percentile, std::size_t sources,
                                  bool port_sampling) {
  DirectRoundPlan plan;
  plan.samples_per_bin = samples_per_bin;
  plan.photons = photons;
  std::vector<GridVariance> predicted = grids;
  double plan_rays = photon_plan_rays(photons, cost);
  const int max_k = static_cast<int>(std::floor(std::sqrt(double(MaxDirectSamplesPerBin))));
  for (std::size_t g = 0; g < grids.size(); ++g) {
    const GridVariance& v = grids[g];
    const std::size_t n_sources = cost.size();
    std::vector<double> relative(v.df_percent.size(), 0.0);
    for (std::size_t i = 0; i < relative.size(); ++i) {
      double var = v.direct_variance[i];
      for (std::size_t p = 0; p < n_sources; ++p) var += v.photon_variance[i * n_sources + p];
      relative[i] = v.df_percent[i] > 0 ? 100.0 * std::sqrt(std::max(0.0, var)) / v.df_percent[i] : 0.0;
    }
    // The failing sensors whose direct variance is at least half their budget.
    std::vector<std::size_t> direct_heavy;
    std::size_t limited = 0;
    for (std::size_t i : sensors_at_or_below_percentile(relative, v.df_percent, percentile)) {
      if (!(relative[i] > aim_percent)) continue;
      const double allowed = aim_percent / 100.0 * v.df_percent[i];
      if (v.direct_variance[i] >= 0.5 * allowed * allowed) direct_heavy.push_back(i);
      if (v.direct_variance[i] >= allowed * allowed) ++limited;
    }
    if (direct_heavy.empty()) continue;
    const int k = static_cast<int>(std::ceil(std::sqrt(double(std::max(1, samples_per_bin[g])))));
    if (k >= max_k) {
      plan.sensors_at_limit += limited;
      if (limited > 0) plan.samples_at_limit = std::max(plan.samples_at_limit, k * k);
      continue;
    }
    // k' = 2k, else 4k, so that every such sensor's predicted direct variance is half its budget.
    int next_k = std::min(max_k, 2 * k);
    auto shrink = [&](int to_k) { return std::pow(double(k) / double(to_k), 2.0 * DirectVarianceExponent); };
    bool enough = true;
    for (std::size_t i : direct_heavy) {
      const double allowed = aim_percent / 100.0 * v.df_percent[i];
      enough = enough && v.direct_variance[i] * shrink(next_k) <= 0.5 * allowed * allowed;
    }
    if (!enough) next_k = std::min(max_k, 4 * k);
    std::vector<GridVariance> trial = predicted;
    for (double& d : trial[g].direct_variance) d *= shrink(next_k);
    const RoundPlan trial_photons = next_round_scale(trial, cost, aim_percent, percentile);
    const double direct_rays = double(g < sensors.size() ? sensors[g] : v.df_percent.size()) * direct_rays_per_sensor(next_k * next_k, sources, port_sampling);
    const double trial_rays = photon_plan_rays(trial_photons, cost) + direct_rays;
    if (limited == 0 && !(trial_rays < plan_rays)) continue;
    predicted = std::move(trial);
    plan.photons = trial_photons;
    plan.samples_per_bin[g] = next_k * next_k;
    plan.rays += direct_rays;
    plan_rays = trial_rays;
  }
  return plan;
}

void raise_to_neyman_scale(const double* variance, const std::vector<double>& cost, double budget,
                           std::vector<double>& scale) {
  // Neyman: minimise sum_p c_p s_p subject to sum_p a_p / s_p = budget.
  const std::size_t n = cost.size();
  double sum = 0;
  for (std::size_t p = 0; p < n; ++p)
    if (cost[p] > 0) sum += std::sqrt(std::max(0.0, variance[p]) * cost[p]);
  for (std::size_t p = 0; p < n; ++p) {
    const double a = cost[p] > 0 ? std::max(0.0, variance[p]) : 0.0;
    if (a > 0) scale[p] = std::max(scale[p], std::sqrt(a / cost[p]) * sum / budget);
  }
}

AccuracyResult run_accuracy_rounds(const AccuracyCase& c, const AccuracyGoal& goal,
                                   const std::function<void(const std::string&)>& log) {
  return run_accuracy_rounds(c, goal, log, *make_local_round_work());
}

AccuracyResult run_accuracy_rounds(const AccuracyCase& c, const AccuracyGoal& goal,
                                   const std::function<void(const std::string&)>& log, RoundWork& work) {
  const engine::Scene& scene = *c.scene;
  const std::vector<engine::Material>& materials = *c.materials;
  const std::vector<engine::ReceiverPlane>& planes = *c.planes;
  const std::vector<SensorGrid>& grids = *c.grids;
  const std::size_t n = c.sources->size();
  const engine::PortEmitter emitter(scene, *c.sources);
  const Clock::time_point start = Clock::now();

  // The sky sources, each traced as source p of the set. The reference count of each source
  // (its photons at photons_per_bin) fixes the scale the bandwidth is meant for
  // (GridPhotons::set_source_scale).
  RoundSources sources;
  sources.reference.assign(n, 0.0);
  for (std::size_t p = 0; p < n; ++p) {
    const double factor = p < c.tracing.source_photon_factor.size() ? c.tracing.source_photon_factor[p] : 1.0;
    sources.reference[p] = double(c.tracing.photons_per_source) * factor;
  }
  sources.max_prepass_attempts_per_target = c.tracing.max_prepass_attempts_per_target;
  sources.empty_record = [&](std::size_t p) { return engine::empty_source_record(scene, materials, emitter, planes, p); };
  sources.trace = [&](std::size_t p, std::uint64_t first, std::uint64_t last) {
    return engine::round_attempt_range(scene, materials, emitter, planes, c.tracing, p, first, last);
  };

  // The direct component: the project's shadow rays until a round raises a grid's
  // (next_direct_round). Its time per shadow ray (the first process's clock) predicts a raise's.
  std::vector<engine::DaylightCoefficients> direct(grids.size());  // each grid's direct part alone
  std::vector<int> direct_samples(grids.size(), c.estimating.direct.samples_per_source);
  double direct_seconds = 0, direct_rays = 0;
  auto trace_direct = [&](std::size_t g) {
    const Clock::time_point t = Clock::now();
    direct[g] = grid_direct(c, g, direct_samples[g], work);
    direct_seconds += std::chrono::duration<double>(Clock::now() - t).count();
    direct_rays += double(grids[g].points.size()) *
                   direct_rays_per_sensor(direct_samples[g], n, c.estimating.direct.port_sampling);
  };
  for (std::size_t g = 0; g < grids.size(); ++g) trace_direct(g);
  std::vector<std::size_t> chased_grid;  // the grid of each of the last measure's chased variances
  std::vector<GridVariance> chased_variance;

  AccuracyResult result;
  result.outcome.target_percent = goal.target_percent;
  // Each round: every grid estimated from the photons so far, its DF and their variances.
  const RoundMeasure measure = [&](std::size_t round, const std::vector<engine::SourcePhotonRecord>& records,
                                   const std::vector<double>& scale) {
    // A plane's sensors next to a cut read the gathered grids' map, if there is one
    // (accuracy_policy.h); else the gather rounds estimate them once.
    const bool near_cut_here = near_cut_gathered_in_rounds(*c.plane_of_grid, c.gather);
    RoundGridMaps maps(*c.planes, *c.plane_of_grid, c.gather, round_photons(records, false), scale,
                       c.near_cut_sensors && near_cut_here ? *c.near_cut_sensors : std::vector<std::size_t>{});
    chased_grid.clear();
    result.coefficients.assign(grids.size(), {});
    result.outcome.reached_percent.assign(grids.size(), 0.0);
    result.outcome.near_cut.assign(grids.size(), NearCutReached{});
    RoundMeasurement m;
    m.grid_status.assign(grids.size(), "");
    m.met = true;
    for (std::size_t g = 0; g < grids.size(); ++g) {
      engine::DaylightCoefficients& dc = result.coefficients[g];
      dc = round_coefficients(c, g, maps, direct[g], work,
                              "accuracy round " + std::to_string(round) + ", grid " + grids[g].name);
      maps.done(g);
      GridVariance v;
      DaylightFactorParts parts =
          daylight_factor_parts(dc, *c.overcast_vector, c.horizontal_illuminance_lux, DaylightFactorSkyIndex);
      std::vector<double> stderr_percent = parts.stderr_percent();
      v.df_percent = std::move(parts.df_percent);
      v.direct_variance = std::move(parts.direct_variance);
      v.photon_variance = std::move(parts.photon_variance);
      // A plane's sensors next to a cut: out of the measure (accuracy_policy.h); where this
      // round does not gather them, their rows hold the plane's estimate until the gather rounds.
      NearCutReached& near = result.outcome.near_cut[g];
      const std::vector<std::size_t> cut_rows =
          near_cut_rows(*c.planes, *c.plane_of_grid, c.near_cut_sensors, grids[g].points, g);
      near = take_out_near_cut_rows(cut_rows, v.df_percent, stderr_percent);
      near.gather_rays = near.sensors > 0 && near_cut_here ? c.estimating.gather.rays_per_sensor : 0;
      const std::string near_cut = near_cut_note(near, goal.target_percent);
      const double reached = percentile_relative_stderr_percent(v.df_percent, stderr_percent, AccuracyPercentile);
      result.outcome.reached_percent[g] = reached;
      const bool chased = grid_chased_by_photons(*c.plane_of_grid, c.gather, g);
      m.grid_status[g] = accuracy_grid_status(chased, reached, goal.target_percent);
      m.grids += (g ? ", " : " ") + grids[g].name + " " + number(reached) + " %" +
                 (chased ? "" : " (gathered: its gather rays follow)") + near_cut;
      if (!chased) continue;
      m.met = m.met && reached <= goal.target_percent;
      m.chased.push_back(std::move(v));
      chased_grid.push_back(g);
      // The point-in-time cases' sky parts at this grid, each against itself (case_skies).
      std::string case_words;
      for (const CaseSky& sky : c.case_skies) {
        SkyIlluminanceParts sky_part = sky_illuminance_parts(dc, sky.vector, sky.direct_sky);
        std::vector<double> stderr_lux = sky_part.total();
        for (double& x : stderr_lux) x = std::sqrt(x);
        GridVariance cv;
        cv.df_percent = std::move(sky_part.lux);
        cv.direct_variance = std::move(sky_part.direct_variance);
        cv.photon_variance = std::move(sky_part.photon_variance);
        take_out_near_cut_rows(cut_rows, cv.df_percent, stderr_lux);
        const double case_reached = percentile_relative_stderr_percent(cv.df_percent, stderr_lux, AccuracyPercentile);
        case_words += (case_words.empty() ? "" : ", ") + sky.name + " " + number(case_reached) + " %";
        m.met = m.met && case_reached <= goal.target_percent;
        m.chased.push_back(std::move(cv));
        chased_grid.push_back(g);
      }
      if (!case_words.empty()) m.grids += " (point-in-time sky parts: " + case_words + ")";
    }
    chased_variance = m.chased;
    result.outcome.grid_status = m.grid_status;
    return m;
  };
  // The direct part's own round decision (next_direct_round) over the chased grids.
  RoundDirect round_direct;
  round_direct.plan = [&](const std::vector<double>& cost, const RoundPlan& photons, double aim_percent) {
    std::vector<int> samples;
    std::vector<std::size_t> sensors;
    for (std::size_t g : chased_grid) {
      samples.push_back(direct_samples[g]);
      sensors.push_back(grids[g].points.size());
    }
    return next_direct_round(chased_variance, samples, sensors, cost, photons, aim_percent, AccuracyPercentile, n,
                             c.estimating.direct.port_sampling);
  };
  // A raise's predicted time from the direct traces so far (the first process's clock).
  auto direct_raise_seconds = [&](double rays) {
    return direct_rays > 0 ? work.agreed(direct_seconds) / direct_rays * rays : 0.0;
  };
  round_direct.seconds = [&](const DirectRoundPlan& plan) { return direct_raise_seconds(plan.rays); };
  round_direct.apply = [&](std::size_t round, const DirectRoundPlan& plan) {
    // A grid measured more than once (its point-in-time cases' skies) takes the largest count.
    std::vector<int> next = direct_samples;
    for (std::size_t j = 0; j < chased_grid.size(); ++j)
      next[chased_grid[j]] = std::max(next[chased_grid[j]], plan.samples_per_bin[j]);
    for (std::size_t g = 0; g < grids.size(); ++g) {
      if (next[g] == direct_samples[g]) continue;
      log("accuracy: round " + std::to_string(round) + " raises grid " + grids[g].name +
          "'s shadow rays per bin " + std::to_string(direct_samples[g]) + " -> " + std::to_string(next[g]) +
          " (its direct part keeps it above the target)");
      direct_samples[g] = next[g];
      trace_direct(g);
    }
  };
  // Gathered grids above the target: more gather rays (gather_accuracy_rounds.h), which may
  // settle the stop reason, and more photons for their photon part.
  // Their shadow rays, raised as the chased grids' are (next_direct_round).
  GatherDirectRaise gather_direct;
  gather_direct.samples_per_bin = [&](std::size_t g) { return direct_samples[g]; };
  gather_direct.raise = [&](std::size_t g, int samples_per_bin) {
    direct_samples[g] = samples_per_bin;
    trace_direct(g);
  };
  gather_direct.seconds = direct_raise_seconds;
  gather_direct.port_sampling = c.estimating.direct.port_sampling;
  GatherPhotonRequest asked;     // of the last gather rounds
  std::string photon_stop;       // the photon rounds' stop they were given
  RoundLoopFinish gather_rounds;
  gather_rounds.finish = [&](RoundLoopOutcome& o, const std::vector<engine::SourcePhotonRecord>& records) {
    photon_stop = result.outcome.stop_reason = o.stop_reason;
    result.outcome.rounds = o.rounds;
    asked = run_gather_accuracy_rounds(c, goal, records, direct,
                                       std::chrono::duration<double>(Clock::now() - start).count(), work, log, result,
                                       gather_direct);
    o.stop_reason = result.outcome.stop_reason;
    return asked.scale;
  };
  gather_rounds.refused = [&](RoundLoopOutcome& o, const std::string& reason) {
    refuse_gather_photons(result.outcome, asked, reason, photon_stop);
    o.stop_reason = result.outcome.stop_reason;
  };
  const RoundLoopOutcome o =
      run_round_loop(sources, goal, measure, {"accuracy", DfMeasure}, log, work, start, gather_rounds, round_direct);
  result.outcome.direct_samples_per_bin = direct_samples;
  result.outcome.rounds = o.rounds;
  result.outcome.photons = o.photons;
  result.outcome.attempts = o.attempts;
  result.outcome.stop_reason = o.stop_reason;
  result.outcome.pilot_attempts = o.pilot_attempts;
  result.outcome.final_attempts = o.final_attempts;
  return result;
}

CaseAccuracy accuracy_coefficients(const AccuracyCase& c, const AccuracyGoal& goal, StepExecutor& executor,
                                   const std::vector<std::string>& photon_keys,
                                   const std::function<void(const std::string&)>& log) {
  // The goal and the policy are part of every key; the photon keys carry the scene, planes,
  // basis, seed, reference count and the other tracing options.
  const std::string rounds = "accuracy:" + number(goal.target_percent, "%.17g") + ":" +
                             std::to_string(goal.max_photons) + ":" + number(goal.max_seconds, "%.17g") + ":" +
                             number(AccuracyPercentile, "%.17g") + ":" + std::to_string(MaxAccuracyRounds) + ":" +
                             number(AccuracyPilotFraction, "%.17g") + ":" + number(AccuracyRoundAim, "%.17g") + ":" +
                             number(goal.max_growth, "%.17g") + ":direct-rays:" +
                             std::to_string(MaxDirectSamplesPerBin) + ":" + number(DirectVarianceExponent, "%.17g") +
                             ":" + (c.gather ? "gather-rays-photons:" + std::to_string(GatherMaxRounds) + ":" +
                                                   number(GatherMaxGrowth, "%.17g") + ":" + std::to_string(GatherMaxRays)
                                             : std::string("surface"));
  // The point-in-time skies the rounds hold to the target too.
  ContentHash skies;
  for (const CaseSky& sky : c.case_skies) {
    skies.text(sky.name).integer(sky.direct_sky ? std::int64_t(*sky.direct_sky) : -1);
    skies.integer(std::int64_t(sky.vector.rows())).integer(sky.vector.components());
    for (float x : sky.vector.data()) skies.number(x);
  }
  const std::string case_skies = c.case_skies.empty() ? std::string() : ":case-skies:" + skies.hex();
  std::vector<std::string> keys = photon_keys;
  for (std::string& k : keys) k += "|" + rounds + case_skies;
  const std::vector<SensorGrid>& grids = *c.grids;
  std::vector<std::string> grid_keys;
  // Every grid's coefficients depend on all grids' variances (the rounds serve them all).
  std::string all_grids;
  auto near_cuts = [&](std::size_t g) { return near_cut_count(*c.plane_of_grid, c.near_cut_sensors, g); };
  for (std::size_t g = 0; g < grids.size(); ++g) all_grids += coefficients_key(keys, grids[g], c.estimating, near_cuts(g)) + ";";
  for (std::string& k : keys) k += "|" + all_grids;
  for (std::size_t g = 0; g < grids.size(); ++g) grid_keys.push_back(coefficients_key(keys, grids[g], c.estimating, near_cuts(g)));
  const std::string outcome_key = grid_keys.empty() ? std::string("none") : grid_keys.front();
  // One step (plan_step.h): the coefficients of every grid, then the outcome. Not a pure
  // function of its inputs when max_seconds stops the rounds; collective, so every process
  // runs it together (rank 0's clock decides, round_work.h) rather than one process alone.
  CaseAccuracy out;
  Step step;
  step.kind = StepKind::SkyCoefficients;
  for (const std::string& k : grid_keys) step.outputs.push_back({"coefficients", k});
  step.outputs.push_back({"accuracy", outcome_key});
  // Collective (plan_step.h): every process of the run takes part in the rounds (round_work.h).
  step.collective = true;
  step.compute = [&]() -> std::vector<std::string> {
    AccuracyResult r = run_accuracy_rounds(c, goal, log, executor.round_work());
    std::vector<std::string> bytes;
    for (std::size_t g = 0; g < grids.size(); ++g) bytes.push_back(encode_coefficients(r.coefficients[g]));
    // Kept as the cache keeps the coefficients, so a later run from the cache writes the same bytes.
    for (std::size_t g = 0; g < grids.size(); ++g) r.coefficients[g] = decode_coefficients(bytes[g]);
    const nlohmann::json j = {{"target_percent", r.outcome.target_percent}, {"reached_percent", r.outcome.reached_percent},
                              {"rounds", r.outcome.rounds}, {"photons", r.outcome.photons},
                              {"attempts", r.outcome.attempts}, {"stop_reason", r.outcome.stop_reason},
                              {"grid_status", r.outcome.grid_status},
                              {"direct_samples_per_bin", r.outcome.direct_samples_per_bin},
                              {"gather", gather_accuracy_json(r.outcome.gather)},
                              {"near_cut", near_cut_reached_json(r.outcome.near_cut)}};
    bytes.push_back(j.dump());
    out.coefficients = std::move(r.coefficients);
    out.outcome = r.outcome;
    return bytes;
  };
  step.take = [&](const std::vector<std::string>& bytes) {
    std::vector<engine::DaylightCoefficients> cached;
    for (std::size_t g = 0; g < grids.size(); ++g) {
      cached.push_back(decode_coefficients(bytes.at(g)));
      if (cached.back().sensors != grids[g].points.size()) return false;
    }
    const nlohmann::json j = nlohmann::json::parse(bytes.at(grids.size()));
    AccuracyOutcome o;
    o.target_percent = j.at("target_percent").get<double>();
    o.reached_percent = j.at("reached_percent").get<std::vector<double>>();
    o.rounds = j.at("rounds").get<std::size_t>();
    o.photons = j.at("photons").get<std::uint64_t>();
    o.attempts = j.at("attempts").get<std::uint64_t>();
    o.stop_reason = j.at("stop_reason").get<std::string>();
    if (!j.contains("grid_status")) return false;  // made before the gathered grids' status
    o.grid_status = j.at("grid_status").get<std::vector<std::string>>();
    if (!j.contains("gather")) return false;  // made before the gather rounds
    o.gather = gather_accuracy_from_json(j.at("gather"));
    if (!j.contains("direct_samples_per_bin")) return false;  // made before the direct rounds
    o.direct_samples_per_bin = j.at("direct_samples_per_bin").get<std::vector<int>>();
    if (!j.contains("near_cut")) return false;  // made before the near-cut rows' record
    o.near_cut = near_cut_reached_from_json(j.at("near_cut"));
    if (o.reached_percent.size() != grids.size() || o.grid_status.size() != grids.size() ||
        o.gather.size() != grids.size() || o.direct_samples_per_bin.size() != grids.size() ||
        o.near_cut.size() != grids.size())
      return false;
    out.coefficients = std::move(cached);
    out.outcome = std::move(o);
    return true;
  };
  out.cached = executor.lookup(step);
  if (out.cached) {
    log("accuracy: cached (" + out.outcome.stop_reason + " after " + std::to_string(out.outcome.rounds) +
        " round(s))");
    return out;
  }
  executor.run(step);
  return out;
}

std::string accuracy_sentence(const AccuracyOutcome& o, std::size_t grid) {
  const double reached = grid < o.reached_percent.size() ? o.reached_percent[grid] : 0.0;
  const std::string status = grid < o.grid_status.size() && o.grid_status[grid] == "not reachable by photons"
                                 ? " (gathered: not reachable by photons; simulation.gather_rays lowers it)"
                                 : "";
  return round_outcome_sentence(DfMeasure, reached, o.target_percent, status + gather_accuracy_note(o, grid),
                                o.stop_reason, o.rounds, o.photons) +
         (grid < o.near_cut.size() ? near_cut_note(o.near_cut[grid], o.target_percent) : std::string());
}

}  // namespace dayphoton::study
