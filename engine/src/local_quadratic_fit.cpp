// Local-quadratic fit: see local_quadratic_fit.h.
#include "dayphoton/engine/local_quadratic_fit.h"

#include <cmath>

namespace dayphoton::engine {

LocalQuadraticKernel local_quadratic_kernel(const ScaledMoments4& m) {
  static const int ea[6] = {0, 1, 0, 2, 1, 0}, eb[6] = {0, 0, 1, 0, 1, 2};  // phi's exponents
  double a[6][6];
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) a[i][j] = m.at(ea[i] + ea[j], eb[i] + eb[j]);
  LocalQuadraticKernel k;
  // Cholesky, a = L L^T (lower triangle in place). A pivot below 1e-10 of its diagonal entry
  // means the region is (numerically) too thin for a quadratic in some direction.
  for (int j = 0; j < 6; ++j) {
    double d = a[j][j];
    for (int p = 0; p < j; ++p) d -= a[j][p] * a[j][p];
    if (!(d > 1e-10 * a[j][j])) return k;
    a[j][j] = std::sqrt(d);
    for (int i = j + 1; i < 6; ++i) {
      double s = a[i][j];
      for (int p = 0; p < j; ++p) s -= a[i][p] * a[j][p];
      a[i][j] = s / a[j][j];
    }
  }
  // Forward substitution L y = e_1, then L^T c = y over the first n unknowns: the leading
  // n x n block of L is the Cholesky factor of the leading block of the moment matrix, so
  // n = 3 gives the local-linear fit's kernel.
  double y[6];
  for (int i = 0; i < 6; ++i) {
    double s = i == 0 ? 1.0 : 0.0;
    for (int p = 0; p < i; ++p) s -= a[i][p] * y[p];
    y[i] = s / a[i][i];
  }
  auto back = [&](int n, double* out) {
    for (int i = n - 1; i >= 0; --i) {
      double s = y[i];
      for (int p = i + 1; p < n; ++p) s -= a[p][i] * out[p];
      out[i] = s / a[i][i];
    }
  };
  back(6, k.c);
  back(3, k.linear);
  k.valid = true;
  return k;
}

}  // namespace dayphoton::engine
