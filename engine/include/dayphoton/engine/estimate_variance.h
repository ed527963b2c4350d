// The Monte Carlo variance of the daylight coefficients: what every estimator path adds to
// DaylightCoefficients::direct_variance and photon_variance (docs/photon-map.md,
// "Uncertainty").
//
// Unit: the variance of a coefficient's LUMINANCE, y = RgbLuminanceWeights . C (RGB W/m^2 per
// unit radiance weighted by RADIANCE's luminance weights, without the 179 lm/W), per (sensor,
// source). Sources are traced and sampled independently (their own random streams), so the
// variance of any sky-weighted sum at a sensor is the sum over sources,
//
//   Var(sum_p L_p y_sp) = sum_p L_p^2 Var(y_sp),
//
// exact for a grey sky (equal RGB radiance per patch: the CIE overcast sky of the daylight
// factor); for a coloured sky L_p is its luminance-weighted radiance and the identity holds
// to the degree that a source's coefficient colour does not fluctuate.
//
// Two kinds of estimator, two estimates of their variance:
//   - sums over stored photons (a kernel disc, the local-linear fit, the contribution
//     estimate): the estimate is linear in the photons, sum_j w_j Phi_j, over photons that
//     are independent draws (each pass makes a fixed number of attempts). The sum of the
//     squared terms, sum_j (w_j y(Phi_j))^2, is the variance of a compound Poisson sum, and
//     for the next-neighbour radius (pi lambda d_{N+1}^2 ~ Gamma(N + 1)) it is unbiased for
//     the variance of the k-NN estimate too: E[N / G^2] = 1 / (N - 1) = Var(N / G) / E[1/G]^2
//     (density_estimate.h). The final gather sums the terms of a photon over all its rays
//     first and groups photons by path (final_gather.h), because one photon and one path
//     reach a sensor along many gather rays.
//   - stratified sampling with one sample per stratum (the direct component's shadow rays):
//     a stratum's variance cannot be estimated from its one sample, so neighbouring strata
//     stand in for each other (Cochran, "Sampling Techniques", 3rd ed., 1977, section 5A.12,
//     "collapsed strata"). Differences of two neighbours count a smooth integrand's trend
//     across them as variance (it overstated the office's direct variance several times
//     over: the cosine and the window's solid angle change smoothly from stratum to
//     stratum), so StratifiedVariance takes second differences of three, which cancel a
//     linear trend (Wolter, "Introduction to Variance Estimation", 2nd ed., 2007, section
//     8.2, successive-difference estimators). Edges (a window frame cutting a stratum) are
//     real variance and are counted; a curved trend is still counted, upward.
//   - the final gather's rays (final_gather.h): second differences of runs of three
//     neighbouring strata on the sky-weighted values, the photon noise they carry subtracted.
// Kernel bias (the blur of a disc of finite radius) is NOT variance and is not included:
// the stated uncertainty is the Monte Carlo standard error.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/core/vec3.h"

namespace dayphoton::engine {

/// Luminance weight of an RGB value (RADIANCE's weights, no efficacy): the scalar whose
/// variance the coefficients carry.
inline double luminance_of(const Vec3& rgb) { return dot(RgbLuminanceWeights, rgb); }

/// The variance of a sum over rows of strata, one sample each, from the samples themselves
/// (see the header comment). Within a row of k strata, each run of three neighbours gives
/// (z1 - 2 z2 + z3)^2 / 6, whose mean is the strata's mean variance wherever the integrand
/// is linear across the three (a linear trend cancels; first differences would count it as
/// variance); the k - 2 runs of a row, times k / (k - 2), estimate the row's sum. A row of
/// two gives (z1 - z2)^2, a row of one z^2 (no estimate is possible: an upper bound about a
/// mean of 0).
///
/// Samples shared by several sources: each sample is credited to one source (or none: -1,
/// value 0), as the port points of the direct component are. The per-source estimates are
/// then NOT independent (a point that falls in patch p misses patch q), and the variance of
/// a sum over sources is not the sum of per-source variances taken alone: at every patch
/// boundary those see a step, which the sum does not have. So the runs are taken on the
/// values whatever their source (the variance of the sum for equal weights), and each run's
/// variance is shared among the sources of its three samples in proportion to |c_i z_i|
/// (c = 1, -2, 1). For one source this is the plain estimate; for several, sum_p L_p^2 V_p
/// is exact where L is equal over neighbouring sources and close where it changes slowly
/// from patch to patch (a sky; the sun in the direct component is a source of its own).
/// Usage: add() every stratum's (source, value) row by row in order; the variances
/// accumulate into the caller's array, indexed by source.
class StratifiedVariance {
 public:
  StratifiedVariance(int row_length, double* variance_by_source) : m_row(row_length), m_out(variance_by_source) {}
  void add(int source, double value) {
    m_window[m_in_row % 3] = {source, source >= 0 ? value : 0.0};
    ++m_in_row;
    if (m_row >= 3 && m_in_row >= 3) {
      const Credit& a = m_window[(m_in_row - 3) % 3];
      const Credit& b = m_window[(m_in_row - 2) % 3];
      const Credit& c = m_window[(m_in_row - 1) % 3];
      const double d = a.value - 2.0 * b.value + c.value;
      share(double(m_row) / (double(m_row) - 2.0) / 6.0 * d * d, {a, b, c}, {1.0, 2.0, 1.0});
    }
    if (m_in_row < m_row) return;
    if (m_row == 1 && source >= 0) m_out[source] += value * value;
    if (m_row == 2) {
      const Credit& a = m_window[0];
      const Credit& b = m_window[1];
      share((a.value - b.value) * (a.value - b.value), {a, b, Credit{}}, {1.0, 1.0, 0.0});
    }
    m_in_row = 0;
  }

 private:
  struct Credit {
    int source = -1;
    double value = 0;
  };
  /// `variance` to the credited samples in proportion to |c_i z_i|.
  void share(double variance, const Credit (&run)[3], const double (&c)[3]) {
    double total = 0;
    for (int i = 0; i < 3; ++i)
      if (run[i].source >= 0) total += c[i] * std::fabs(run[i].value);
    if (!(total > 0) || !(variance > 0)) return;
    for (int i = 0; i < 3; ++i)
      if (run[i].source >= 0) m_out[run[i].source] += variance * c[i] * std::fabs(run[i].value) / total;
  }
  int m_row;
  double* m_out;
  int m_in_row = 0;
  Credit m_window[3];
};

}  // namespace dayphoton::engine
