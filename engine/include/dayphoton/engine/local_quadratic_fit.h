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

}  // namespace dayphoton::engine
