// The Monte Carlo standard error of a point-in-time illuminance (docs/outputs.md,
// point_in_time.csv `<case>_stderr_lux`): the standard deviation the value would show over
// runs with other seeds, everything else equal, made as the daylight factor's and the annual
// illuminance's are (engine/estimate_variance.h). The case's parts are independent estimates
// (their own random streams), so their variances add:
//   - the sky and the ground: sky_illuminance_variance (daylight_factor.h) under the case's sky
//     column, with the direct part from the case's continuous sky where the value takes it
//     from there (the CIE cases) and the photon part from the photons' sky ratios where the
//     value takes it from there (cie_overcast: the DF's, scaled to its sky);
//   - the indirect sun: the sun bins' variances through the case's interpolation stencil
//     (interpolated_sun_variance, verdict_uncertainty.h);
//   - the exact direct sun: its shadow rays' collapsed-strata variance over the disc
//     (direct_sun_coefficients' `variance`): zero where the disc is wholly seen or wholly hidden,
//     the penumbra's where an edge crosses it.
// The sub-patch correction of the sky part (sub_patch_shares.h) re-weights the same estimates
// within each patch; its effect on the variance is left out, as the annual verdicts leave it
// out. Kernel bias is not variance and is not included.
#pragma once

#include <cstddef>
#include <vector>

#include "dayphoton/engine/sun_bins.h"
#include "dayphoton/study/daylight_factor.h"

namespace dayphoton::study {

/// The sun of one case at a grid's sensors.
struct PointInTimeSunVariance {
  double disc_radiance = 0;  ///< the sun's disc radiance, W/(sr m^2) (sky::SunRecord)
  /// Per sensor: the exact direct sun's luminance variance per unit disc radiance squared
  /// (direct_sun_coefficients' `variance`, this sun's column).
  std::vector<double> direct;
  /// sensors x bin_count: the sun bins' luminance variances (GridSun::bin_variance); null for
  /// none.
  const std::vector<float>* bins = nullptr;
  std::size_t bin_count = 0;
  engine::SunStencil stencil;  ///< the case's sun in the bins (engine::SunBins::weights)
};

/// Per sensor, a case's variance (lux^2) by part (header comment): what each part's own random
/// streams contribute, so the accuracy rounds and the run's statement can say which part keeps a
/// case above its target (point_in_time_accuracy.h).
struct PointInTimeVarianceParts {
  std::vector<double> sky;           ///< the sky and the ground (photons and shadow rays)
  std::vector<double> indirect_sun;  ///< the sun bins through the case's stencil
  std::vector<double> direct_sun;    ///< the exact direct sun's shadow rays over the disc
  /// sqrt of the three parts' sum per sensor: the standard error (lux).
  std::vector<double> stderr_lux() const;
};

/// `sky` in lux^2 (sky_illuminance_variance with unit_per_lux 1), `sun` the case's sun or null
/// (no sun: the sun parts zero). Throws std::invalid_argument on a size mismatch.
PointInTimeVarianceParts point_in_time_variance_parts(const SkyIlluminanceVariance& sky,
                                                      const PointInTimeSunVariance* sun);

/// Per sensor, the standard error (lux) of a case's illuminance: point_in_time_variance_parts'
/// stderr_lux().
std::vector<double> point_in_time_stderr_lux(const SkyIlluminanceVariance& sky, const PointInTimeSunVariance* sun);

}  // namespace dayphoton::study
