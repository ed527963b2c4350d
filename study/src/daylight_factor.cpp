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
#include "dayphoton/engine/estimate_variance.h"

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

/// The luminance of `rgb` weighted by bin p of the sky vector, lux: `w` its
/// photometric_weights (per component for RGB vectors; a one-component vector weights the
/// luminance).
double sky_weighted_lux(const Vec3& rgb, const std::vector<double>& w, const RadianceMatrix& sky_vector,
                        std::size_t p) {
  if (w.size() == 1) return w[0] * engine::luminance_of(rgb) * double(sky_vector.at(p, 0, 0));
  return w[0] * rgb.x * double(sky_vector.at(p, 0, 0)) + w[1] * rgb.y * double(sky_vector.at(p, 0, 1)) +
         w[2] * rgb.z * double(sky_vector.at(p, 0, 2));
}

}  // namespace

std::vector<double> sky_vector_luminance(const RadianceMatrix& sky_vector) {
  const int nc = sky_vector.components();
  std::vector<double> luminance(sky_vector.rows(), 0.0);
  for (std::size_t p = 0; p < luminance.size(); ++p)
    luminance[p] = nc == 3 ? RgbLuminanceWeights.x * sky_vector.at(p, 0, 0) + RgbLuminanceWeights.y * sky_vector.at(p, 0, 1) +
                                 RgbLuminanceWeights.z * sky_vector.at(p, 0, 2)
                           : static_cast<double>(sky_vector.at(p, 0, 0));
  return luminance;
}

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
  const std::vector<double> luminance = sky_vector_luminance(sky_vector);
  const double scale = 100.0 * RadianceWhiteEfficacy_lm_per_W / horizontal_illuminance_lux;
  std::vector<double> out(sensors, 0.0);
  for (std::size_t s = 0; s < sensors; ++s) {
    double v = 0;
    for (std::size_t p = 0; p < bins; ++p) v += luminance[p] * luminance[p] * variance[s * bins + p];
    out[s] = scale * std::sqrt(std::max(0.0, v));
  }
  return out;
}

std::vector<double> SkyIlluminanceVariance::total() const {
  const std::size_t sensors = direct_variance.size();
  const std::size_t bins = sensors ? photon_variance.size() / sensors : 0;
  std::vector<double> out(sensors, 0.0);
  for (std::size_t s = 0; s < sensors; ++s) {
    double v = direct_variance[s];
    if (!photon_sky_variance.empty())
      v += photon_sky_variance[s];
    else
      for (std::size_t p = 0; p < bins; ++p) v += photon_variance[s * bins + p];
    out[s] = std::max(0.0, v);
  }
  return out;
}

std::vector<double> DaylightFactorParts::stderr_percent() const {
  std::vector<double> out = total();
  for (double& v : out) v = std::sqrt(v);
  return out;
}

SkyIlluminanceVariance sky_illuminance_variance(const engine::DaylightCoefficients& c, const RadianceMatrix& sky_vector,
                                                double unit_per_lux, std::optional<std::size_t> direct_sky,
                                                std::optional<double> photon_sky_scale) {
  const std::size_t bins = c.sources, sensors = c.sensors;
  if (sky_vector.columns() != 1 || sky_vector.rows() != bins)
    throw std::invalid_argument("illuminance variance: " + std::to_string(bins) + " coefficient bins but a sky vector of " +
                                std::to_string(sky_vector.rows()) + " x " + std::to_string(sky_vector.columns()));
  if (c.direct_variance.size() != sensors * bins || c.photon_variance.size() != sensors * bins)
    throw std::invalid_argument("illuminance variance: coefficients without their parts' variances");
  const engine::DirectOnSkies& skies = c.direct_on_skies;
  if (direct_sky && (*direct_sky >= skies.skies || skies.variance.size() != sensors * skies.skies))
    throw std::invalid_argument("illuminance variance: sky " + std::to_string(*direct_sky) + " of " +
                                std::to_string(skies.skies) + " continuous skies");
  const engine::PhotonOnSky& photon_sky = c.photon_on_sky;
  if (photon_sky_scale && photon_sky.variance.size() != sensors)
    throw std::invalid_argument("illuminance variance: the photon part on the sky holds " +
                                std::to_string(photon_sky.variance.size()) + " variances for " +
                                std::to_string(sensors) + " sensors");
  const std::vector<double> luminance = sky_vector_luminance(sky_vector);
  const double variance_scale = std::pow(unit_per_lux * RadianceWhiteEfficacy_lm_per_W, 2);
  SkyIlluminanceVariance out;
  out.direct_variance.assign(sensors, 0.0);
  out.photon_variance.assign(sensors * bins, 0.0);
  if (photon_sky_scale) out.photon_sky_variance.assign(sensors, 0.0);
  for (std::size_t s = 0; s < sensors; ++s) {
    if (photon_sky_scale)
      out.photon_sky_variance[s] = variance_scale * *photon_sky_scale * *photon_sky_scale * photon_sky.variance[s];
    for (std::size_t p = 0; p < bins; ++p) {
      const std::size_t i = s * bins + p;
      out.photon_variance[i] = variance_scale * luminance[p] * luminance[p] * c.photon_variance[i];
      if (!direct_sky) out.direct_variance[s] += variance_scale * luminance[p] * luminance[p] * c.direct_variance[i];
    }
    if (direct_sky) out.direct_variance[s] = variance_scale * skies.variance[s * skies.skies + *direct_sky];
  }
  return out;
}

