// Which sensors' annual verdicts the Monte Carlo uncertainty leaves open (docs/metrics.md,
// "Uncertainty of the verdicts"): the standard error of every hour's illuminance from the
// coefficients' variances (engine/estimate_variance.h), and the sensors whose DA verdict
// (DA_X >= the sDA time fraction, the verdict sDA counts) differs between the illuminance
// lowered and raised by two standard errors in every occupied hour at once. All hours move
// together because their errors are those of the same coefficients (strongly correlated
// from hour to hour), which is the widest band the verdict can move in.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/engine/sun_bins.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/study/annual_study.h"

namespace dayphoton::study {

/// The sun bins' part of the variance (sun: bins): the indirect sun interpolated from the
/// bins, each bin's variance weighted by its stencil weight squared.
struct SunBinVariance {
  const std::vector<float>* variance = nullptr;  ///< sensors x bins, luminance (estimate_variance.h)
  const engine::SunBins* bins = nullptr;
  const std::vector<sky::SunRecord>* suns = nullptr;
};

/// The variance of the luminance of the sun-bin coefficients interpolated to one sun, per unit
/// disc radiance squared: sum_k w_k^2 Var(y_bin_k), `variance_row` one sensor's row of
/// SunBinVariance::variance (the bins are traced and estimated independently). Times
/// (179 disc radiance)^2 it is the indirect sun's variance in lux^2 (the verdicts' hours, the
/// point-in-time cases).
inline double interpolated_sun_variance(const engine::SunStencil& stencil, const float* variance_row) {
  double v = 0;
  for (int k = 0; k < stencil.count; ++k) {
    const double w = stencil.weight[static_cast<std::size_t>(k)];
    v += w * w * variance_row[static_cast<std::size_t>(stencil.index[static_cast<std::size_t>(k)])];
  }
  return v;
}

/// Multiplier of the standard error in the verdict test.
constexpr double VerdictSigmas = 2.0;

/// The hourly variances are computed for a block of sensors at a time, at most this many
/// values (16 MiB of doubles) whatever the grid's size: no sensors x hours table is held.
constexpr std::size_t VerdictSensorBlockValues = std::size_t(1) << 21;

struct VerdictUncertainty {
  std::size_t da_verdicts_uncertain = 0;  ///< sensors whose DA verdict could flip
  /// Their share of the grid's area (percent): the most sDA can move by. Set only for a grid
  /// whose sensors stand for unequal areas (AnnualStudySettings::sensor_area_m2), where it
  /// differs from the count's share.
  std::optional<double> da_verdicts_uncertain_area_percent;
  double mean_occupied_stderr_lux = 0;    ///< RMS over sensors and occupied hours of the standard error
};

/// `study` as computed (its illuminance and sensors), `sky` its sky, `sky_variance` the sky
/// coefficients' variance (sensors x bins, DaylightCoefficients::variance), `sun` the sun
/// bins' part or null. Throws std::invalid_argument on a size mismatch. `block_values`: the
/// hourly variances held at once (the result does not depend on it).
VerdictUncertainty verdict_uncertainty(const AnnualStudy& study, const AnnualSky& sky,
                                       const std::vector<double>& sky_variance, const SunBinVariance* sun,
                                       const AnnualStudySettings& settings,
                                       std::size_t block_values = VerdictSensorBlockValues);

}  // namespace dayphoton::study
