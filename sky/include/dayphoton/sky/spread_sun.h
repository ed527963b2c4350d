// Where RADIANCE's gendaymtx puts the sun of a sky matrix (its AddDirect; facts restated in
// sky_matrix.h's sources, section 4.4): into the NSUNPATCH = 4 sky patches whose centres are
// nearest to the sun (largest cosine; the ground bin 0 never), each with weight
// w_k = 1 / (1.002 - cos angle_k) normalised to sum 1, as radiance
// w_k E_n / (179 Omega_k), so that radiance x patch solid angle adds up to the direct normal
// illuminance E_n / 179. `gendaymtx -d` writes that sun alone (sky and ground zero). One
// place for the rule: build_sky_matrix spreads its suns with it, and the RADIANCE sun matrix
// (study/radiance_sun_matrix.h) is built for it.
#pragma once

#include <array>

#include "dayphoton/core/vec3.h"
#include "dayphoton/sky/patch_basis.h"

namespace dayphoton::sky {

/// The 4 patches of a spread sun, nearest first, and their weights (sum 1).
struct SpreadSunPatches {
  static constexpr int Count = 4;
  std::array<int, Count> bin{};
  std::array<double, Count> weight{};
};

/// The patches and weights gendaymtx gives the sun along `sun` (unit vector) in `basis`;
/// ties go to the lower bin, as gendaymtx's scan in bin order.
SpreadSunPatches spread_sun_patches(const PatchBasis& basis, const Vec3& sun);

/// Solid angle of the sun disc of half angle SunHalfAngle_rad, 2 pi (1 - cos), sr: what a
/// SunRecord's disc radiance spreads its direct normal illuminance over (sun_record).
double sun_disc_solid_angle_sr();

}  // namespace dayphoton::sky
