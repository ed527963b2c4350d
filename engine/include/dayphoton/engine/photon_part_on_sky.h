// The photon part of the coefficients under a continuous sky (continuous_sky.h): per sensor,
//
//   E_s = sum_p C'_sp . L_p,
//
// C' the photon coefficients estimated with every photon's flux times its sky ratio
// r = L(w) / L_p (sky_ratios.h; PhotonFlux::TimesSkyRatio: photon_coefficients sums it over the
// coefficients' own lookups when CoefficientOptions::photon_sky_bin_radiance_rgb is set), L_p
// the bin radiances the ratios were taken against. The same discs, kernels, fits and clamps as
// the coefficients, so E_s is that estimator's response to the continuous sky itself and its
// variance is sum_p lum(L_p)^2 Var(y'_sp) (the sources are independent, estimate_variance.h).
//
// Rows a final gather estimates (a gathered grid: a point set, a Honeybee grid, wall
// sensors; a receiver plane's sensors next to a cut) take the gather's own estimate under the
// same sky from the same rays (final_gather.h, "The continuous sky"): its lookups sum each
// photon's flux times its ratio, and a specular path that leaves toward a bin carries the sky's
// exact ratio in its direction, so E_s is again the response to the continuous sky, with the
// variance of that estimator. Only a gather without the ratios (CoefficientOptions::
// photon_sky_ratios not given) leaves a row on the basis sum sum_p C_sp . L_p and its
// variance; PhotonOnSky::basis_rows counts those rows (the study gives the ratios, so none).
#pragma once

#include <vector>

#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/daylight_coefficients.h"

namespace dayphoton::engine {

/// The sums above from the ratio-weighted estimate `weighted` of the same rows (its caustic,
/// global and photon_variance: estimate_photon_coefficients' `weighted`, which
/// photon_coefficients makes from the coefficients' own lookups when
/// CoefficientOptions::photon_sky_bin_radiance_rgb is set). The rows a final gather estimates
/// (all of them for gather photons, where `weighted` may be null; else a plane's sensors next
/// to a cut, sensors_near_cuts' order) from `gathered`, the gather of those rows in that
/// order, where it has its estimate on the sky (GatheredCoefficients::on_sky); without it from
/// `basis`, the coefficients of the same rows, counted in basis_rows. `photons`: traced with
/// TracingOptions::sky_ratios; `bin_radiance_rgb[p]`: L_p, RGB W/(sr m^2), the radiances whose
/// luminances the ratios divide by. Throws std::invalid_argument on a size mismatch.
PhotonOnSky photon_part_on_sky_of(const GridPhotons& photons, const std::vector<SensorPoint>& sensors,
                                  const DaylightCoefficients& basis, const DaylightCoefficients* weighted,
                                  const std::vector<Vec3>& bin_radiance_rgb, SensorRange rows = {},
                                  const GatheredCoefficients* gathered = nullptr);

/// Row `row` of `on_sky` set to row `from_row` of `c`'s basis sum, sum_p C_p . L_p with its
/// variance (a row a final gather estimated without the ratios after the photon part on the
/// sky was taken). Does not count it in basis_rows. Throws std::out_of_range for a row either
/// does not have.
void set_basis_row(PhotonOnSky& on_sky, std::size_t row, const DaylightCoefficients& c, std::size_t from_row,
                   const std::vector<Vec3>& bin_radiance_rgb);

}  // namespace dayphoton::engine
