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
// Rows a final gather estimates (a gathered grid; a receiver plane's sensors next to a cut)
// keep the basis sum sum_p C_sp . L_p and its variance: a gather ray's specular path to the
// sky reaches a bin without a photon, so it has no ratio. PhotonOnSky::basis_rows counts them.
#pragma once

#include <vector>

#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/daylight_coefficients.h"

namespace dayphoton::engine {

/// The sums above from the ratio-weighted estimate `weighted` of the same rows (its caustic,
/// global and photon_variance: estimate_photon_coefficients' `weighted`, which
/// photon_coefficients makes from the coefficients' own lookups when
/// CoefficientOptions::photon_sky_bin_radiance_rgb is set), the rows a final gather estimates
/// from `basis`, the coefficients of the same rows (all of them for gather photons, where
/// `weighted` may be null). `photons`: traced with TracingOptions::sky_ratios;
/// `bin_radiance_rgb[p]`: L_p, RGB W/(sr m^2), the radiances whose luminances the ratios
/// divide by. Throws std::invalid_argument on a size mismatch.
PhotonOnSky photon_part_on_sky_of(const GridPhotons& photons, const std::vector<SensorPoint>& sensors,
                                  const DaylightCoefficients& basis, const DaylightCoefficients* weighted,
                                  const std::vector<Vec3>& bin_radiance_rgb, SensorRange rows = {});

/// Row `row` of `on_sky` set to row `from_row` of `c`'s basis sum, sum_p C_p . L_p with its
/// variance (a row a final gather estimated after the photon part on the sky was taken: the
/// accuracy rounds' gathered rows next to a cut). Does not count it in basis_rows. Throws
/// std::out_of_range for a row either does not have.
void set_basis_row(PhotonOnSky& on_sky, std::size_t row, const DaylightCoefficients& c, std::size_t from_row,
                   const std::vector<Vec3>& bin_radiance_rgb);

}  // namespace dayphoton::engine
