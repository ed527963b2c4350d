// A continuous sky: a radiance in every direction, as opposed to its means over the bins of a
// basis. The coefficients are per unit radiance of a uniform bin, so a sky-weighted sum over
// them treats each bin as uniformly bright at its mean; where a sky varies within a bin (the
// CIE overcast sky rises by 42 % across the lowest Tregenza band) and a sensor weights the
// bin unevenly, that sum is off. The estimators that know each sample's direction estimate
// the continuous sky's response directly: the shadow rays (direct_component.h, "Continuous
// skies") and the photons through their sky ratios (sky_ratios.h).
#pragma once

#include <functional>
#include <string>

#include "dayphoton/core/vec3.h"

namespace dayphoton::engine {

struct ContinuousSky {
  /// What the sky is, with every parameter its radiance depends on: cache keys hash it.
  std::string key;
  /// Direction toward the sky (unit, world axes, +Z up) -> RGB radiance W/(sr m^2), the
  /// ground's below the horizon (the basis's ground bin 0 is the lower hemisphere).
  std::function<Vec3(const Vec3&)> radiance_rgb;
};

}  // namespace dayphoton::engine
