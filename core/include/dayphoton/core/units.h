// Physical and photometric constants, with the convention each one encodes.
// See ../shared/facts/sky-and-metrics.md section 0 and docs/architecture.md.
#pragma once

#include "dayphoton/core/vec3.h"

namespace dayphoton {

constexpr double Pi = 3.14159265358979323846;
constexpr double DegPerRad = 180.0 / Pi;
constexpr double RadPerDeg = Pi / 180.0;

inline constexpr double deg_to_rad(double deg) { return deg * RadPerDeg; }
inline constexpr double rad_to_deg(double rad) { return rad * DegPerRad; }

/// RADIANCE's luminous efficacy of white light (lm/W) used to turn RGB radiometric values
/// into photometric ones; not a physical efficacy of daylight (that is Perez 1990's job).
constexpr double RadianceWhiteEfficacy_lm_per_W = 179.0;

/// RADIANCE's RGB -> luminance weights (CIE Y of its RGB primaries).
constexpr Vec3 RgbLuminanceWeights{0.265, 0.670, 0.065};

/// Photometric value (lux or cd/m^2) of an RGB radiometric triple (W/m^2 or W/(sr m^2)).
inline constexpr double rgb_to_photometric(const Vec3& rgb) {
  return RadianceWhiteEfficacy_lm_per_W * dot(RgbLuminanceWeights, rgb);
}

}  // namespace dayphoton
