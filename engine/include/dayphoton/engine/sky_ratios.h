// SkyRatios: each sky-bin photon's sky ratio (photon.h), the luminance of one continuous sky
// in the direction the photon was emitted toward over that sky's luminance in the photon's
// bin, L(w) / L_p.
//
// Why it is exact. A bin's photon coefficient C_p estimates the response to the bin at unit
// radiance, each photon emitted uniformly over the bin's solid angle (distant_source.h). The
// same estimator with every photon's flux times r = L(w) / L_p estimates the response to the
// bin at radiance L(w) / L_p, so C'_p L_p is the response to the continuous sky within bin p,
// whatever L_p is (it cancels), and sum_p C'_p L_p is the photon part under the continuous sky
// itself, without the basis's patch-uniform radiance. With L_p the sky's mean over the bin
// (the sky vector the daylight factor sums the coefficients with) the ratios are near 1
// (0.83-1.18 for the CIE overcast sky on the Tregenza basis, closer to 1 on finer ones), which
// keeps the 12-bit code fine and the variance about the basis estimate's.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/continuous_sky.h"

namespace dayphoton::engine {

class SkyRatios {
 public:
  /// `bin_luminance[p]`: the sky's luminance-weighted radiance in bin p of the basis (ground
  /// bin 0 included), the L_p the ratios divide by. Throws std::invalid_argument for a sky
  /// without a radiance or a negative or non-finite bin luminance.
  SkyRatios(ContinuousSky sky, std::vector<double> bin_luminance);

  /// The ratio for a photon of bin `bin` emitted toward `toward_sky` (unit): 1 for a bin of
  /// luminance 0 (its coefficient is multiplied by 0). Throws std::out_of_range for a bin the
  /// basis does not have, and EngineError where the ratio has no 12-bit code (a sky more than
  /// twice as bright somewhere in a bin as its mean there: not a daylight-factor sky).
  double ratio(std::size_t bin, const Vec3& toward_sky) const;

  std::size_t bins() const { return m_bin_luminance.size(); }
  /// The sky's key: photon cache keys hash it, so it must name everything the ratios depend
  /// on besides the basis (the sky's shape, how the bin means were taken); the ratios are
  /// free of the sky's scale.
  const std::string& key() const { return m_sky.key; }

 private:
  ContinuousSky m_sky;
  std::vector<double> m_bin_luminance;
};

}  // namespace dayphoton::engine