SkyIlluminanceParts sky_illuminance_parts(const engine::DaylightCoefficients& c, const RadianceMatrix& sky_vector,
                                          std::optional<std::size_t> direct_sky) {
  SkyIlluminanceParts out;
  static_cast<SkyIlluminanceVariance&>(out) = sky_illuminance_variance(c, sky_vector, 1.0, direct_sky, std::nullopt);
  if (c.caustic.size() != c.sensors * c.sources || c.global.size() != c.sensors * c.sources ||
      c.direct.size() != c.sensors * c.sources)
    throw std::invalid_argument("sky illuminance: coefficients without their parts");
  const std::vector<double> w = photometric_weights(sky_vector.components());
  const engine::DirectOnSkies& skies = c.direct_on_skies;
  out.lux.assign(c.sensors, 0.0);
  for (std::size_t s = 0; s < c.sensors; ++s) {
    double e_lux = 0;
    for (std::size_t p = 0; p < c.sources; ++p) {
      const std::size_t i = s * c.sources + p;
      e_lux += sky_weighted_lux(c.caustic[i] + c.global[i], w, sky_vector, p);
      if (!direct_sky) e_lux += sky_weighted_lux(c.direct[i], w, sky_vector, p);
    }
    if (direct_sky)
      e_lux += RadianceWhiteEfficacy_lm_per_W * engine::luminance_of(skies.irradiance[s * skies.skies + *direct_sky]);
    out.lux[s] = e_lux;
  }
  return out;
}

DaylightFactorParts daylight_factor_parts(const engine::DaylightCoefficients& c, const RadianceMatrix& sky_vector,
                                          double horizontal_illuminance_lux, std::size_t sky_index) {
  if (!(horizontal_illuminance_lux > 0) || !std::isfinite(horizontal_illuminance_lux))
    throw std::invalid_argument("daylight factor: the horizontal illuminance must be positive and finite");
  const std::size_t bins = c.sources, sensors = c.sensors;
  if (sky_vector.columns() != 1 || sky_vector.rows() != bins)
    throw std::invalid_argument("daylight factor: " + std::to_string(bins) + " coefficient bins but a sky vector of " +
                                std::to_string(sky_vector.rows()) + " x " + std::to_string(sky_vector.columns()));
  if (!c.has_variance() || c.direct.size() != sensors * bins)
    throw std::invalid_argument("daylight factor: coefficients without their parts' variances");
  const engine::DirectOnSkies& skies = c.direct_on_skies;
  const bool continuous = skies.skies > 0;
  if (continuous && sky_index >= skies.skies)
    throw std::invalid_argument("daylight factor: sky " + std::to_string(sky_index) + " of " +
                                std::to_string(skies.skies) + " continuous skies");
  // The photon part under the continuous sky: the coefficients carry it for their first sky.
  const engine::PhotonOnSky& photon_sky = c.photon_on_sky;
  const bool photon_continuous = continuous && sky_index == 0 && !photon_sky.empty();
  if (photon_continuous && (photon_sky.irradiance.size() != sensors || photon_sky.variance.size() != sensors))
    throw std::invalid_argument("daylight factor: the photon part on the sky holds " +
                                std::to_string(photon_sky.irradiance.size()) + " values for " +
                                std::to_string(sensors) + " sensors");
  const std::vector<double> w = photometric_weights(sky_vector.components());
  auto lux = [&](const Vec3& rgb, std::size_t p) { return sky_weighted_lux(rgb, w, sky_vector, p); };
  const double scale = 100.0 / horizontal_illuminance_lux;  // lux -> DF points
  DaylightFactorParts out;
  static_cast<SkyIlluminanceVariance&>(out) =
      sky_illuminance_variance(c, sky_vector, scale, continuous ? std::optional<std::size_t>(sky_index) : std::nullopt,
                               photon_continuous ? std::optional<double>(1.0) : std::nullopt);
  out.df_percent.assign(sensors, 0.0);
  for (std::size_t s = 0; s < sensors; ++s) {
    double e_lux = 0;
    if (photon_continuous) e_lux += RadianceWhiteEfficacy_lm_per_W * engine::luminance_of(photon_sky.irradiance[s]);
    for (std::size_t p = 0; p < bins; ++p) {
      const std::size_t i = s * bins + p;
      if (!photon_continuous) e_lux += lux(c.caustic[i] + c.global[i], p);
      if (!continuous) e_lux += lux(c.direct[i], p);
    }
    if (continuous) e_lux += RadianceWhiteEfficacy_lm_per_W * engine::luminance_of(skies.irradiance[s * skies.skies + sky_index]);
    out.df_percent[s] = scale * e_lux;
  }
  return out;
}

