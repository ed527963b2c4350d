// The local-quadratic density estimate at the centre of a (wall-clipped) kernel disc.
//
// The photons crossing a receiver plane are a Poisson process whose intensity is the
// irradiance E. Fitting E(q) = beta . phi((q - p) / r), phi = (1, u, v, u^2, uv, v^2), by
// moments over the clipped disc R (sum_j Phi_j phi_j = int_R phi phi^T dA beta) gives
// E(p) = beta_1 = sum_j w_j Phi_j with w_j = c . phi_j / r^2, c = M^-1 e_1 and M the moment
// matrix of R in the disc's scaled coordinates (ReceiverPlane::clipped_disc_moments4). It is
// the local polynomial regression of Hastie and Loader ("Local regression: automatic kernel
// carpentry", Statistical Science 8(2), 1993, section 3) with the uniform weight, applied to a
// density: exact for every quadratic field, whatever the disc's shape, so the curvature bias
// of the local-linear fit (Loader, "Local Regression and Likelihood", 1999, section 5.3)
// goes with it. Its cost is variance: `c` is the equivalent kernel, and for photons of flux
// y_j the estimate's variance is sum_j w_j^2 y_j^2 (a compound Poisson sum, as every
// estimate linear in the photons; estimate_variance.h). On a whole disc that is 4 times the
// local-linear fit's (w = (4 - 6 s^2) / (pi r^2)); on a disc cut by walls 1.5-4 times.
#pragma once

#include "dayphoton/engine/receiver_plane.h"

namespace dayphoton::engine {

/// c = M^-1 e_1 of the header; `valid` false when M is singular to working precision (a
/// region too thin to fit a quadratic: the caller falls back to a lower degree).
struct LocalQuadraticKernel {
  double c[6] = {0, 0, 0, 0, 0, 0};
  /// The local-linear fit's kernel over the same region, phi = (1, u, v) (the leading 3 x 3
  /// block of the moment matrix).
  double linear[3] = {0, 0, 0};
  bool valid = false;
  /// c . phi(u, v): the weight of a photon at scaled offset (u, v) times r^2.
  double weight(double u, double v) const {
    return c[0] + c[1] * u + c[2] * v + c[3] * u * u + c[4] * u * v + c[5] * v * v;
  }
  double linear_weight(double u, double v) const { return linear[0] + linear[1] * u + linear[2] * v; }
};

/// The equivalent kernel of the local-quadratic fit over the region whose scaled moments are
/// `m` (Cholesky decomposition of the 6 x 6 moment matrix).
LocalQuadraticKernel local_quadratic_kernel(const ScaledMoments4& m);

/// The curvature correction of a local-linear fit over a disc the walls cut, from a pilot disc
/// about the same centre clipped by the same walls (docs/photon-map.md, "Curvature at cut
/// discs"). For a field E = a + g . d + sum_k beta_k phi_k(d / R) (k over u^2, uv, v^2), the
/// local-linear fit over the disc's region, of kernel l . (1, u, v) / r^2 with u = d / r
/// (LocalQuadraticKernel::linear), reads a + (r / R)^2 sum_k beta_k L_k, L_ab = int_A l .
/// (1, u, v) u^a v^b du dv over the disc's scaled region: the disc's moments up to order 3
/// (Loader, "Local Regression and Likelihood", 1999, section 5.3, the bias of a local fit of
/// degree 1 from the moments of its region). The quadratic fitted by moments over the pilot's
/// clipped region (as local_quadratic_kernel, scaled by R) gives beta = M_R^-1 sum_j phi_j
/// Phi_j / R^2, so the bias estimate is sum_j w_j Phi_j with w_j = (r^2 / R^4) gv . phi_j and
/// gv = M_R^-1 (0, 0, 0, L_20, L_11, L_02). The corrected estimate is exact for every quadratic
/// field. On a whole disc gv . phi = (6 / pi) (rho^2 - 1/2), the pilot correction of whole discs.
struct CutCurvaturePilot {
  double linear[3] = {0, 0, 0};  ///< the disc's local-linear kernel l
  double g[6] = {0, 0, 0, 0, 0, 0};
  double scale = 0;  ///< r^2 / R^4
  bool valid = false;
  /// The weight in the bias of a photon at (u, v) = d / R in the pilot disc, per m^2.
  double bias_weight(double u, double v) const {
    return scale * (g[0] + g[1] * u + g[2] * v + g[3] * u * u + g[4] * u * v + g[5] * v * v);
  }
};

/// `disc` and `pilot`: the scaled moments of the disc's region (radius_m) and the pilot's
/// (pilot_m); `valid` false when either region is too thin for its fit.
CutCurvaturePilot cut_curvature_pilot(const ScaledMoments4& disc, const ScaledMoments4& pilot, double radius_m,
                                      double pilot_m);

}  // namespace dayphoton::engine
