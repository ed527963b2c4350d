// The accuracy target's sun rounds: see sun_accuracy_rounds.h.
#include "dayphoton/study/sun_accuracy_rounds.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include <tbb/parallel_for.h>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/photon_rounds.h"
#include "dayphoton/engine/port_emission.h"
#include "dayphoton/study/accuracy_policy.h"
#include "dayphoton/study/annual_sun.h"

namespace dayphoton::study {
namespace {

std::string number(double x, const char* format = "%.3g") {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, x);
  return buffer;
}

/// Luminance (RgbLuminanceWeights . C) of every (sensor, bin) of a sun-bin coefficient matrix.
std::vector<double> bin_luminance(const RadianceMatrix& c) {
  std::vector<double> l(c.rows() * c.columns(), 0.0);
  for (std::size_t s = 0; s < c.rows(); ++s)
    for (std::size_t k = 0; k < c.columns(); ++k)
      l[s * c.columns() + k] = c.components() == 3 ? RgbLuminanceWeights.x * c.at(s, k, 0) +
                                                         RgbLuminanceWeights.y * c.at(s, k, 1) +
                                                         RgbLuminanceWeights.z * c.at(s, k, 2)
                                                   : double(c.at(s, k, 0));
  return l;
}

}  // namespace

SunYearWeights sun_year_weights(const engine::SunBins& bins, const std::vector<sky::SunRecord>& suns) {
  SunYearWeights w;
  w.annual.assign(bins.size(), 0.0);
  w.squared.assign(bins.size(), 0.0);
  for (const sky::SunRecord& sun : suns) {
    const engine::SunStencil st = bins.weights(sun.direction);
    for (int k = 0; k < st.count; ++k) {
      const std::size_t bin = static_cast<std::size_t>(st.index[static_cast<std::size_t>(k)]);
      const double x = st.weight[static_cast<std::size_t>(k)] * sun.disc_radiance;
      w.annual[bin] += x;
      w.squared[bin] += x * x;
    }
  }
  return w;
}

GridVariance sun_annual_variance(const RadianceMatrix& coefficients, const std::vector<double>& variance,
                                 const SunYearWeights& weights) {
  const std::size_t sensors = coefficients.rows(), n = coefficients.columns();
  const std::vector<double> lum = bin_luminance(coefficients);
  GridVariance g;
  g.df_percent.assign(sensors, 0.0);
  g.direct_variance.assign(sensors, 0.0);
  g.photon_variance.assign(sensors * n, 0.0);
  for (std::size_t s = 0; s < sensors; ++s)
    for (std::size_t k = 0; k < n; ++k) {
      g.df_percent[s] += weights.annual[k] * lum[s * n + k];
      g.photon_variance[s * n + k] = weights.annual[k] * weights.annual[k] * variance[s * n + k];
    }
  return g;
}

std::vector<double> sun_hourly_relative_stderr_percent(const RadianceMatrix& coefficients,
                                                       const std::vector<double>& variance,
                                                       const engine::SunBins& bins,
                                                       const std::vector<sky::SunRecord>& suns,
                                                       const SunYearWeights& weights) {
  const std::size_t sensors = coefficients.rows(), n = coefficients.columns();
  const std::vector<double> lum = bin_luminance(coefficients);
  std::vector<double> square(sensors, 0.0), var(sensors, 0.0);
  for (const sky::SunRecord& sun : suns) {
    const engine::SunStencil st = bins.weights(sun.direction);
    for (std::size_t s = 0; s < sensors; ++s) {
      double e = 0;
      for (int k = 0; k < st.count; ++k)
        e += st.weight[static_cast<std::size_t>(k)] * lum[s * n + static_cast<std::size_t>(st.index[static_cast<std::size_t>(k)])];
      e *= sun.disc_radiance;
      square[s] += e * e;
    }
  }
  for (std::size_t s = 0; s < sensors; ++s)
    for (std::size_t k = 0; k < n; ++k) var[s] += weights.squared[k] * variance[s * n + k];
  std::vector<double> r(sensors, 0.0);
  for (std::size_t s = 0; s < sensors; ++s)
    if (square[s] > 0) r[s] = 100.0 * std::sqrt(std::max(0.0, var[s]) / square[s]);
  return r;
}

