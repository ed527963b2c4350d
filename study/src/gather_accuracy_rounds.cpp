// The gather rounds of the accuracy target: see gather_accuracy_rounds.h.
#include "dayphoton/study/gather_accuracy_rounds.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <stdexcept>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/final_gather.h"
#include "dayphoton/engine/photon_part_on_sky.h"
#include "dayphoton/study/accuracy_policy.h"
#include "dayphoton/study/artifact_codec.h"
#include "dayphoton/study/daylight_factor.h"
#include "dayphoton/study/simulation_plan.h"
#include "dayphoton/study/plan_policy.h"
#include "dayphoton/study/sensor_blocks.h"
#include "accuracy_round_loop.h"
#include "lazy_value.h"

namespace dayphoton::study {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::string number(double x, const char* format = "%.3g") {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, x);
  return buffer;
}

/// The smallest square >= n (the gather's k x k strata), at most GatherMaxRays.
int square_at_least(double n) {
  if (!(n > 1)) return 1;
  if (n >= double(GatherMaxRays)) return GatherMaxRays;
  int k = static_cast<int>(std::sqrt(n));
  while (double(k) * k < n) ++k;
  return std::min(k * k, GatherMaxRays);
}

/// A sensor block's bytes: its coefficient artefact, then the fixed part of its gather variance
/// (engine::GatheredCoefficients::fixed_photon_variance) as raw doubles.
std::string frame_block(const std::string& coefficients, const std::vector<double>& fixed) {
  const std::uint64_t size = coefficients.size();
  std::string out(sizeof size, '\0');
  std::memcpy(out.data(), &size, sizeof size);
  out += coefficients;
  const std::size_t at = out.size();
  out.resize(at + fixed.size() * sizeof(double));
  if (!fixed.empty()) std::memcpy(out.data() + at, fixed.data(), fixed.size() * sizeof(double));
  return out;
}

/// The inverse: the coefficient artefact into `coefficients`, the doubles appended to `fixed`.
void unframe_block(const std::string& block, std::string& coefficients, std::vector<double>& fixed) {
  std::uint64_t size = 0;
  if (block.size() < sizeof size) throw std::runtime_error("gather rounds: malformed sensor block");
  std::memcpy(&size, block.data(), sizeof size);
  const std::size_t rest = block.size() - sizeof size;
  if (size > rest || (rest - size) % sizeof(double) != 0) throw std::runtime_error("gather rounds: malformed sensor block");
  coefficients = block.substr(sizeof size, size);
  const std::size_t count = (rest - size) / sizeof(double);
  const std::size_t at = fixed.size();
  fixed.resize(at + count);
  if (count > 0) std::memcpy(fixed.data() + at, block.data() + sizeof size + size, count * sizeof(double));
}

/// One estimate of a gathered grid and its variances in DF units.
struct GridEstimate {
  engine::DaylightCoefficients dc;
  std::vector<double> df_percent, direct_variance, gather_variance, fixed_variance;  ///< per sensor, (DF %)^2
  std::vector<double> fixed_per_source;  ///< [sensor x sources + source], (DF %)^2: fixed_variance by source
  std::vector<double> fixed;             ///< the gather's fixed part as estimated (coefficient units)
  double reached_percent = 0;
};

/// Each sensor's relative standard error of DF in percent from its direct and gather variances
/// (0 for a sensor without daylight).
std::vector<double> relative_stderr_percent(const std::vector<double>& df_percent,
                                            const std::vector<double>& direct_variance,
                                            const std::vector<double>& gather_variance) {
  std::vector<double> relative(df_percent.size(), 0.0);
  for (std::size_t i = 0; i < df_percent.size(); ++i)
    relative[i] = df_percent[i] > 0
                      ? 100.0 * std::sqrt(std::max(0.0, direct_variance[i] + gather_variance[i])) / df_percent[i]
                      : 0.0;
  return relative;
}

