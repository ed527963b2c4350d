// Sky ratios of sky-bin photons: see sky_ratios.h.
#include "dayphoton/engine/sky_ratios.h"

#include <cmath>
#include <stdexcept>

#include "dayphoton/engine/engine_error.h"
#include "dayphoton/engine/estimate_variance.h"
#include "dayphoton/engine/photon.h"

namespace dayphoton::engine {

SkyRatios::SkyRatios(ContinuousSky sky, std::vector<double> bin_luminance)
    : m_sky(std::move(sky)), m_bin_luminance(std::move(bin_luminance)) {
  if (!m_sky.radiance_rgb) throw std::invalid_argument("sky ratios: the continuous sky has no radiance");
  for (std::size_t p = 0; p < m_bin_luminance.size(); ++p)
    if (!(m_bin_luminance[p] >= 0) || !std::isfinite(m_bin_luminance[p]))
      throw std::invalid_argument("sky ratios: bin " + std::to_string(p) + " has luminance " +
                                  std::to_string(m_bin_luminance[p]));
}

double SkyRatios::ratio(std::size_t bin, const Vec3& toward_sky) const {
  if (bin >= m_bin_luminance.size())
    throw std::out_of_range("sky ratios: bin " + std::to_string(bin) + " of " + std::to_string(m_bin_luminance.size()));
  const double mean = m_bin_luminance[bin];
  if (!(mean > 0)) return 1.0;
  const double r = luminance_of(m_sky.radiance_rgb(toward_sky)) / mean;
  if (!Photon::sky_ratio_fits(r))
    throw EngineError("sky ratios: the sky '" + m_sky.key + "' is " + std::to_string(r) + " times its mean in bin " +
                      std::to_string(bin) + " at (" + std::to_string(toward_sky.x) + ", " +
                      std::to_string(toward_sky.y) + ", " + std::to_string(toward_sky.z) +
                      "), beyond the photon record's sky ratio (at most " +
                      std::to_string(double(SkyRatioMaxCode) / double(SkyRatioOne)) + ")");
  return r;
}

}  // namespace dayphoton::engine
