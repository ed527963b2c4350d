// Bench support: the reference radiances L_ref,p a sky's ratios are taken against when the
// sky photons are traced again under one continuous sky (engine/sky_ratios.h), so that the
// estimate with each flux times its ratio, summed with L_ref,p, is the photon part under that
// sky itself (perez_photon_part_bench, point_in_time_photon_part_bench).
//
// L_ref,p is the bin's centre value, raised to RatioHeadroom x its largest luminance where the
// sky varies more than 1.8-fold within the bin (the circumsolar bins of clear skies), so that
// every ratio fits the record's 12-bit code (at most 4095 / 2048): any L_ref,p gives the exact
// sum.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/continuous_sky.h"
#include "dayphoton/engine/estimate_variance.h"
#include "dayphoton/sky/patch_basis.h"

namespace dayphoton::bench {

/// The ratio's largest code is 4095 / 2048: a bin whose sky varies more than this far is
/// referred to this fraction of its largest luminance.
constexpr double RatioHeadroom = 0.55;
/// Directions per axis of a bin searched for its largest luminance (plus the sun's own).
constexpr int MaximumSearchPerAxis = 33;

/// The bins' reference radiances L_ref,p (RGB) for `sky` (the ground bin: the sky's radiance
/// straight down), `sun` the sun's direction if the sky has one.
inline std::vector<Vec3> reference_radiances(const engine::ContinuousSky& sky, const sky::PatchBasis& basis,
                                             const std::optional<Vec3>& sun) {
  std::vector<Vec3> out(std::size_t(basis.bin_count()));
  out[0] = sky.radiance_rgb(Vec3{0, 0, -1});
  for (int p = 1; p < basis.bin_count(); ++p) {
    const Vec3 centre = sky.radiance_rgb(basis.centre(p));
    double largest = sun && basis.find_bin(*sun) == p ? engine::luminance_of(sky.radiance_rgb(*sun)) : 0.0;
    const int n = MaximumSearchPerAxis;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double u1 = std::min(double(i) / (n - 1), 1 - 1e-9), u2 = std::min(double(j) / (n - 1), 1 - 1e-9);
        largest = std::max(largest, engine::luminance_of(sky.radiance_rgb(basis.sample_direction(p, u1, u2))));
      }
    const double l = engine::luminance_of(centre);
    out[std::size_t(p)] = l >= RatioHeadroom * largest ? centre : centre * (RatioHeadroom * largest / l);
  }
  return out;
}

}  // namespace dayphoton::bench