std::vector<double> continuous_sky_direct_correction_lux(const engine::DaylightCoefficients& c,
                                                         const RadianceMatrix& sky_vector, std::size_t sky_index) {
  const engine::DirectOnSkies& skies = c.direct_on_skies;
  std::vector<double> out(c.sensors, 0.0);
  if (skies.skies == 0) return out;
  if (sky_index >= skies.skies || sky_vector.rows() != c.sources || c.direct.size() != c.sensors * c.sources)
    throw std::invalid_argument("sky component correction: sky " + std::to_string(sky_index) + " of " +
                                std::to_string(skies.skies) + ", a vector of " + std::to_string(sky_vector.rows()) +
                                " bins for " + std::to_string(c.sources));
  const std::vector<double> w = photometric_weights(sky_vector.components());
  for (std::size_t s = 0; s < c.sensors; ++s) {
    double basis_lux = 0;
    for (std::size_t p = 0; p < c.sources; ++p)
      basis_lux += sky_weighted_lux(c.direct[s * c.sources + p], w, sky_vector, p);
    out[s] = RadianceWhiteEfficacy_lm_per_W * engine::luminance_of(skies.irradiance[s * skies.skies + sky_index]) -
             basis_lux;
  }
  return out;
}

std::vector<double> continuous_sky_photon_correction_lux(const engine::DaylightCoefficients& c,
                                                         const RadianceMatrix& sky_vector) {
  const engine::PhotonOnSky& on_sky = c.photon_on_sky;
  std::vector<double> out(c.sensors, 0.0);
  if (on_sky.empty()) return out;
  if (on_sky.irradiance.size() != c.sensors || sky_vector.rows() != c.sources ||
      c.caustic.size() != c.sensors * c.sources || c.global.size() != c.sensors * c.sources)
    throw std::invalid_argument("photon part correction: a vector of " + std::to_string(sky_vector.rows()) +
                                " bins for " + std::to_string(c.sources) + " and " +
                                std::to_string(on_sky.irradiance.size()) + " values for " +
                                std::to_string(c.sensors) + " sensors");
  const std::vector<double> w = photometric_weights(sky_vector.components());
  for (std::size_t s = 0; s < c.sensors; ++s) {
    double basis_lux = 0;
    for (std::size_t p = 0; p < c.sources; ++p) {
      const std::size_t i = s * c.sources + p;
      basis_lux += sky_weighted_lux(c.caustic[i] + c.global[i], w, sky_vector, p);
    }
    out[s] = RadianceWhiteEfficacy_lm_per_W * engine::luminance_of(on_sky.irradiance[s]) - basis_lux;
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

namespace {

/// grid_statistics over sensors standing for the areas `area_m2` (sums in sensor order, the
/// median's walk in value order, ties by sensor index: no value depends on the threads).
GridStatistics weighted_grid_statistics(const std::vector<double>& values, const std::vector<double>& thresholds,
                                        const std::vector<double>& area_m2) {
  GridStatistics g;
  const std::size_t n = values.size();
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  g.min = values[order.front()];
  g.max = values[order.back()];
  double total_m2 = 0, sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    total_m2 += area_m2[i];
    sum += area_m2[i] * values[i];
  }
  if (!(total_m2 > 0)) throw std::invalid_argument("grid statistics: the sensors' areas add up to no area");
  g.mean = sum / total_m2;
  // The value where the area, sorted by value, reaches half of the total.
  double below_m2 = 0;
  g.median = g.max;
  for (std::size_t k = 0; k < n; ++k) {
    below_m2 += area_m2[order[k]];
    if (below_m2 < 0.5 * total_m2) continue;
    g.median = below_m2 == 0.5 * total_m2 && k + 1 < n ? 0.5 * (values[order[k]] + values[order[k + 1]])
                                                        : values[order[k]];
    break;
  }
  g.uniformity = g.mean != 0 ? g.min / g.mean : 0;
  for (double threshold : thresholds) {
    double at_or_above_m2 = 0;  // ">=", as the unweighted count
    for (std::size_t i = 0; i < n; ++i)
      if (values[i] >= threshold) at_or_above_m2 += area_m2[i];
    g.area_at_or_above_percent.emplace_back(threshold, 100.0 * at_or_above_m2 / total_m2);
  }
  return g;
}

}  // namespace

GridStatistics grid_statistics(const std::vector<double>& values, const std::vector<double>& thresholds,
                               const std::vector<double>& area_m2) {
  if (values.empty()) throw std::invalid_argument("grid statistics of an empty set of sensors");
  for (double v : values)
    if (!std::isfinite(v)) throw std::invalid_argument("grid statistics: a sensor value is not finite");
  if (!area_m2.empty() && area_m2.size() != values.size())
    throw std::invalid_argument("grid statistics: " + std::to_string(area_m2.size()) + " areas for " +
                                std::to_string(values.size()) + " sensors");
  if (!area_m2.empty()) return weighted_grid_statistics(values, thresholds, area_m2);
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
