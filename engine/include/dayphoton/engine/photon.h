// Photon: one stored photon record of a contribution photon map (seeds/001 section 4.2,
// DESIGN.md section 5).
//
// A record keeps the position, the RGB flux, the emitting source (the sky or sun bin whose
// photon this is: contribution maps bin flux by emitter at lookup), the path class and the
// side of the surface it arrived on. 32 bytes: float position and flux (the thesis found
// RGBE flux biased by about -0.5 %, digest section 2.4, so flux stays float), the normal
// quantised to signed bytes (used only to reject photons from the other side of a thin
// surface, for which 1/127 is ample).
//
// Difference from RADIANCE's contribution photons: RADIANCE emits from one continuous sky
// and stores each photon's primary ray (direction and entry point) so that it can bin them
// afterwards. dayphoton emits every bin as its own source, so the bin is known at emission
// and stored directly; no primary-ray table is needed.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

#include "dayphoton/core/vec3.h"

namespace dayphoton::engine {

/// Path class of a stored photon (seeds/000 section 3.1.1.3, digest section 2.1.5).
enum class PathClass : std::uint8_t {
  Direct = 0,   ///< first hit after entering through a port (diagnostic only; the direct
                ///< component comes from shadow rays)
  Caustic = 1,  ///< only specular (delta or glossy) events since the port
  Global = 2,   ///< at least one diffuse event since the port
};

/// Bit mask of path classes, for lookup filters.
inline constexpr std::uint8_t path_class_bit(PathClass c) {
  return static_cast<std::uint8_t>(1u << static_cast<unsigned>(c));
}
inline constexpr std::uint8_t IndirectPathClasses =
    path_class_bit(PathClass::Caustic) | path_class_bit(PathClass::Global);

struct Photon {
  std::array<float, 3> position{};  ///< metres
  std::array<float, 3> flux{};      ///< RGB, watts per unit source radiance (W/(W/(sr m2)))
  std::uint32_t source = 0;         ///< emitting source (index into the SourceSet)
  std::array<std::int8_t, 3> normal{};  ///< side it arrived on, x 127
  PathClass path_class = PathClass::Global;

  Vec3 position_m() const { return {position[0], position[1], position[2]}; }
  Vec3 flux_rgb() const { return {flux[0], flux[1], flux[2]}; }
  Vec3 normal_vector() const {
    return Vec3{double(normal[0]), double(normal[1]), double(normal[2])} * (1.0 / 127.0);
  }
  void set_normal(const Vec3& n) {
    normal = {quantise(n.x * 127.0), quantise(n.y * 127.0), quantise(n.z * 127.0)};
  }

 private:
  /// std::lround(v) (nearest integer, halves away from zero) as a signed byte, for |v| <= 127
  /// plus rounding, inline: one stored photon took three calls into the maths library. The
  /// integer part is v truncated and the fraction v minus it, both exact in double, so the
  /// result is lround's for every such v; anything else (never a unit normal) is lround's own.
  static std::int8_t quantise(double v) {
    if (!(std::fabs(v) < 128.0)) return static_cast<std::int8_t>(std::lround(v));
    int i = static_cast<int>(v);
    const double fraction = v - double(i);
    if (fraction >= 0.5) ++i;
    if (fraction <= -0.5) --i;
    return static_cast<std::int8_t>(i);
  }
};
static_assert(sizeof(Photon) == 32, "photon record layout is documented as 32 bytes");

}  // namespace dayphoton::engine
