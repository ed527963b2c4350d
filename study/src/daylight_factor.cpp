// Daylight factor from daylight coefficients and grid statistics of a set of sensor values
// (issue 5 item 3). The product is dctimestep's for one sky column; the photometric weights
// are RADIANCE's (core/units.h). Statistics follow the usual DF reporting (BS 8206-2, EN
// 17037 annex: mean, median, min, max, uniformity min/mean, area above a threshold), each
// sensor standing for an equal area of a regular grid.
#include "dayphoton/study/daylight_factor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dayphoton/core/units.h"

namespace dayphoton::study {

namespace {

/// Photometric weight per component: 179 x RADIANCE's RGB weights for RGB matrices, 179 for
/// one-component (luminance-like) matrices. Throws for anything else.
std::vector<double> photometric_weights(int components) {
  if (components == 3)
    return {RadianceWhiteEfficacy_lm_per_W * RgbLuminanceWeights.x,
            RadianceWhiteEfficacy_lm_per_W * RgbLuminanceWeights.y,
            RadianceWhiteEfficacy_lm_per_W * RgbLuminanceWeights.z};
  if (components == 1) return {RadianceWhiteEfficacy_lm_per_W};
  throw std::invalid_argument("matrices must have 1 or 3 components, not " + std::to_string(components));
}

}  // namespace

std::vector<double> daylight_factor_percent(const RadianceMatrix& coefficients,
                                            const RadianceMatrix& sky_vector,
                                            double horizontal_illuminance_lux) {
  if (!(horizontal_illuminance_lux > 0) || !std::isfinite(horizontal_illuminance_lux))
    throw std::invalid_argument("daylight factor: the horizontal illuminance must be positive and finite");
  if (sky_vector.columns() != 1)
    throw std::invalid_argument("daylight factor: the sky vector has " + std::to_string(sky_vector.columns()) +
                                " columns, expected 1");
  if (coefficients.columns() != sky_vector.rows())
    throw std::invalid_argument("daylight factor: " + std::to_string(coefficients.columns()) +
                                " coefficient bins but a sky vector of " + std::to_string(sky_vector.rows()) +
                                " bins");
  if (coefficients.components() != sky_vector.components())
    throw std::invalid_argument("daylight factor: coefficients have " + std::to_string(coefficients.components()) +
                                " components, the sky vector " + std::to_string(sky_vector.components()));
  const int nc = coefficients.components();
  const std::vector<double> w = photometric_weights(nc);

  std::vector<double> df(coefficients.rows(), 0.0);
  for (std::size_t s = 0; s < coefficients.rows(); ++s) {
    double lux = 0;
    for (std::size_t p = 0; p < coefficients.columns(); ++p)
      for (int c = 0; c < nc; ++c)
        lux += w[c] * static_cast<double>(coefficients.at(s, p, c)) * static_cast<double>(sky_vector.at(p, 0, c));
    df[s] = 100.0 * lux / horizontal_illuminance_lux;
  }
  return df;
}

std::vector<double> daylight_factor_stderr_percent(const std::vector<double>& variance, std::size_t sensors,
                                                   const RadianceMatrix& sky_vector,
                                                   double horizontal_illuminance_lux) {
  if (!(horizontal_illuminance_lux > 0) || !std::isfinite(horizontal_illuminance_lux))
    throw std::invalid_argument("daylight factor: the horizontal illuminance must be positive and finite");
  const std::size_t bins = sky_vector.rows();
  if (variance.size() != sensors * bins)
    throw std::invalid_argument("daylight factor uncertainty: " + std::to_string(variance.size()) +
                                " variances for " + std::to_string(sensors) + " sensors x " + std::to_string(bins) +
                                " bins");
  const int nc = sky_vector.components();
  // The luminance-weighted radiance of each bin (one-component vectors: the value itself).
  std::vector<double> luminance(bins, 0.0);
  for (std::size_t p = 0; p < bins; ++p)
    luminance[p] = nc == 3 ? RgbLuminanceWeights.x * sky_vector.at(p, 0, 0) + RgbLuminanceWeights.y * sky_vector.at(p, 0, 1) +
                                 RgbLuminanceWeights.z * sky_vector.at(p, 0, 2)
                           : static_cast<double>(sky_vector.at(p, 0, 0));
  const double scale = 100.0 * RadianceWhiteEfficacy_lm_per_W / horizontal_illuminance_lux;
  std::vector<double> out(sensors, 0.0);
  for (std::size_t s = 0; s < sensors; ++s) {
    double v = 0;
    for (std::size_t p = 0; p < bins; ++p) v += luminance[p] * luminance[p] * variance[s * bins + p];
    out[s] = scale * std::sqrt(std::max(0.0, v));
  }
  return out;
}

DaylightFactorUncertainty daylight_factor_uncertainty(const std::vector<double>& df_percent,
                                                      const std::vector<double>& stderr_percent) {
  if (df_percent.size() != stderr_percent.size())
    throw std::invalid_argument("daylight factor uncertainty: " + std::to_string(df_percent.size()) + " values but " +
                                std::to_string(stderr_percent.size()) + " standard errors");
  DaylightFactorUncertainty u;
  double sum = 0;
  for (std::size_t s = 0; s < df_percent.size(); ++s) {
    if (!(df_percent[s] > 0)) continue;
    const double r = stderr_percent[s] / df_percent[s];
    sum += r * r;
    u.max_relative_stderr_percent = std::max(u.max_relative_stderr_percent, 100.0 * r);
    ++u.sensors_with_light;
  }
  if (u.sensors_with_light > 0) u.rms_relative_stderr_percent = 100.0 * std::sqrt(sum / double(u.sensors_with_light));
  return u;
}

GridStatistics grid_statistics(const std::vector<double>& values, const std::vector<double>& thresholds) {
  if (values.empty()) throw std::invalid_argument("grid statistics of an empty set of sensors");
  for (double v : values)
    if (!std::isfinite(v)) throw std::invalid_argument("grid statistics: a sensor value is not finite");
  GridStatistics g;
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  g.min = sorted.front();
  g.max = sorted.back();
  double sum = 0;
  for (double v : sorted) sum += v;
  g.mean = sum / static_cast<double>(n);
  // Median of an even count: the mean of the two middle values.
  g.median = n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  g.uniformity = g.mean != 0 ? g.min / g.mean : 0;
  for (double threshold : thresholds) {
    // ">=": a sensor exactly at the threshold meets it (as the DA and sDA conventions).
    const auto at_or_above = static_cast<double>(
        sorted.end() - std::lower_bound(sorted.begin(), sorted.end(), threshold));
    g.area_at_or_above_percent.emplace_back(threshold, 100.0 * at_or_above / static_cast<double>(n));
  }
  return g;
}

}  // namespace dayphoton::study