/// The largest of `relative` over the sensors with light (0 without any).
double largest_of(const std::vector<double>& relative, const std::vector<double>& df_percent) {
  double largest = 0;
  for (std::size_t i = 0; i < relative.size(); ++i)
    if (df_percent[i] > 0) largest = std::max(largest, relative[i]);
  return largest;
}

/// Grid g, which the time budget leaves no gather round on the photons traced since its last
/// gather estimate: that estimate stands, with its accuracy, rays and rounds (the photon rounds'
/// estimate at the project's rays if it has none), and its stop is the time budget unless it
/// had met the target.
void keep_last_gather(AccuracyResult& result, std::size_t g, double target_percent) {
  AccuracyOutcome& outcome = result.outcome;
  GatherAccuracy& a = outcome.gather[g];
  GatheredEstimate& last = result.gathered[g];
  if (last.accuracy.rays > 0) {
    result.coefficients[g] = std::move(last.coefficients);
    outcome.reached_percent[g] = last.reached_percent;
    a = last.accuracy;
    last = GatheredEstimate{};
  } else {
    a.rounds = 0;  // a.rays is the project's: the photon rounds' estimate is the one written
  }
  if (!(outcome.reached_percent[g] <= target_percent)) a.stop_reason = "time budget";
  outcome.grid_status[g] = outcome.reached_percent[g] <= target_percent ? "met" : "above target";
}

}  // namespace

GatherRayPlan next_gather_rays(const std::vector<double>& df_percent, const std::vector<double>& direct_variance,
                               const std::vector<double>& gather_variance, const std::vector<double>& fixed_variance,
                               int rays, double aim_percent, double percentile) {
  const std::vector<double> relative = relative_stderr_percent(df_percent, direct_variance, gather_variance);
  GatherRayPlan plan;
  double needed = rays;
  for (const std::size_t i : sensors_at_or_below_percentile(relative, df_percent, percentile)) {
    if (!(relative[i] > aim_percent)) continue;
    ++plan.sensors_constrained;
    const double allowed = aim_percent / 100.0 * df_percent[i];
    const double budget = allowed * allowed - direct_variance[i];
    if (!(budget > 0)) {
      ++plan.sensors_direct_limited;
      continue;
    }
    // V_g(N') = alpha + beta / N' (header comment).
    const double v = std::max(0.0, gather_variance[i]);
    const double alpha = std::clamp(fixed_variance[i], 0.0, v);
    const double beta = (v - alpha) * rays;
    if (!(budget > alpha) || !(beta > 0)) {
      ++plan.sensors_photon_limited;
      continue;
    }
    needed = std::max(needed, beta / (budget - alpha));
  }
  plan.rays = needed > rays ? square_at_least(std::min(needed, GatherMaxGrowth * rays)) : rays;
  return plan;
}

GatherPhotonPlan next_gather_photons(const std::vector<double>& df_percent, const std::vector<double>& direct_variance,
                                     const std::vector<double>& gather_variance,
                                     const std::vector<double>& fixed_per_source, int rays,
                                     const std::vector<double>& cost, double aim_percent, double percentile,
                                     double max_growth) {
  const std::size_t n = cost.size();
  const std::vector<double> relative = relative_stderr_percent(df_percent, direct_variance, gather_variance);
  GatherPhotonPlan plan;
  plan.scale.assign(n, 1.0);
  for (const std::size_t i : sensors_at_or_below_percentile(relative, df_percent, percentile)) {
    if (!(relative[i] > aim_percent)) continue;
    const double allowed = aim_percent / 100.0 * df_percent[i];
    const double budget = allowed * allowed - direct_variance[i];
    if (!(budget > 0)) continue;  // direct-limited: photons do not help
    const double v = std::max(0.0, gather_variance[i]);
    double alpha = 0;
    for (std::size_t p = 0; p < n; ++p) alpha += fixed_per_source[i * n + p];
    alpha = std::clamp(alpha, 0.0, v);
    // The rays' part left to the rays (header comment): what it is now, at most half the
    // budget, but never below what it would be at the ray limit.
    const double rays_part = v - alpha;
    const double left_to_rays =
        std::min(rays_part, std::max(0.5 * budget, rays_part * double(rays) / double(GatherMaxRays)));
    const double photon_budget = budget - left_to_rays;
    if (!(photon_budget > 0) || !(alpha > photon_budget)) continue;
    ++plan.sensors;
    raise_to_neyman_scale(&fixed_per_source[i * n], cost, photon_budget, plan.scale);
  }
  for (double& x : plan.scale) x = std::min(x, max_growth);
  return plan;
}