SunAccuracyResult run_sun_accuracy_rounds(const SunAccuracyCase& c, const AccuracyGoal& goal,
                                          const std::function<void(const std::string&)>& log) {
  const engine::Scene& scene = *c.scene;
  const std::vector<engine::Material>& materials = *c.materials;
  const std::vector<engine::ReceiverPlane>& planes = *c.planes;
  const std::vector<SensorGrid>& grids = *c.grids;
  const engine::SunBins& bins = *c.bins;
  const std::size_t n = bins.size();
  const engine::SourceSet sources = bins.sources(sky::SunHalfAngle_rad);
  const std::vector<char> lit = sun_bins_to_trace(engine::PortEmitter(scene, sources), n);
  // Each bin traced alone, as trace_sun_bin: its own disc, seed and emitter, source 0.
  std::vector<engine::SourceSet> one(n);
  std::vector<std::unique_ptr<engine::PortEmitter>> emitter(n);
  std::vector<engine::TracingOptions> tracing(n);
  for (std::size_t k = 0; k < n; ++k) {
    if (!lit[k]) continue;
    one[k] = sun_bin_source(bins, k);
    emitter[k] = std::make_unique<engine::PortEmitter>(scene, one[k]);
    tracing[k] = sun_bin_tracing(c.tracing, bins, k);
  }
  const double reference = double(c.tracing.photons_per_source);
  std::vector<engine::SourcePhotonRecord> records(n);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t k) {
    if (!lit[k]) return;
    const auto target = static_cast<std::size_t>(std::max(1.0, std::round(reference * AccuracyPilotFraction)));
    records[k] = engine::pilot_source_photons(scene, materials, *emitter[k], planes, tracing[k], 0, target);
  });
  SunAccuracyResult result;
  for (const auto& r : records) result.outcome.pilot_attempts.push_back(r.attempts);
  std::vector<double> per_attempt(n, 0.0);  // photons at the reference per attempt, from the pilot
  for (std::size_t k = 0; k < n; ++k) {
    if (!lit[k] || records[k].raw.tallies.empty()) continue;
    const engine::SourceTally& t = records[k].raw.tallies[0];
    const double stored = double(t.stored_global + t.stored_caustic);
    if (records[k].attempts > 0 && stored > 0) per_attempt[k] = stored / double(records[k].attempts) / reference;
  }
  const SunYearWeights weights = sun_year_weights(bins, *c.suns);
  std::vector<char> chased(grids.size());
  for (std::size_t g = 0; g < grids.size(); ++g) chased[g] = grid_chased_by_photons(*c.plane_of_grid, c.gather, g);

  SunAccuracyOutcome& o = result.outcome;
  o.target_percent = goal.target_percent;
  bool budget_cut = false;
  for (std::size_t round = 1;; ++round) {
    std::vector<engine::TracedPhotons> scaled(n);
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t k) {
      if (!lit[k]) {
        scaled[k].planes.resize(planes.size());
        scaled[k].tallies.resize(1);
        return;
      }
      scaled[k] = engine::scaled_source_photons(records[k]);
      relabel_photons(scaled[k], static_cast<std::uint32_t>(k));
    });
    const engine::TracedPhotons photons = engine::merge_traced_photons(std::move(scaled));
    std::vector<double> scale(n, 1.0);
    for (std::size_t k = 0; k < n; ++k)
      if (per_attempt[k] > 0) scale[k] = double(records[k].attempts) * per_attempt[k];
    result.coefficients.assign(grids.size(), {});
    result.variance.assign(grids.size(), {});
    o.reached_percent.assign(grids.size(), 0.0);
    o.hourly_percent.assign(grids.size(), 0.0);
    o.grid_status.assign(grids.size(), "");
    std::vector<GridVariance> chased_variances;
    bool met = true;
    for (std::size_t g = 0; g < grids.size(); ++g) {
      const int plane = (*c.plane_of_grid)[g];
      engine::GridPhotons gp =
          plane >= 0 ? engine::GridPhotons::for_plane(planes[std::size_t(plane)], photons.planes[std::size_t(plane)], n)
          : c.gather ? engine::GridPhotons::for_gather(photons.surface, n)
                     : engine::GridPhotons::for_surfaces(photons.surface, n);
      if (!gp.gather()) gp.set_source_scale(scale);
      result.coefficients[g] =
          sun_bin_coefficients(scene, materials, sources, gp, grids[g].points, c.estimating, &result.variance[g]);
      GridVariance v = sun_annual_variance(result.coefficients[g], result.variance[g], weights);
      std::vector<double> stderr_value(v.df_percent.size(), 0.0);
      for (std::size_t s = 0; s < stderr_value.size(); ++s) {
        double x = 0;
        for (std::size_t k = 0; k < n; ++k) x += v.photon_variance[s * n + k];
        stderr_value[s] = std::sqrt(std::max(0.0, x));
      }
      o.reached_percent[g] = percentile_relative_stderr_percent(v.df_percent, stderr_value, AccuracyPercentile);
      // The hourly measure at the same percentile, over the sensors with sun-bin light.
      const std::vector<double> hourly =
          sun_hourly_relative_stderr_percent(result.coefficients[g], result.variance[g], bins, *c.suns, weights);
      o.hourly_percent[g] = percentile_relative_stderr_percent(v.df_percent, [&] {
        std::vector<double> se(hourly.size());
        for (std::size_t s = 0; s < se.size(); ++s) se[s] = hourly[s] / 100.0 * v.df_percent[s];
        return se;
      }(), AccuracyPercentile);
      o.grid_status[g] = accuracy_grid_status(chased[g], o.reached_percent[g], goal.target_percent);
      if (chased[g]) {
        met = met && o.reached_percent[g] <= goal.target_percent;
        chased_variances.push_back(std::move(v));
      }
    }
    std::uint64_t stored = 0, attempts = 0;
    std::vector<double> cost(n, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
      stored += records[k].stored();
      attempts += records[k].attempts;
      if (lit[k]) cost[k] = double(records[k].raw.tallies[0].rays);
    }
    o.rounds = round;
    o.photons = stored;
    o.attempts = attempts;
    std::string line = "sun accuracy round " + std::to_string(round) + (round == 1 ? " (pilot)" : "") + ": " +
                       number(double(stored), "%.0f") + " photons, " + number(double(attempts), "%.0f") +
                       " attempts; annual sun-bin illuminance relative standard error (" +
                       number(AccuracyPercentile, "%.0f") + "th percentile)";
    for (std::size_t g = 0; g < grids.size(); ++g)
      line += (g ? ", " : " ") + grids[g].name + " " + number(o.reached_percent[g]) + " % (hourly " +
              number(o.hourly_percent[g]) + " %" + (chased[g] ? "" : ", gathered: not chased") + ")";
    log(line + " (target " + number(goal.target_percent) + " %)");
    if (met) {
      o.stop_reason = met_stop_reason(o.grid_status);
      break;
    }
    if (budget_cut) {
      o.stop_reason = "photon budget";
      break;
    }
    if (round >= MaxAccuracyRounds) {
      o.stop_reason = "round limit";
      break;
    }
    const RoundPlan plan = next_round_scale(chased_variances, cost, AccuracyRoundAim * goal.target_percent,
                                            AccuracyPercentile);
    std::vector<std::uint64_t> next(n);
    double more_photons = 0, more_attempts = 0;
    for (std::size_t k = 0; k < n; ++k) {
      next[k] = plan.scale[k] > 1.0 ? static_cast<std::uint64_t>(std::ceil(double(records[k].attempts) * plan.scale[k]))
                                    : records[k].attempts;
      more_attempts += double(next[k] - records[k].attempts);
      more_photons += double(records[k].stored()) * (plan.scale[k] - 1.0);
    }
    if (!(more_attempts > 0)) {
      o.stop_reason = "no light";
      break;
    }
    if (goal.max_photons > 0 && double(goal.max_photons) - double(stored) < more_photons) {
      const double share = std::max(0.0, (double(goal.max_photons) - double(stored)) / more_photons);
      for (std::size_t k = 0; k < n; ++k)
        next[k] = records[k].attempts +
                  static_cast<std::uint64_t>(std::floor(share * double(next[k] - records[k].attempts)));
      if (share < 0.05) {
        o.stop_reason = "photon budget";
        log("sun accuracy: no round " + std::to_string(round + 1) + ": the photon budget leaves room for " +
            number(100.0 * share) + " % of it");
        break;
      }
      budget_cut = true;
      log("sun accuracy: round " + std::to_string(round + 1) + " cut to " + number(100.0 * share) +
          " % of its plan by the photon budget; the last round");
    }
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t k) {
      if (lit[k]) engine::extend_source_photons(scene, materials, *emitter[k], planes, tracing[k], 0, next[k], records[k]);
    });
  }
  for (const auto& r : records) o.final_attempts.push_back(r.attempts);
  log("sun accuracy: " + o.stop_reason + " after " + std::to_string(o.rounds) + " round(s)");
  return result;
}

std::string sun_accuracy_sentence(const SunAccuracyOutcome& o, std::size_t grid) {
  const double reached = grid < o.reached_percent.size() ? o.reached_percent[grid] : 0.0;
  const double hourly = grid < o.hourly_percent.size() ? o.hourly_percent[grid] : 0.0;
  const std::string status = grid < o.grid_status.size() ? o.grid_status[grid] : "";
  return "annual sun-bin illuminance relative standard error (" + number(AccuracyPercentile, "%.0f") +
         "th percentile of the sensors) " + number(reached) + " % " + (reached <= o.target_percent ? "<=" : ">") +
         " target " + number(o.target_percent) + " % (" + status + "; hourly " + number(hourly) + " %): " +
         o.stop_reason + " after " + std::to_string(o.rounds) + " round(s), " + number(double(o.photons), "%.0f") +
         " photons";
}

}  // namespace dayphoton::study
