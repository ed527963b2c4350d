// Daylight factor from daylight coefficients (issue 5 item 3): DF_s = 100 E_s / E_h, with
// E_s = sum_p C[s][p] . L_p (photometric: 179 lm/W and RADIANCE's RGB weights) for the
// CIE overcast sky vector L (ground bin 0 included, ground radiance from the project's
// ground reflectance, sky/sky_model.h ground_radiance_rgb) and E_h the unobstructed
// horizontal illuminance of that sky (the nominal value the vector was scaled to).
#pragma once

#include <utility>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"

namespace dayphoton::study {

/// DF in percent per sensor. `coefficients`: sensors x bins x 3 (RADIANCE layout);
/// `sky_vector`: bins x 1 x 3 (one-component matrices are also accepted, weight 179);
/// `horizontal_illuminance_lux` > 0. Throws std::invalid_argument on a size or component
/// mismatch or a non-positive illuminance.
std::vector<double> daylight_factor_percent(const RadianceMatrix& coefficients,
                                            const RadianceMatrix& sky_vector,
                                            double horizontal_illuminance_lux);

/// Grid statistics of a set of values (DF in percent here).
struct GridStatistics {
  double mean = 0, median = 0, min = 0, max = 0;
  double uniformity = 0;  ///< min / mean (0 if mean is 0)
  /// Per threshold: percentage of sensors with value >= threshold (each sensor stands for
  /// an equal area on a regular grid).
  std::vector<std::pair<double, double>> area_at_or_above_percent;
};
/// Median of an even count is the mean of the two middle values. Throws
/// std::invalid_argument for an empty or non-finite set.
GridStatistics grid_statistics(const std::vector<double>& values,
                               const std::vector<double>& thresholds);

}  // namespace dayphoton::study