void refuse_gather_photons(AccuracyOutcome& outcome, const GatherPhotonRequest& request, const std::string& reason,
                           const std::string& photon_stop) {
  const std::string stop = reason == "round limit" ? "photon round limit" : reason;
  for (const std::size_t g : request.grids) outcome.gather.at(g).stop_reason = stop;
  settle_case_stop(outcome, photon_stop);
}

void settle_case_stop(AccuracyOutcome& outcome, const std::string& photon_stop) {
  // The photon rounds stopped because only gathered grids were left (met_stop_reason): their
  // own stops decide it.
  outcome.stop_reason = photon_stop;
  if (photon_stop != "not reachable by photons") return;
  outcome.stop_reason = "target met";
  for (std::size_t g = 0; g < outcome.grid_status.size(); ++g)
    if (outcome.grid_status[g] != "met" && g < outcome.gather.size()) {
      outcome.stop_reason = outcome.gather[g].stop_reason;
      break;
    }
}

GatherPhotonRequest run_gather_accuracy_rounds(const AccuracyCase& c, const AccuracyGoal& goal,
                                const std::vector<engine::SourcePhotonRecord>& records,
                                const std::vector<engine::DaylightCoefficients>& direct, double seconds_so_far,
                                RoundWork& work, const std::function<void(const std::string&)>& log,
                                AccuracyResult& result, const GatherDirectRaise& raise_direct) {
  const Clock::time_point start = Clock::now();
  const std::vector<SensorGrid>& grids = *c.grids;
  const std::size_t n = c.sources->size();
  AccuracyOutcome& outcome = result.outcome;
  // After a photon round asked for by an earlier call, each grid starts from the rays it reached.
  if (outcome.gather.size() != grids.size()) outcome.gather.assign(grids.size(), GatherAccuracy{});
  if (result.gathered.size() != grids.size()) result.gathered.assign(grids.size(), GatheredEstimate{});
  const std::string photon_stop = outcome.stop_reason;
  GatherPhotonRequest request;
  request.scale.assign(n, 1.0);
  std::vector<double> cost(n);
  for (std::size_t p = 0; p < n; ++p) cost[p] = double(records[p].raw.tallies.at(0).rays);
  const int first_rays = square_at_least(double(std::max(1, c.estimating.gather.rays_per_sensor)));

  // The overcast sky's weights: a sensor's DF variance is sum_p (df_scale L_p)^2 var_p.
  const RadianceMatrix& sky = *c.overcast_vector;
  const double df_scale = 100.0 * RadianceWhiteEfficacy_lm_per_W / c.horizontal_illuminance_lux;
  const std::vector<double> luminance = sky_vector_luminance(sky);
  std::vector<double> weight(n);
  for (std::size_t p = 0; p < n; ++p) {
    const double l = luminance[p];
    weight[p] = df_scale * df_scale * l * l;
  }
  auto measure = [&](engine::DaylightCoefficients dc, const std::vector<double>& fixed) {
    GridEstimate e;
    e.fixed_variance.assign(dc.sensors, 0.0);
    e.fixed_per_source.assign(dc.sensors * n, 0.0);
    DaylightFactorParts parts = daylight_factor_parts(dc, sky, c.horizontal_illuminance_lux, DaylightFactorSkyIndex);
    const std::vector<double> stderr_percent = parts.stderr_percent();
    e.df_percent = std::move(parts.df_percent);
    e.direct_variance = std::move(parts.direct_variance);
    e.gather_variance.assign(dc.sensors, 0.0);
    for (std::size_t i = 0; i < dc.sensors; ++i) {
      for (std::size_t p = 0; p < n; ++p) {
        e.gather_variance[i] += parts.photon_variance[i * n + p];
        e.fixed_per_source[i * n + p] = weight[p] * fixed[i * n + p];
        e.fixed_variance[i] += e.fixed_per_source[i * n + p];
      }
    }
    e.reached_percent = percentile_relative_stderr_percent(e.df_percent, stderr_percent, AccuracyPercentile);
    e.dc = std::move(dc);
    e.fixed = fixed;
    return e;
  };

  // The photons of the last round, merged once, for any grid that needs more rays.
  LazyValue<engine::GridPhotons> maps;
  auto build = [&] { return engine::GridPhotons::for_gather(engine::scaled_merged_photons(records, c.relabel_sources).surface, n); };
  // Grid g's gather at `rays`: of every sensor, or (rows given) of those rows alone, each row
  // bit for bit that sensor's gather in the whole grid (seeded by its index).
  auto estimate = [&](std::size_t g, int rays, const std::string& name, const std::vector<std::size_t>* rows = nullptr) {
    const SensorGrid& grid = grids[g];
    engine::CoefficientOptions options = c.estimating;
    options.gather.rays_per_sensor = rays;
    options.gather.sky_quadrants = options.photon_quadrants;  // as photon_coefficients' gather
    const std::vector<std::string> blocks = work.estimate(
        rows ? rows->size() : grid.points.size(),
        [&](std::size_t begin, std::size_t end) {
          const engine::GridPhotons& gp = maps.get(build);
          engine::DaylightCoefficients dc;
          // The gather of photon_coefficients, with the part more rays do not reduce; the sun
          // bins' gathered grids have no direct part (zeros).
          engine::GatheredCoefficients gathered;
          // The photon part on the DF's continuous sky from the same rays (engine/final_gather.h).
          std::optional<engine::GatherOnSky> on_sky;
          if (!options.photon_sky_bin_radiance_rgb.empty() && options.photon_sky_ratios)
            on_sky.emplace(engine::GatherOnSky{*options.photon_sky_ratios, options.photon_sky_bin_radiance_rgb});
          if (rows) {
            const std::vector<std::size_t> which(rows->begin() + std::ptrdiff_t(begin), rows->begin() + std::ptrdiff_t(end));
            copy_direct_rows(direct[g], which, n, dc);
            gathered = engine::gather_photon_coefficients_at(*c.scene, *c.materials, *c.sources, gp.all(), grid.points,
                                                             options.gather, &gp.groups(), which, on_sky ? &*on_sky : nullptr);
          } else {
            copy_direct_rows(direct[g], begin, end, n, dc);
            gathered = engine::gather_photon_coefficients(*c.scene, *c.materials, *c.sources, gp.all(), grid.points,
                                                          options.gather, &gp.groups(), {begin, end},
                                                          on_sky ? &*on_sky : nullptr);
          }
          dc.caustic = std::move(gathered.caustic);
          dc.global = std::move(gathered.global);
          dc.photon_variance = std::move(gathered.variance);
          dc.photon_quadrants = std::move(gathered.quadrants);
          dc.photon_on_sky.irradiance = std::move(gathered.on_sky);
          dc.photon_on_sky.variance = std::move(gathered.on_sky_variance);
          return frame_block(encode_coefficients(dc), gathered.fixed_photon_variance);
        },
        name);
    std::vector<std::string> coefficients(blocks.size());
    std::vector<double> fixed;
    for (std::size_t b = 0; b < blocks.size(); ++b) unframe_block(blocks[b], coefficients[b], fixed);
    return measure(decode_coefficients(join_coefficient_blocks(coefficients)), fixed);
  };

  double elapsed_s = seconds_so_far;
  for (std::size_t g = 0; g < grids.size(); ++g) {
    if (grid_chased_by_photons(*c.plane_of_grid, c.gather, g)) continue;
    GatherAccuracy& a = outcome.gather[g];
    const int start_rays = a.gathered ? std::max(a.rays, first_rays) : first_rays;
    a.gathered = true;
    a.first_rays = a.rays = first_rays;  // the photon rounds' estimate, until another replaces it
    a.stop_reason.clear();
    if (outcome.reached_percent[g] <= goal.target_percent) {
      // The photon rounds' estimate at the project's rays is the one written: no gather round.
      a.rounds = 0;
      a.stop_reason = "target met";
      outcome.grid_status[g] = "met";
      result.gathered[g] = GatheredEstimate{};
      continue;
    }
    if (goal.max_seconds > 0 && work.agreed(elapsed_s + seconds_since(start)) >= goal.max_seconds) {
      log(c.round_name + ": grid " + grids[g].name + ": no gather round: the time budget is spent" +
          (result.gathered[g].accuracy.rays > 0 ? "; its last gather estimate stands" : ""));
      keep_last_gather(result, g, goal.target_percent);
      continue;
    }
    // The photon rounds' estimate again, with its fixed part (the same coefficients: the
    // same photons, rays and seed); or, after a photon round asked for by this grid, an
    // estimate at the rays it had reached (a gather round).
    Clock::time_point t = Clock::now();
    GridEstimate now = estimate(
        g, start_rays,
        c.round_name + " gather round " + (start_rays > first_rays ? std::to_string(a.rounds + 1) : std::string("0")) +
            ", grid " + grids[g].name);
    double seconds_per_ray = seconds_since(t) / start_rays;  // of the last estimate, per gather ray per sensor
    std::size_t rounds_now = 0;  // gather rounds on these photons
    if (start_rays > first_rays) {
      a.rays = start_rays;
      ++a.rounds;
      ++rounds_now;
      log(c.round_name + " gather round " + std::to_string(a.rounds) + ", grid " + grids[g].name + ": " +
          std::to_string(a.rays) + " gather rays per sensor (the rays reached before this photon round); " + c.measure_name + " "
          "(" + number(AccuracyPercentile, "%.0f") + "th percentile) " + number(now.reached_percent) +
          " % (target " + number(goal.target_percent) + " %)");
    }
    for (;;) {
      outcome.reached_percent[g] = now.reached_percent;
      if (now.reached_percent <= goal.target_percent) {
        a.stop_reason = "target met";
        break;
      }
      const GatherRayPlan plan = next_gather_rays(now.df_percent, now.direct_variance, now.gather_variance,
                                                  now.fixed_variance, a.rays, AccuracyRoundAim * goal.target_percent,
                                                  AccuracyPercentile);
      // No more gather rays (none would help, or the ray or round limit): the direct part's raise.
      const bool no_more_rays = plan.rays <= a.rays || rounds_now >= GatherMaxRounds || a.rays >= GatherMaxRays;
      if (no_more_rays && plan.sensors_direct_limited > 0 && raise_direct) {
        // More shadow rays by the photon rounds' rule (header comment), for this grid alone.
        GridVariance v;
        v.df_percent = now.df_percent;
        v.direct_variance = now.direct_variance;
        v.photon_variance.assign(now.dc.sensors * n, 0.0);
        for (std::size_t i = 0; i < now.dc.sensors; ++i)
          for (std::size_t p = 0; p < n; ++p) v.photon_variance[i * n + p] = weight[p] * now.dc.photon_variance[i * n + p];
        RoundPlan no_photons;
        no_photons.scale.assign(n, 1.0);
        const int samples = raise_direct.samples_per_bin(g);
        const DirectRoundPlan d =
            next_direct_round({v}, {samples}, {grids[g].points.size()}, cost, no_photons,
                              AccuracyRoundAim * goal.target_percent, AccuracyPercentile, n, raise_direct.port_sampling);
        if (d.raised()) {
          if (goal.max_seconds > 0) {
            const double spent = work.agreed(elapsed_s + seconds_since(start));
            const double need = raise_direct.seconds(d.rays);
            if (spent + need > goal.max_seconds) {
              a.stop_reason = "time budget";
              log(c.round_name + ": grid " + grids[g].name + ": no raise of shadow rays: it would take about " + number(need) +
                  " s of the " + number(goal.max_seconds - spent) + " s left");
              break;
            }
          }
          log(c.round_name + ": grid " + grids[g].name + ": shadow rays per bin " + std::to_string(samples) + " -> " +
              std::to_string(d.samples_per_bin[0]) + " (its direct part keeps it above the target)");
          raise_direct.raise(g, d.samples_per_bin[0]);
          // The same gather (photons, rays, seed) with the new direct part.
          engine::DaylightCoefficients dc = std::move(now.dc);
          copy_direct_rows(direct[g], 0, dc.sensors, n, dc);
          const std::vector<double> fixed = std::move(now.fixed);
          now = measure(std::move(dc), fixed);
          log(c.round_name + ": grid " + grids[g].name + ": " + c.measure_name + " (" +
              number(AccuracyPercentile, "%.0f") + "th percentile) " + number(now.reached_percent) + " % at " +
              std::to_string(d.samples_per_bin[0]) + " shadow rays per bin (target " + number(goal.target_percent) +
              " %)");
          continue;
        }
        if (d.sensors_at_limit > 0 && plan.sensors_photon_limited == 0 && plan.rays <= a.rays) {
          a.stop_reason = "direct rays limit";
          log(c.round_name + ": grid " + grids[g].name + ": " + std::to_string(d.sensors_at_limit) +
              " sensor(s) miss the target by their direct component alone at " +
              direct_rays_limit_words(d.samples_at_limit));
          break;
        }
      }
      if (rounds_now >= GatherMaxRounds) {
        a.stop_reason = "round limit";
        break;
      }
      if (a.rays >= GatherMaxRays) {
        a.stop_reason = "gather ray limit";
        break;
      }
      if (plan.rays <= a.rays) {
        a.stop_reason = plan.sensors_photon_limited > 0 ? "gather photon part" : "direct component";
        log(c.round_name + ": grid " + grids[g].name + ": " + std::to_string(plan.sensors_photon_limited) +
            " sensor(s) above the aim by the gather's photon part (which more rays do not reduce: more photons "
            "or simulation.gather_bandwidth would) and " +
            std::to_string(plan.sensors_direct_limited) +
            " by their direct component alone (simulation.direct_samples_per_bin)");
        break;
      }
      if (goal.max_seconds > 0) {
        // The first process's clock, so that every process stops alike (round_work.h); before
        // the grid's first gather round only the time already spent counts.
        const double spent = work.agreed(elapsed_s + seconds_since(start));
        const double need = work.agreed(seconds_per_ray * plan.rays);
        if (spent + need > goal.max_seconds) {
          a.stop_reason = "time budget";
          log(c.round_name + ": grid " + grids[g].name + ": no gather round with " + std::to_string(plan.rays) +
              " rays: it would take about " + number(need) + " s of the " + number(goal.max_seconds - spent) +
              " s left");
          break;
        }
      }
      t = Clock::now();
      now = estimate(g, plan.rays, c.round_name + " gather round " + std::to_string(a.rounds + 1) + ", grid " + grids[g].name);
      seconds_per_ray = seconds_since(t) / plan.rays;
      a.rays = plan.rays;
      ++a.rounds;
      ++rounds_now;
      log(c.round_name + " gather round " + std::to_string(a.rounds) + ", grid " + grids[g].name + ": " +
          std::to_string(a.rays) + " gather rays per sensor; " + c.measure_name + " (" +
          number(AccuracyPercentile, "%.0f") + "th percentile) " + number(now.reached_percent) + " % (target " +
          number(goal.target_percent) + " %)");
    }
    // A grid that rays cannot bring further asks for more photons (header comment).
    if (a.stop_reason == "gather photon part" || a.stop_reason == "gather ray limit") {
      const GatherPhotonPlan photons =
          next_gather_photons(now.df_percent, now.direct_variance, now.gather_variance, now.fixed_per_source, a.rays,
                              cost, AccuracyRoundAim * goal.target_percent, AccuracyPercentile, goal.max_growth);
      double largest = 1.0;
      std::size_t growing = 0;
      for (std::size_t p = 0; p < n; ++p) {
        largest = std::max(largest, photons.scale[p]);
        if (photons.scale[p] > 1.0) ++growing;
        request.scale[p] = std::max(request.scale[p], photons.scale[p]);
      }
      if (growing > 0) {
        request.grids.push_back(g);
        log(c.round_name + ": grid " + grids[g].name + ": " + std::to_string(photons.sensors) +
            " sensor(s) ask for more photons for the gather's photon part: up to " + number(largest) +
            " times the photons of " + std::to_string(growing) + " source(s)");
      }
    }
    outcome.grid_status[g] = outcome.reached_percent[g] <= goal.target_percent ? "met" : "above target";
    result.gathered[g] = GatheredEstimate{};
    if (a.rays > first_rays) result.gathered[g] = GatheredEstimate{now.dc, outcome.reached_percent[g], a};
    result.coefficients[g] = std::move(now.dc);
  }
  // A plane's sensors next to a cut (accuracy_policy.h), which the photon rounds' measure leaves
  // out: gathered here from the last round's photons at the project's rays where the rounds did
  // not gather them (whatever the time budget: their rows hold the plane's estimate until then;
  // near.gather_rays 0), then the same gather rounds over those rows alone, on the largest of
  // their errors.
  if (outcome.near_cut.size() != grids.size()) outcome.near_cut.resize(grids.size());
  result.near_cut.assign(grids.size(), NearCutEstimate{});
  for (std::size_t g = 0; g < grids.size(); ++g) {
    NearCutReached& near = outcome.near_cut[g];
    if (near.sensors == 0) continue;
    near.rounds = 0;
    near.stop_reason = "target met";
    const bool gathered_in_rounds = near.gather_rays > 0;
    if (gathered_in_rounds && near.largest_percent <= goal.target_percent) continue;
    const std::vector<std::size_t> rows = near_cut_rows(*c.planes, *c.plane_of_grid, c.near_cut_sensors, grids[g].points, g);
    if (rows.empty()) continue;
    const std::string who = "grid " + grids[g].name + "'s " + std::to_string(rows.size()) + " sensors next to a cut";
    int rays = first_rays;
    Clock::time_point t = Clock::now();
    GridEstimate now = estimate(g, rays, c.round_name + " near-cut gather, " + who, &rows);
    double seconds_per_ray = seconds_since(t) / rays;
    for (;;) {
      const std::vector<double> relative =
          relative_stderr_percent(now.df_percent, now.direct_variance, now.gather_variance);
      near.largest_percent = largest_of(relative, now.df_percent);
      if (near.largest_percent <= goal.target_percent) {
        near.stop_reason = "target met";
        break;
      }
      // Over every one of them (the 100th percentile): their largest is what the verdict states.
      const GatherRayPlan plan = next_gather_rays(now.df_percent, now.direct_variance, now.gather_variance,
                                                  now.fixed_variance, rays, AccuracyRoundAim * goal.target_percent, 100.0);
      if (near.rounds >= GatherMaxRounds) {
        near.stop_reason = "round limit";
        break;
      }
      if (rays >= GatherMaxRays) {
        near.stop_reason = "gather ray limit";
        break;
      }
      if (plan.rays <= rays) {
        near.stop_reason = plan.sensors_photon_limited > 0 ? "gather photon part" : "direct component";
        break;
      }
      if (goal.max_seconds > 0) {
        const double spent = work.agreed(elapsed_s + seconds_since(start));
        if (spent + work.agreed(seconds_per_ray * plan.rays) > goal.max_seconds) {
          near.stop_reason = "time budget";
          break;
        }
      }
      t = Clock::now();
      now = estimate(g, plan.rays, c.round_name + " gather round " + std::to_string(near.rounds + 1) + ", " + who, &rows);
      seconds_per_ray = seconds_since(t) / plan.rays;
      rays = plan.rays;
      ++near.rounds;
      log(c.round_name + " gather round " + std::to_string(near.rounds) + ", " + who + ": " + std::to_string(rays) +
          " gather rays per sensor; largest relative standard error " +
          number(largest_of(relative_stderr_percent(now.df_percent, now.direct_variance, now.gather_variance),
                            now.df_percent)) +
          " % (target " + number(goal.target_percent) + " %)");
    }
    near.gather_rays = rays;
    // The grid's rows replaced where the grid's coefficients are held here (the sky's rounds;
    // the sun's splice result.near_cut into their own).
    engine::DaylightCoefficients& whole = result.coefficients[g];
    if (whole.sensors == grids[g].points.size() && whole.sources == n) {
      for (std::size_t r = 0; r < rows.size(); ++r)
        for (std::size_t p = 0; p < n; ++p) {
          whole.caustic[rows[r] * n + p] = now.dc.caustic[r * n + p];
          whole.global[rows[r] * n + p] = now.dc.global[r * n + p];
          whole.photon_variance[rows[r] * n + p] = now.dc.photon_variance[r * n + p];
          if (!whole.photon_quadrants.empty())
            for (std::size_t q = 0; q < engine::StoredQuadrants; ++q)
              whole.photon_quadrants[(rows[r] * n + p) * engine::StoredQuadrants + q] =
                  now.dc.photon_quadrants.empty() ? 0.0f
                                                  : now.dc.photon_quadrants[(r * n + p) * engine::StoredQuadrants + q];
        }
      // Their photon part on the DF sky: the gather's own (engine/final_gather.h, "The
      // continuous sky"), or without the sky ratios its basis sum (engine/photon_part_on_sky.h),
      // in place of the plane's estimate where the rounds did not gather them.
      if (!whole.photon_on_sky.empty()) {
        const engine::PhotonOnSky& gathered = now.dc.photon_on_sky;
        for (std::size_t r = 0; r < rows.size(); ++r)
          if (!gathered.empty()) {
            whole.photon_on_sky.irradiance.at(rows[r]) = gathered.irradiance.at(r);
            whole.photon_on_sky.variance.at(rows[r]) = gathered.variance.at(r);
          } else {
            engine::set_basis_row(whole.photon_on_sky, rows[r], now.dc, r, c.estimating.photon_sky_bin_radiance_rgb);
          }
        if (!gathered_in_rounds && gathered.empty()) whole.photon_on_sky.basis_rows += rows.size();
      }
    }
    result.near_cut[g] = NearCutEstimate{rows, std::move(now.dc)};
  }
  settle_case_stop(outcome, photon_stop);
  if (request.grids.empty()) request.scale.clear();
  return request;
}

std::string gather_accuracy_note(const AccuracyOutcome& outcome, std::size_t grid) {
  return gather_accuracy_note(outcome.gather, grid);
}

std::string gather_accuracy_note(const std::vector<GatherAccuracy>& gather, std::size_t grid) {
  if (grid >= gather.size() || !gather[grid].gathered) return "";
  const GatherAccuracy& a = gather[grid];
  return " (final gather, " + std::to_string(a.rays) + " rays per sensor" +
         (a.rounds > 0 ? ", " + std::to_string(a.rounds) + " gather round(s) from " + std::to_string(a.first_rays)
                       : std::string()) +
         ": " + a.stop_reason + ")";
}

}  // namespace dayphoton::study
