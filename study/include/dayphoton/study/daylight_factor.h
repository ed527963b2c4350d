// Daylight factor from daylight coefficients (issue 5 item 3): DF_s = 100 E_s / E_h, with
// E_s = sum_p C[s][p] . L_p (photometric: 179 lm/W and RADIANCE's RGB weights) for the
// CIE overcast sky vector L (ground bin 0 included, ground radiance from the project's
// ground reflectance, sky/sky_model.h ground_radiance_rgb) and E_h the unobstructed
// horizontal illuminance of that sky (the nominal value the vector was scaled to). The
// study's DF (daylight_factor_parts) takes the direct part from the shadow rays' estimate
// under the continuous sky instead, where the coefficients carry it.
#pragma once

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/engine/daylight_coefficients.h"

namespace dayphoton::study {

/// The luminance-weighted radiance of each bin of a sky vector (bins x 1; RADIANCE's RGB
/// weights, a one-component vector's value itself): the L_p whose squares weight the
/// coefficients' variances in every DF variance (daylight_factor_stderr_percent below, the
/// accuracy rounds, the gather's variance weights).
std::vector<double> sky_vector_luminance(const RadianceMatrix& sky_vector);

/// DF in percent per sensor. `coefficients`: sensors x bins x 3 (RADIANCE layout);
/// `sky_vector`: bins x 1 x 3 (one-component matrices are also accepted, weight 179);
/// `horizontal_illuminance_lux` > 0. Throws std::invalid_argument on a size or component
/// mismatch or a non-positive illuminance.
std::vector<double> daylight_factor_percent(const RadianceMatrix& coefficients,
                                            const RadianceMatrix& sky_vector,
                                            double horizontal_illuminance_lux);

/// The standard error of each sensor's DF in percent (points of DF): the sources are
/// independent, so Var(DF_s) = (100 x 179 / E_h)^2 sum_p L_p^2 Var(y_sp), y the luminance of
/// the coefficient and L_p the sky vector's luminance-weighted radiance (exact for a grey sky
/// such as the CIE overcast one; engine/estimate_variance.h). `variance` is
/// [sensor x bins + bin] (engine::DaylightCoefficients::variance). Throws
/// std::invalid_argument on a size mismatch or a non-positive illuminance.
std::vector<double> daylight_factor_stderr_percent(const std::vector<double>& variance, std::size_t sensors,
                                                   const RadianceMatrix& sky_vector,
                                                   double horizontal_illuminance_lux);

/// The Monte Carlo variance, by part, of an illuminance under one sky made from the
/// coefficients (engine/estimate_variance.h): the daylight factor's (daylight_factor_parts)
/// and each point-in-time case's sky part (point_in_time_uncertainty.h), in (unit)^2 for a
/// value in `unit_per_lux` x lux. The sources are independent, so a part summed over the
/// basis has the variance sum_p (179 L_p)^2 Var(y_sp); a part taken under a continuous sky
/// (the direct part by its shadow rays, the photon part by the photons' sky ratios) has that
/// estimate's own variance, which already holds the covariances of one ray or one photon
/// counted in several patches.
struct SkyIlluminanceVariance {
  std::vector<double> direct_variance;  ///< per sensor
  /// [sensor x bins + bin]: the basis's, by bin (what the accuracy rounds share out over the
  /// sources), also when the photon part is the continuous sky's.
  std::vector<double> photon_variance;
  /// Per sensor: the photon part's under the continuous sky, when the value takes it from
  /// there; empty otherwise.
  std::vector<double> photon_sky_variance;
  /// direct + photon variance per sensor: the photon part's on the sky when there is one,
  /// else the sum over the bins.
  std::vector<double> total() const;
};
/// `sky_vector`: the sky over the basis (bins x 1, 1 or 3 components; its luminance weights
/// the bins); `direct_sky`: the index among the coefficients' continuous skies of the sky
/// whose direct part the value takes (nullopt: the basis's sum); `photon_sky_scale`: the value
/// takes the photon part of the coefficients' photon_on_sky (the DF sky's) times this factor
/// (nullopt: the basis's sum). Throws std::invalid_argument on a size mismatch or missing
/// variances.
SkyIlluminanceVariance sky_illuminance_variance(const engine::DaylightCoefficients& coefficients,
                                                const RadianceMatrix& sky_vector, double unit_per_lux,
                                                std::optional<std::size_t> direct_sky,
                                                std::optional<double> photon_sky_scale);

/// A sky's illuminance through the coefficients (lux per sensor) with its variance by part
/// (lux^2): the direct part under continuous sky `direct_sky` of the coefficients (nullopt:
/// the sky-weighted sum over the basis), the photon part the sum over the basis. A
/// point-in-time case's sky part as the accuracy rounds measure it (accuracy_rounds.h,
/// AccuracyCase::case_skies), with the variance point_in_time_uncertainty.h states for it.
/// Throws std::invalid_argument as sky_illuminance_variance.
struct SkyIlluminanceParts : SkyIlluminanceVariance {
  std::vector<double> lux;  ///< per sensor
};
SkyIlluminanceParts sky_illuminance_parts(const engine::DaylightCoefficients& coefficients,
                                          const RadianceMatrix& sky_vector, std::optional<std::size_t> direct_sky);

/// A grid's DF and its variance by part ((DF points)^2), from coefficients that may carry the
/// direct part under the DF sky itself (engine::DaylightCoefficients::direct_on_skies; engine/
/// direct_component.h, "Continuous skies") and the photon part under it
/// (DaylightCoefficients::photon_on_sky; engine/photon_part_on_sky.h): each part the
/// continuous sky's where the coefficients carry it, free of the basis's patch-uniform
/// radiance, and the sky-weighted sum over the basis where they do not.
struct DaylightFactorParts : SkyIlluminanceVariance {
  std::vector<double> df_percent;  ///< per sensor
  /// sqrt(total()) per sensor.
  std::vector<double> stderr_percent() const;
};
/// `sky_vector`: the DF sky over the basis (bins x 1, 1 or 3 components); `sky_index`: the
/// DF sky's index among the coefficients' continuous skies (used when they carry any; the
/// photon part on the sky, when there is one, belongs to sky 0, the plan's DF sky).
/// Throws std::invalid_argument on a size mismatch, missing variances or a non-positive
/// illuminance.
DaylightFactorParts daylight_factor_parts(const engine::DaylightCoefficients& coefficients,
                                          const RadianceMatrix& sky_vector, double horizontal_illuminance_lux,
                                          std::size_t sky_index);

/// Per sensor, the direct illuminance (lux) of continuous sky `sky_index` minus the
/// sky-weighted sum of the direct coefficients under `sky_vector`, the same sky over the basis:
/// what the basis's patch-uniform radiance misses of the sky component (zeros when the
/// coefficients carry no continuous sky). Added to an illuminance computed through the
/// coefficients under a multiple of that sky, scaled alike, it makes it the continuous sky's.
std::vector<double> continuous_sky_direct_correction_lux(const engine::DaylightCoefficients& coefficients,
                                                         const RadianceMatrix& sky_vector, std::size_t sky_index);

/// Per sensor, the photon part (lux) under the continuous sky the coefficients' photon_on_sky
/// holds (the DF sky) minus the photon coefficients' sum over `sky_vector`, the same sky's bin
/// means: what the basis's patch-uniform radiance misses of the photon part (zeros without
/// photon_on_sky). The ground bin's photons have ratio 1 (engine/sky_ratios.h), so for any sky
/// of the same shape over the sky bins, scaled by k, the miss is k times this, whatever its
/// ground.
std::vector<double> continuous_sky_photon_correction_lux(const engine::DaylightCoefficients& coefficients,
                                                         const RadianceMatrix& sky_vector);

/// The uncertainty of a grid's DF (docs/outputs.md, summary.json `uncertainty`).
struct DaylightFactorUncertainty {
  /// sqrt(mean over sensors with DF > 0 of (stderr / DF)^2), percent.
  double rms_relative_stderr_percent = 0;
  double max_relative_stderr_percent = 0;  ///< the largest stderr / DF over those sensors
  std::size_t sensors_with_light = 0;      ///< sensors with DF > 0 (the others have no relative error)
};
DaylightFactorUncertainty daylight_factor_uncertainty(const std::vector<double>& df_percent,
                                                      const std::vector<double>& stderr_percent);

/// Grid statistics of a set of values (DF in percent here).
struct GridStatistics {
  double mean = 0, median = 0, min = 0, max = 0;
  double uniformity = 0;  ///< min / mean (0 if mean is 0)
  /// Per threshold: percentage of the area with value >= threshold (of the sensors, each an
  /// equal share, unless area_m2 is given).
  std::vector<std::pair<double, double>> area_at_or_above_percent;
};
/// Median of an even count is the mean of the two middle values. With `area_m2` (one per
/// value; SensorGrid::area_m2) the mean, the median and the shares are of the area: the
/// median is the value where the area sorted by value reaches half the total (the mean of
/// two values where it reaches exactly half between them); min, max and uniformity (min /
/// mean) stay of the sensors. Empty: equal shares, the unweighted formulas. Throws
/// std::invalid_argument for an empty or non-finite set, or another count of areas.
GridStatistics grid_statistics(const std::vector<double>& values, const std::vector<double>& thresholds,
                               const std::vector<double>& area_m2 = {});

}  // namespace dayphoton::study
