// point_in_time_stderr_lux: see point_in_time_uncertainty.h.
#include "dayphoton/study/point_in_time_uncertainty.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "dayphoton/core/units.h"
#include "dayphoton/study/verdict_uncertainty.h"

namespace dayphoton::study {

PointInTimeVarianceParts point_in_time_variance_parts(const SkyIlluminanceVariance& sky,
                                                      const PointInTimeSunVariance* sun) {
  PointInTimeVarianceParts parts;
  parts.sky = sky.total();
  const std::size_t sensors = parts.sky.size();
  parts.indirect_sun.assign(sensors, 0.0);
  parts.direct_sun.assign(sensors, 0.0);
  if (!sun) return parts;
  if (sun->direct.size() != sensors || (sun->bins && sun->bins->size() != sensors * sun->bin_count))
    throw std::invalid_argument("point-in-time uncertainty: the sun's variances (" + std::to_string(sun->direct.size()) +
                                " direct) do not match " + std::to_string(sensors) + " sensors");
  const double scale = std::pow(RadianceWhiteEfficacy_lm_per_W * sun->disc_radiance, 2);
  for (std::size_t s = 0; s < sensors; ++s) {
    parts.direct_sun[s] = scale * sun->direct[s];
    if (sun->bins)
      parts.indirect_sun[s] = scale * interpolated_sun_variance(sun->stencil, sun->bins->data() + s * sun->bin_count);
  }
  return parts;
}

std::vector<double> PointInTimeVarianceParts::stderr_lux() const {
  std::vector<double> e(sky.size());
  for (std::size_t s = 0; s < e.size(); ++s) e[s] = std::sqrt(sky[s] + indirect_sun.at(s) + direct_sun.at(s));
  return e;
}

std::vector<double> point_in_time_stderr_lux(const SkyIlluminanceVariance& sky, const PointInTimeSunVariance* sun) {
  return point_in_time_variance_parts(sky, sun).stderr_lux();
}

}  // namespace dayphoton::study
