// point_in_time_stderr_lux: see point_in_time_uncertainty.h.
#include "dayphoton/study/point_in_time_uncertainty.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "dayphoton/core/units.h"
#include "dayphoton/study/verdict_uncertainty.h"

namespace dayphoton::study {

std::vector<double> point_in_time_stderr_lux(const SkyIlluminanceVariance& sky, const PointInTimeSunVariance* sun) {
  std::vector<double> variance = sky.total();
  const std::size_t sensors = variance.size();
  if (sun) {
    if (sun->direct.size() != sensors || (sun->bins && sun->bins->size() != sensors * sun->bin_count))
      throw std::invalid_argument("point-in-time uncertainty: the sun's variances (" +
                                  std::to_string(sun->direct.size()) + " direct) do not match " +
                                  std::to_string(sensors) + " sensors");
    const double scale = std::pow(RadianceWhiteEfficacy_lm_per_W * sun->disc_radiance, 2);
    for (std::size_t s = 0; s < sensors; ++s) {
      double v = sun->direct[s];
      if (sun->bins) v += interpolated_sun_variance(sun->stencil, sun->bins->data() + s * sun->bin_count);
      variance[s] += scale * v;
    }
  }
  for (double& v : variance) v = std::sqrt(v);
  return variance;
}

}  // namespace dayphoton::study
