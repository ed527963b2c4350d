// verdict_uncertainty: see verdict_uncertainty.h.
#include "dayphoton/study/verdict_uncertainty.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "dayphoton/core/units.h"
#include "dayphoton/metrics/occupancy.h"

namespace dayphoton::study {

VerdictUncertainty verdict_uncertainty(const AnnualStudy& study, const AnnualSky& sky,
                                       const std::vector<double>& sky_variance, const SunBinVariance* sun,
                                       const AnnualStudySettings& settings) {
  const std::size_t n_steps = study.illuminance.step_count(), n_sensors = study.illuminance.sensor_count();
  const std::size_t bins = sky.matrix.rows();
  if (sky_variance.size() != n_sensors * bins || sky.matrix.columns() != n_steps)
    throw std::invalid_argument("verdict uncertainty: " + std::to_string(sky_variance.size()) + " variances for " +
                                std::to_string(n_sensors) + " sensors x " + std::to_string(bins) + " bins, " +
                                std::to_string(sky.matrix.columns()) + " sky steps for " + std::to_string(n_steps));
  const double efficacy2 = RadianceWhiteEfficacy_lm_per_W * RadianceWhiteEfficacy_lm_per_W;
  // Variance (lux^2) of every (step, sensor), occupied steps only.
  const metrics::OccupancySchedule occupancy = occupancy_schedule(settings, sky.steps);
  std::vector<double> variance(n_steps * n_sensors, 0.0);
  std::vector<double> radiance2(bins);
  const int nc = sky.matrix.components();
  for (std::size_t t = 0; t < n_steps; ++t) {
    if (!occupancy.occupied(t)) continue;
    for (std::size_t p = 0; p < bins; ++p) {
      const double l = nc == 3 ? RgbLuminanceWeights.x * sky.matrix.at(p, t, 0) + RgbLuminanceWeights.y * sky.matrix.at(p, t, 1) +
                                     RgbLuminanceWeights.z * sky.matrix.at(p, t, 2)
                               : double(sky.matrix.at(p, t, 0));
      radiance2[p] = l * l;
    }
    for (std::size_t s = 0; s < n_sensors; ++s) {
      double v = 0;
      for (std::size_t p = 0; p < bins; ++p) v += radiance2[p] * sky_variance[s * bins + p];
      variance[t * n_sensors + s] = efficacy2 * v;
    }
  }
  if (sun && sun->variance && sun->bins && sun->suns) {
    const std::size_t n_bins = sun->bins->size();
    if (sun->variance->size() != n_sensors * n_bins)
      throw std::invalid_argument("verdict uncertainty: the sun bins' variances do not match the sensors");
    for (const sky::SunRecord& record : *sun->suns) {
      if (record.step >= n_steps || !occupancy.occupied(record.step)) continue;
      const engine::SunStencil st = sun->bins->weights(record.direction);
      for (std::size_t s = 0; s < n_sensors; ++s) {
        double v = 0;
        for (int k = 0; k < st.count; ++k) {
          const double w = st.weight[static_cast<std::size_t>(k)];
          v += w * w * (*sun->variance)[s * n_bins + static_cast<std::size_t>(st.index[static_cast<std::size_t>(k)])];
        }
        variance[record.step * n_sensors + s] += efficacy2 * record.disc_radiance * record.disc_radiance * v;
      }
    }
  }
  VerdictUncertainty out;
  const std::size_t occupied = occupancy.occupied_count();
  if (occupied == 0) return out;
  const double threshold = settings.metrics.da_threshold_lux;
  double sum_variance = 0;
  for (std::size_t s = 0; s < n_sensors; ++s) {
    std::size_t low = 0, high = 0;
    for (std::size_t t = 0; t < n_steps; ++t) {
      if (!occupancy.occupied(t)) continue;
      const double e = study.illuminance.lux(t, s), v = variance[t * n_sensors + s];
      const double band = VerdictSigmas * std::sqrt(v);
      low += e - band >= threshold ? 1 : 0;
      high += e + band >= threshold ? 1 : 0;
      sum_variance += v;
    }
    const double need = settings.metrics.sda_time_fraction * double(occupied);
    if ((double(low) >= need) != (double(high) >= need)) ++out.da_verdicts_uncertain;
  }
  out.mean_occupied_stderr_lux = std::sqrt(sum_variance / (double(occupied) * double(n_sensors)));
  return out;
}

}  // namespace dayphoton::study
