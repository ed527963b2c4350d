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
// The source shares its 32 bits with the photon's sky ratio: for a sky-bin photon, the
// radiance of one continuous sky (the daylight factor's) in the direction it was emitted
// toward, over that sky's mean radiance in the bin (TracingOptions::sky_ratios, sky_ratios.h).
// A bin's coefficient treats the bin as uniformly bright; the same estimate with each photon's
// flux times its ratio is the bin's response to the continuous sky within it
// (photon_part_on_sky.h). 12 bits in steps of 1/2048 (0.05 %, rounded to nearest, so unbiased
// over many photons), up to 4095/2048; sources get the other 20 bits (MaxPhotonSources, more
// than Reinhart MF:64's 589,826 bins, ground included).
//
// The path class's byte also holds the photon's sky quadrant (2 bits): the quadrant of its
// emitting sky bin that its emission direction lies in (sky::PatchBasis::quadrant: halves in
// sine of altitude and in azimuth; 0 for the ground bin and sun photons). The estimate with each
// flux times the indicator of one quadrant is the bin's response to that quadrant alone, the
// photon part's sub-patch share (PhotonFlux::InSkyQuadrant0..2; the annual product's sub-patch
// correction, docs/photon-map.md "The annual photon part on sub-patches").
//
// Difference from RADIANCE's contribution photons: RADIANCE emits from one continuous sky
// and stores each photon's primary ray (direction and entry point) so that it can bin them
// afterwards. dayphoton emits every bin as its own source, so the bin is known at emission
// and stored directly; no primary-ray table is needed.
#pragma once

#include <array>
#include <cstddef>
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

/// Sources a photon record can name (20 bits).
inline constexpr std::uint32_t MaxPhotonSources = 1u << 20;
/// The largest absolute coordinate of a scene's geometry in its description's coordinates,
/// metres: the positions are stored as floats in those coordinates, rounded by up to 2^-24 of
/// a coordinate (6 mm at 1e5 m, 0.25 m at a UTM northing of 4.2e6 m). A 6 x 8 m room with
/// walls of reflectance 0.5 read its daylight factor to within its noise at 1.5e5 m, 1-2 %
/// high at 3e5 m and 2-3 times too high at 4.2e6 m. A project's description is held around a
/// local origin (SceneDescription::world_origin_m, project/local_origin.h), so this limits a
/// model's extent (about 200 km across), not where it lies; Scene::build refuses geometry
/// beyond it.
inline constexpr double PhotonCoordinateLimit_m = 1e5;
/// The sky ratio's fixed point: this value is a ratio of 1 (12 bits, steps of 1/2048).
inline constexpr std::uint32_t SkyRatioOne = 2048;
inline constexpr std::uint32_t SkyRatioMaxCode = 4095;

struct Photon {
  Photon() : source(0), sky_ratio_code(SkyRatioOne), path_class(PathClass::Global), sky_quadrant(0), unused_bits(0) {}

  std::array<float, 3> position{};  ///< metres
  std::array<float, 3> flux{};      ///< RGB, watts per unit source radiance (W/(W/(sr m2)))
  /// Emitting source (index into the SourceSet), < MaxPhotonSources.
  std::uint32_t source : 20;
  /// The sky ratio (header comment) x SkyRatioOne; SkyRatioOne for sun photons and when no
  /// continuous sky was given.
  std::uint32_t sky_ratio_code : 12;
  std::array<std::int8_t, 3> normal{};  ///< side it arrived on, x 127
  PathClass path_class : 2;
  /// The quadrant of its sky bin it was emitted into (header comment), 0-3.
  std::uint8_t sky_quadrant : 2;
  /// Always 0: named so that a record's every byte is defined (digests and comparisons of
  /// whole records).
  std::uint8_t unused_bits : 4;

  double sky_ratio() const { return double(sky_ratio_code) / double(SkyRatioOne); }
  /// Whether `ratio` has a code: non-negative and rounding to at most SkyRatioMaxCode (a NaN
  /// has none).
  static bool sky_ratio_fits(double ratio) {
    return ratio >= 0 && ratio * double(SkyRatioOne) < double(SkyRatioMaxCode) + 0.5;
  }
  /// The code of a ratio that fits, rounded to nearest.
  static std::uint32_t sky_ratio_code_of(double ratio) {
    return static_cast<std::uint32_t>(std::lround(ratio * double(SkyRatioOne)));
  }
  /// The source and sky ratio code as one 32-bit word (the artifact codec's layout).
  std::uint32_t source_word() const { return std::uint32_t(source) | (std::uint32_t(sky_ratio_code) << 20); }
  void set_source_word(std::uint32_t w) {
    source = w & (MaxPhotonSources - 1);
    sky_ratio_code = w >> 20;
  }

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

 public:
  /// The path class and sky quadrant as one byte (the artifact codec's layout): class + 4 x
  /// quadrant.
  std::uint8_t class_byte() const {
    return static_cast<std::uint8_t>(static_cast<unsigned>(path_class) | (unsigned(sky_quadrant) << 2));
  }
};
/// Which flux an estimate sums: the photons' own, each times its sky ratio (the response
/// to the continuous sky the ratios come from, sky_ratios.h), or each times the indicator of
/// its sky quadrant being 0, 1 or 2 (the response to that quadrant of its bin alone).
enum class PhotonFlux : std::uint8_t { AsTraced, TimesSkyRatio, InSkyQuadrant0, InSkyQuadrant1, InSkyQuadrant2 };
inline PhotonFlux in_sky_quadrant(std::size_t q) {
  return static_cast<PhotonFlux>(static_cast<unsigned>(PhotonFlux::InSkyQuadrant0) + q);
}
inline Vec3 flux_of(const Photon& p, PhotonFlux f) {
  switch (f) {
    case PhotonFlux::AsTraced:
      return p.flux_rgb();
    case PhotonFlux::TimesSkyRatio:
      return p.flux_rgb() * p.sky_ratio();
    default:
      return p.sky_quadrant == static_cast<unsigned>(f) - static_cast<unsigned>(PhotonFlux::InSkyQuadrant0)
                 ? p.flux_rgb()
                 : Vec3{0, 0, 0};
  }
}

static_assert(sizeof(Photon) == 32, "photon record layout is documented as 32 bytes");

}  // namespace dayphoton::engine
