// The accuracy target's sun rounds: see sun_accuracy_rounds.h.
#include "dayphoton/study/sun_accuracy_rounds.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/photon_rounds.h"
#include "dayphoton/engine/port_emission.h"
#include "dayphoton/study/accuracy_policy.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/artifact_codec.h"
#include "dayphoton/study/gather_accuracy_rounds.h"
#include "dayphoton/study/round_grid_maps.h"
#include "dayphoton/study/sensor_blocks.h"
#include "accuracy_round_loop.h"

namespace dayphoton::study {
namespace {

/// What the sun rounds measure (the log lines and the outcome's sentence).
constexpr const char* SunMeasure = "annual sun-bin illuminance relative standard error";
/// What they measure with point-in-time cases (SunRoundCase).
constexpr const char* CaseMeasure = "point-in-time illuminance relative standard error";

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

/// A block of sensors' sun-bin coefficients and variances as one string (RoundWork::estimate):
/// the coefficient matrix's artefact bytes, then the variances as doubles (exact: the rounds
/// measure them before the cache rounds them to single precision).
std::string encode_sun_block(const RadianceMatrix& coefficients, const std::vector<double>& variance) {
  const std::string matrix = encode_matrix(coefficients);
  const std::uint64_t length = matrix.size();
  std::string out(sizeof length, '\0');
  std::memcpy(out.data(), &length, sizeof length);
  out += matrix;
  const std::size_t at = out.size();
  out.resize(at + variance.size() * sizeof(double));
  if (!variance.empty()) std::memcpy(out.data() + at, variance.data(), variance.size() * sizeof(double));
  return out;
}

/// The blocks of encode_sun_block joined in sensor order: the grid's coefficients (sensors x
/// bins x RGB) and variances (sensors x bins), as one estimate of the whole grid gives them.
void join_sun_blocks(const std::vector<std::string>& blocks, std::size_t sensors, std::size_t bins,
                     RadianceMatrix& coefficients, std::vector<double>& variance) {
  std::vector<std::string> matrices;
  variance.clear();
  variance.reserve(sensors * bins);
  for (const std::string& b : blocks) {
    std::uint64_t length = 0;
    if (b.size() < sizeof length) throw std::runtime_error("sun accuracy rounds: malformed block");
    std::memcpy(&length, b.data(), sizeof length);
    if (b.size() - sizeof length < length || (b.size() - sizeof length - length) % sizeof(double) != 0)
      throw std::runtime_error("sun accuracy rounds: malformed block");
    matrices.push_back(b.substr(sizeof length, length));
    const std::size_t values = (b.size() - sizeof length - length) / sizeof(double);
    const std::size_t at = variance.size();
    variance.resize(at + values);
    if (values > 0) std::memcpy(variance.data() + at, b.data() + sizeof length + length, values * sizeof(double));
  }
  coefficients = matrices.size() == 1 ? decode_matrix(matrices[0]) : decode_matrix(join_matrix_blocks(matrices));
  if (coefficients.rows() != sensors || coefficients.columns() != bins || variance.size() != sensors * bins)
    throw std::runtime_error("sun accuracy rounds: the blocks do not make the grid");
}

}  // namespace

engine::CoefficientOptions sun_annual_estimating(engine::CoefficientOptions estimating, const SunYearWeights& weights) {
  estimating.gather.variance_weights = weights.annual;
  return estimating;
}

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

GridVariance sun_case_variance(const RadianceMatrix& coefficients, const std::vector<double>& variance,
                               const engine::SunBins& bins, const sky::SunRecord& sun,
                               const std::vector<double>& other_lux, const std::vector<double>& other_variance) {
  const std::size_t sensors = coefficients.rows(), n = coefficients.columns();
  if (other_lux.size() != sensors || other_variance.size() != sensors || variance.size() != sensors * n)
    throw std::invalid_argument("sun rounds: a point-in-time case's parts do not match the grid's " +
                                std::to_string(sensors) + " sensors");
  const std::vector<double> lum = bin_luminance(coefficients);
  const engine::SunStencil st = bins.weights(sun.direction);
  const double scale = RadianceWhiteEfficacy_lm_per_W * sun.disc_radiance;
  GridVariance g;
  g.df_percent = other_lux;
  g.direct_variance = other_variance;
  g.photon_variance.assign(sensors * n, 0.0);
  for (std::size_t s = 0; s < sensors; ++s)
    for (int i = 0; i < st.count; ++i) {
      const std::size_t k = static_cast<std::size_t>(st.index[static_cast<std::size_t>(i)]);
      const double w = scale * st.weight[static_cast<std::size_t>(i)];
      g.df_percent[s] += w * lum[s * n + k];
      g.photon_variance[s * n + k] += w * w * variance[s * n + k];
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
  return run_sun_accuracy_rounds(c, goal, log, *make_local_round_work());
}

SunAccuracyResult run_sun_accuracy_rounds(const SunAccuracyCase& c, const AccuracyGoal& goal,
                                          const std::function<void(const std::string&)>& log, RoundWork& work) {
  const std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  const engine::Scene& scene = *c.scene;
  const std::vector<engine::Material>& materials = *c.materials;
  const std::vector<engine::ReceiverPlane>& planes = *c.planes;
  const std::vector<SensorGrid>& grids = *c.grids;
  const engine::SunBins& bins = *c.bins;
  const std::size_t n = bins.size();
  const engine::SourceSet sources = bins.sources(sky::SunHalfAngle_rad);
  const std::vector<char> lit = sun_bins_to_trace(engine::PortEmitter(scene, sources), n);
  // Each bin traced alone, as trace_sun_bin: its own disc, seed and emitter, source 0; its
  // photons relabelled as bin k in the maps. A bin not traced has a zero bound flux, so the
  // pilot leaves it at no attempts.
  std::vector<engine::SourceSet> one(n);
  std::vector<std::unique_ptr<engine::PortEmitter>> emitter(n);
  std::vector<engine::TracingOptions> tracing(n);
  for (std::size_t k = 0; k < n; ++k) {
    if (!lit[k]) continue;
    one[k] = sun_bin_source(bins, k);
    emitter[k] = std::make_unique<engine::PortEmitter>(scene, one[k]);
    tracing[k] = sun_bin_tracing(c.tracing, bins, k);
  }
  RoundSources bin_sources;
  bin_sources.reference.assign(n, double(c.tracing.photons_per_source));
  bin_sources.max_prepass_attempts_per_target = c.tracing.max_prepass_attempts_per_target;
  bin_sources.empty_record = [&](std::size_t k) {
    if (lit[k]) return engine::empty_source_record(scene, materials, *emitter[k], planes, 0);
    engine::SourcePhotonRecord none;
    none.raw.planes.resize(planes.size());
    none.raw.tallies.resize(1);
    return none;
  };
  bin_sources.trace = [&](std::size_t k, std::uint64_t first, std::uint64_t last) {
    return engine::round_attempt_range(scene, materials, *emitter.at(k), planes, tracing[k], 0, first, last);
  };

  const SunYearWeights weights = sun_year_weights(bins, *c.suns);
  // A gathered grid's rays' variance split over the bins as the annual measure sums them:
  // weighted by A_k (engine::GatherOptions::variance_weights, final_gather.h "Variance"), so
  // that sum_k A_k^2 var_k is the variance of the annual value's own rays; unit weights
  // overstate it (the rays are shared by the bins), and the rounds then traced more rays than
  // the target needs.
  const engine::CoefficientOptions estimating = sun_annual_estimating(c.estimating, weights);
  std::vector<char> chased(grids.size());
  for (std::size_t g = 0; g < grids.size(); ++g) chased[g] = grid_chased_by_photons(*c.plane_of_grid, c.gather, g);

  const bool by_case = c.cases && !c.cases->empty();
  SunAccuracyResult result;
  SunAccuracyOutcome& o = result.outcome;
  o.target_percent = goal.target_percent;
  // Grid g's hourly measure at the percentile over the sensors with sun-bin light (`annual`: each
  // sensor's annual value), from its coefficients and variances in `result`.
  auto hourly_percent = [&](std::size_t g, const std::vector<double>& annual) {
    const std::vector<double> hourly =
        sun_hourly_relative_stderr_percent(result.coefficients[g], result.variance[g], bins, *c.suns, weights);
    std::vector<double> se(hourly.size());
    for (std::size_t s = 0; s < se.size(); ++s) se[s] = hourly[s] / 100.0 * annual[s];
    return percentile_relative_stderr_percent(annual, se, AccuracyPercentile);
  };
  // Each round: every grid's sun-bin coefficients and variances by sensor blocks, then the
  // annual measure (the target's) and the hourly one (reported).
  const RoundMeasure measure = [&](std::size_t round, const std::vector<engine::SourcePhotonRecord>& records,
                                   const std::vector<double>& scale) {
    // A plane's sensors next to a cut read the gathered grids' map, if there is one
    // (accuracy_policy.h); else the gather rounds estimate them once.
    const bool near_cut_here = near_cut_gathered_in_rounds(*c.plane_of_grid, c.gather);
    RoundGridMaps maps(planes, *c.plane_of_grid, c.gather, round_photons(records, true), scale,
                       c.near_cut_sensors && near_cut_here ? *c.near_cut_sensors : std::vector<std::size_t>{});
    result.coefficients.assign(grids.size(), {});
    result.variance.assign(grids.size(), {});
    o.reached_percent.assign(grids.size(), 0.0);
    o.hourly_percent.assign(grids.size(), 0.0);
    o.near_cut.assign(grids.size(), NearCutReached{});
    o.case_reached_percent.assign(by_case ? grids.size() : 0, {});
    RoundMeasurement m;
    m.grid_status.assign(grids.size(), "");
    m.met = true;
    for (std::size_t g = 0; g < grids.size(); ++g) {
      const std::vector<std::string> blocks = work.estimate(
          grids[g].points.size(),
          [&](std::size_t begin, std::size_t end) {
            const engine::GridPhotons& gp = maps.of_grid(g);  // built once in a process that estimates some block
            std::vector<double> variance;
            const RadianceMatrix coefficients = sun_bin_coefficients(scene, materials, sources, gp, grids[g].points,
                                                                     estimating, &variance, {begin, end});
            return encode_sun_block(coefficients, variance);
          },
          "sun accuracy round " + std::to_string(round) + ", grid " + grids[g].name);
      maps.done(g);
      join_sun_blocks(blocks, grids[g].points.size(), n, result.coefficients[g], result.variance[g]);
      GridVariance v = sun_annual_variance(result.coefficients[g], result.variance[g], weights);
      std::vector<double> stderr_value(v.df_percent.size(), 0.0);
      for (std::size_t s = 0; s < stderr_value.size(); ++s) {
        double x = 0;
        for (std::size_t k = 0; k < n; ++k) x += v.photon_variance[s * n + k];
        stderr_value[s] = std::sqrt(std::max(0.0, x));
      }
      // A plane's sensors next to a cut: out of the measure (accuracy_policy.h); where this
      // round does not gather them, their rows hold the plane's estimate until the gather rounds.
      NearCutReached& near = o.near_cut[g];
      near = take_out_near_cut_rows(near_cut_rows(planes, *c.plane_of_grid, c.near_cut_sensors, grids[g].points, g),
                                    v.df_percent, stderr_value);
      near.gather_rays = near.sensors > 0 && near_cut_here ? estimating.gather.rays_per_sensor : 0;
      const std::string near_cut = near_cut_note(near, goal.target_percent);
      o.reached_percent[g] = percentile_relative_stderr_percent(v.df_percent, stderr_value, AccuracyPercentile);
      o.hourly_percent[g] = hourly_percent(g, v.df_percent);
      // Point-in-time cases: each case's illuminance is the measure (SunRoundCase), the grid's
      // reached value the largest of its cases'.
      std::vector<GridVariance> per_case;
      std::string case_words;
      if (by_case) {
        o.case_reached_percent[g].assign(c.cases->size(), 0.0);
        double largest = 0;
        for (std::size_t i = 0; i < c.cases->size(); ++i) {
          const SunRoundCase& pc = (*c.cases)[i];
          GridVariance cv = sun_case_variance(result.coefficients[g], result.variance[g], bins, c.suns->at(pc.sun),
                                              pc.other_lux.at(g), pc.other_variance.at(g));
          std::vector<double> se(cv.df_percent.size(), 0.0);
          for (std::size_t s = 0; s < se.size(); ++s) {
            double x = cv.direct_variance[s];
            for (std::size_t k = 0; k < n; ++k) x += cv.photon_variance[s * n + k];
            se[s] = std::sqrt(std::max(0.0, x));
          }
          take_out_near_cut_rows(near_cut_rows(planes, *c.plane_of_grid, c.near_cut_sensors, grids[g].points, g),
                                 cv.df_percent, se);
          const double reached = percentile_relative_stderr_percent(cv.df_percent, se, AccuracyPercentile);
          o.case_reached_percent[g][i] = reached;
          largest = std::max(largest, reached);
          case_words += (i ? ", " : "") + pc.name + " " + round_number(reached) + " %";
          // The indirect sun's budget at a sensor (SunRoundCase): what its other parts leave of
          // (aim E)^2, but never less than SunCaseBudgetFloor of it, so a sensor whose sky and
          // direct sun take nearly the whole budget asks for a bounded count (with the bare
          // remainder the office's sky-limited June cases asked for 32 times the photons every
          // round, 5.2 M -> 22.2 M in a fifth round that changed nothing). A sensor is left to
          // its other parts when they alone exceed (target E)^2 (no photon count helps) or
          // when its indirect sun is within that floor.
          const double target = goal.target_percent / 100.0, aim = AccuracyRoundAim * target;
          cv.left_out.assign(se.size(), 0);
          for (std::size_t s = 0; s < se.size(); ++s) {
            const double budget = std::pow(aim * cv.df_percent[s], 2);
            const double other = cv.direct_variance[s], indirect = se[s] * se[s] - other;
            const double cap = (1.0 - SunCaseBudgetFloor) * budget;
            cv.left_out[s] = other >= std::pow(target * cv.df_percent[s], 2) ||
                             (other >= cap && indirect <= SunCaseBudgetFloor * budget);
            cv.direct_variance[s] = std::min(other, cap);
          }
          per_case.push_back(std::move(cv));
        }
        o.reached_percent[g] = largest;
      }
      m.grid_status[g] = accuracy_grid_status(chased[g], o.reached_percent[g], goal.target_percent);
      m.grids += (g ? ", " : " ") + grids[g].name + " " + round_number(o.reached_percent[g]) + " % (" +
                 (by_case ? case_words : "hourly " + round_number(o.hourly_percent[g]) + " %") +
                 (chased[g] ? "" : ", gathered: its gather rays follow") + ")" + near_cut;
      if (chased[g]) {
        m.met = m.met && o.reached_percent[g] <= goal.target_percent;
        if (by_case)
          for (GridVariance& cv : per_case) m.chased.push_back(std::move(cv));
        else
          m.chased.push_back(std::move(v));
      }
    }
    o.grid_status = m.grid_status;
    return m;
  };
  // Gathered grids above the target: the sky's gather rounds (gather_accuracy_rounds.h) on the
  // annual measure. Its "DF" is 100 sum_k w . C_k L_k / E: with L_k the grey A_k and E = 100 x
  // 179 lx (w's efficacy) it is sum_k A_k (luminance of C_k), the annual value, and its
  // per-source weights A_k^2 those of sun_annual_variance.
  RadianceMatrix annual_weights(n, 1, 3);
  for (std::size_t k = 0; k < n; ++k)
    for (int i = 0; i < 3; ++i) annual_weights.at(k, 0, i) = static_cast<float>(weights.annual[k]);
  AccuracyCase gathered;
  gathered.scene = &scene;
  gathered.materials = &materials;
  gathered.sources = &sources;
  gathered.planes = &planes;
  gathered.plane_of_grid = c.plane_of_grid;
  gathered.near_cut_sensors = c.near_cut_sensors;
  gathered.grids = &grids;
  gathered.gather = c.gather;
  gathered.tracing = c.tracing;
  gathered.estimating = estimating;
  gathered.overcast_vector = &annual_weights;
  gathered.horizontal_illuminance_lux = 100.0 * RadianceWhiteEfficacy_lm_per_W;
  gathered.relabel_sources = true;
  gathered.round_name = "sun accuracy";
  gathered.measure_name = SunMeasure;
  // No direct part (the sun bins' coefficients are indirect): empty, zeros to the gather rounds.
  const std::vector<engine::DaylightCoefficients> no_direct(grids.size());
  AccuracyResult gather_result;  // the gather rounds' view of the outcome (their rounds kept across calls)
  GatherPhotonRequest asked;     // of the last gather rounds
  std::string photon_stop;       // the photon rounds' stop they were given
  RoundLoopFinish gather_rounds;
  gather_rounds.finish = [&](RoundLoopOutcome& lo, const std::vector<engine::SourcePhotonRecord>& records) {
    AccuracyOutcome& a = gather_result.outcome;
    a.target_percent = goal.target_percent;
    a.reached_percent = o.reached_percent;
    a.grid_status = o.grid_status;
    a.near_cut = o.near_cut;
    photon_stop = a.stop_reason = lo.stop_reason;
    a.rounds = lo.rounds;
    gather_result.coefficients.assign(grids.size(), {});
    asked = run_gather_accuracy_rounds(gathered, goal, records, no_direct, 0.0, work, log,
                                       gather_result);
    for (std::size_t g = 0; g < grids.size(); ++g) {
      engine::DaylightCoefficients& dc = gather_result.coefficients[g];
      if (chased[g] || dc.sensors != grids[g].points.size()) continue;  // not estimated again
      // As sun_bin_coefficients keeps them: caustic + global, and the variance of its luminance.
      RadianceMatrix m(dc.sensors, n, 3);
      for (std::size_t i = 0; i < dc.sensors * n; ++i) {
        const Vec3 total = Vec3{} + dc.caustic[i] + dc.global[i];
        for (int k = 0; k < 3; ++k) m.at(i / n, i % n, k) = static_cast<float>(total[k]);
      }
      result.coefficients[g] = std::move(m);
      result.variance[g] = std::move(dc.photon_variance);
      o.hourly_percent[g] =
          hourly_percent(g, sun_annual_variance(result.coefficients[g], result.variance[g], weights).df_percent);
    }
    // A plane's sensors next to a cut, gathered by the gather rounds: their rows spliced in, as
    // sun_bin_coefficients keeps them.
    for (std::size_t g = 0; g < grids.size() && g < gather_result.near_cut.size(); ++g) {
      const NearCutEstimate& e = gather_result.near_cut[g];
      if (e.rows.empty() || result.coefficients[g].rows() != grids[g].points.size()) continue;
      for (std::size_t r = 0; r < e.rows.size(); ++r)
        for (std::size_t k = 0; k < n; ++k) {
          const Vec3 total = Vec3{} + e.coefficients.caustic[r * n + k] + e.coefficients.global[r * n + k];
          for (int ch = 0; ch < 3; ++ch) result.coefficients[g].at(e.rows[r], k, ch) = static_cast<float>(total[ch]);
          result.variance[g][e.rows[r] * n + k] = e.coefficients.photon_variance[r * n + k];
        }
    }
    o.near_cut = a.near_cut;
    o.reached_percent = a.reached_percent;
    o.grid_status = a.grid_status;
    o.gather = a.gather;
    lo.stop_reason = a.stop_reason;
    return asked.scale;
  };
  gather_rounds.refused = [&](RoundLoopOutcome& lo, const std::string& reason) {
    refuse_gather_photons(gather_result.outcome, asked, reason, photon_stop);
    o.gather = gather_result.outcome.gather;
    lo.stop_reason = gather_result.outcome.stop_reason;
  };
  const RoundLoopOutcome loop = run_round_loop(bin_sources, goal, measure, {"sun accuracy", by_case ? CaseMeasure : SunMeasure}, log, work,
                                               start, gather_rounds);
  o.rounds = loop.rounds;
  o.photons = loop.photons;
  o.attempts = loop.attempts;
  o.stop_reason = loop.stop_reason;
  o.pilot_attempts = loop.pilot_attempts;
  o.final_attempts = loop.final_attempts;
  return result;
}

std::string sun_accuracy_sentence(const SunAccuracyOutcome& o, std::size_t grid) {
  const double reached = grid < o.reached_percent.size() ? o.reached_percent[grid] : 0.0;
  const double hourly = grid < o.hourly_percent.size() ? o.hourly_percent[grid] : 0.0;
  const std::string status = grid < o.grid_status.size() ? o.grid_status[grid] : "";
  if (!o.case_reached_percent.empty())  // point-in-time cases: the largest case's, each case stated apart
    return round_outcome_sentence(CaseMeasure, reached, o.target_percent, " (" + status + ", the grid's largest case)",
                                  o.stop_reason, o.rounds, o.photons);
  return round_outcome_sentence(SunMeasure, reached, o.target_percent,
                                " (" + status + "; hourly " + round_number(hourly) + " %)" +
                                    gather_accuracy_note(o.gather, grid),
                                o.stop_reason, o.rounds, o.photons) +
         (grid < o.near_cut.size() ? near_cut_note(o.near_cut[grid], o.target_percent) : std::string());
}

}  // namespace dayphoton::study
