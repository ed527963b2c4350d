// Local-quadratic fit: see local_quadratic_fit.h.
#include "dayphoton/engine/local_quadratic_fit.h"

#include <cmath>

namespace dayphoton::engine {

namespace {

/// The 6 x 6 moment matrix of phi = (1, u, v, u^2, uv, v^2) over the region of `m`, factored
/// as L L^T (lower triangle in place). False when a pivot falls below 1e-10 of its diagonal
/// entry: the region is (numerically) too thin for a quadratic in some direction.
bool cholesky_of_moments(const ScaledMoments4& m, double a[6][6]) {
  static const int ea[6] = {0, 1, 0, 2, 1, 0}, eb[6] = {0, 0, 1, 0, 1, 2};  // phi's exponents
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) a[i][j] = m.at(ea[i] + ea[j], eb[i] + eb[j]);
  for (int j = 0; j < 6; ++j) {
    double d = a[j][j];
    for (int p = 0; p < j; ++p) d -= a[j][p] * a[j][p];
    if (!(d > 1e-10 * a[j][j])) return false;
    a[j][j] = std::sqrt(d);
    for (int i = j + 1; i < 6; ++i) {
      double s = a[i][j];
      for (int p = 0; p < j; ++p) s -= a[i][p] * a[j][p];
      a[i][j] = s / a[j][j];
    }
  }
  return true;
}

/// Forward substitution L y = rhs.
void forward(const double a[6][6], const double rhs[6], double y[6]) {
  for (int i = 0; i < 6; ++i) {
    double s = rhs[i];
    for (int p = 0; p < i; ++p) s -= a[i][p] * y[p];
    y[i] = s / a[i][i];
  }
}

/// Back substitution L^T x = y over the first n unknowns: the leading n x n block of L is the
/// Cholesky factor of the leading block of the moment matrix.
void back(const double a[6][6], const double y[6], int n, double* out) {
  for (int i = n - 1; i >= 0; --i) {
    double s = y[i];
    for (int p = i + 1; p < n; ++p) s -= a[p][i] * out[p];
    out[i] = s / a[i][i];
  }
}

}  // namespace

LocalQuadraticKernel local_quadratic_kernel(const ScaledMoments4& m) {
  LocalQuadraticKernel k;
  double a[6][6];
  if (!cholesky_of_moments(m, a)) return k;
  // n = 3 gives the local-linear fit's kernel.
  const double e1[6] = {1, 0, 0, 0, 0, 0};
  double y[6];
  forward(a, e1, y);
  back(a, y, 6, k.c);
  back(a, y, 3, k.linear);
  k.valid = true;
  return k;
}

CutCurvaturePilot cut_curvature_pilot(const ScaledMoments4& disc, const ScaledMoments4& pilot, double radius_m,
                                      double pilot_m) {
  CutCurvaturePilot out;
  const LocalQuadraticKernel kernel = local_quadratic_kernel(disc);
  double a[6][6];
  if (!kernel.valid || !cholesky_of_moments(pilot, a)) return out;
  for (int i = 0; i < 3; ++i) out.linear[i] = kernel.linear[i];
  // L_ab: the local-linear fit's reading of u^a v^b (a + b = 2) at the centre, its kernel
  // integrated against the monomial over the disc's region.
  const auto reads = [&](int i, int j) {
    return kernel.linear[0] * disc.at(i, j) + kernel.linear[1] * disc.at(i + 1, j) +
           kernel.linear[2] * disc.at(i, j + 1);
  };
  const double rhs[6] = {0, 0, 0, reads(2, 0), reads(1, 1), reads(0, 2)};
  double y[6];
  forward(a, rhs, y);
  back(a, y, 6, out.g);
  out.scale = radius_m * radius_m / (pilot_m * pilot_m * pilot_m * pilot_m);
  out.valid = true;
  return out;
}

}  // namespace dayphoton::engine
