// Kernel normalisation in 2-D (digest T-6): integral_0^r K(s) 2 pi s ds = 1 to 1e-9 for all
// four kernels of seeds/000 eqs. 3.19-3.22, several radii and cone slopes, by composite
// Gauss-Legendre quadrature (5 points per panel is exact for polynomials of degree 9; the
// integrands are polynomials of degree <= 5, so the only error is rounding). Also: zero
// outside the disc, the documented shapes at the centre and the rim, and invalid
// arguments.
#include "dayphoton/engine/kernel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "dayphoton/core/units.h"

namespace dayphoton::engine {
namespace {

constexpr KernelType AllKernels[] = {KernelType::Uniform, KernelType::Cone,
                                     KernelType::Epanechnikov, KernelType::Silverman};

/// integral_0^r K(s) 2 pi s ds, composite 5-point Gauss-Legendre on `panels` panels.
double disc_integral(KernelType type, double r_m, double cone_slope, int panels) {
  static const double node[5] = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                 0.5384693101056831, 0.9061798459386640};
  static const double weight[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                   0.4786286704993665, 0.2369268850561891};
  const double h = r_m / panels;
  double sum = 0;
  for (int p = 0; p < panels; ++p) {
    const double centre = (p + 0.5) * h;
    for (int i = 0; i < 5; ++i) {
      const double s = centre + 0.5 * h * node[i];
      sum += 0.5 * h * weight[i] * kernel_weight(type, s, r_m, cone_slope) * 2.0 * Pi * s;
    }
  }
  return sum;
}

TEST(Kernel, NormalisedOverTheDisc) {
  for (KernelType type : AllKernels)
    for (double r_m : {1e-3, 0.37, 1.0, 25.0})
      for (double slope : {1.0, 1.1, 2.5}) {
        if (type != KernelType::Cone && slope != 1.1) continue;
        EXPECT_NEAR(disc_integral(type, r_m, slope, 64), 1.0, 1e-9)
            << kernel_name(type) << " r = " << r_m << " k = " << slope;
      }
}

TEST(Kernel, ZeroOutsideTheDisc) {
  for (KernelType type : AllKernels) {
    EXPECT_EQ(kernel_weight(type, 1.0000001, 1.0), 0.0) << kernel_name(type);
    EXPECT_EQ(kernel_weight(type, 7.0, 2.0), 0.0) << kernel_name(type);
    EXPECT_GT(kernel_weight(type, 0.0, 1.0), 0.0) << kernel_name(type);
  }
}

TEST(Kernel, ShapesAtCentreAndRim) {
  const double r = 0.5, disc = Pi * r * r;
  EXPECT_DOUBLE_EQ(kernel_weight(KernelType::Uniform, 0.3, r), 1.0 / disc);
  EXPECT_DOUBLE_EQ(kernel_weight(KernelType::Epanechnikov, 0.0, r), 2.0 / disc);
  EXPECT_DOUBLE_EQ(kernel_weight(KernelType::Silverman, 0.0, r), 3.0 / disc);
  EXPECT_NEAR(kernel_weight(KernelType::Epanechnikov, r, r), 0.0, 1e-15);
  EXPECT_NEAR(kernel_weight(KernelType::Silverman, r, r), 0.0, 1e-15);
  // Cone with k = 1 falls to zero at the rim; with k > 1 it stops at 1 - 1/k of its peak.
  EXPECT_NEAR(kernel_weight(KernelType::Cone, r, r, 1.0), 0.0, 1e-15);
  EXPECT_NEAR(kernel_weight(KernelType::Cone, r, r, 1.1) / kernel_weight(KernelType::Cone, 0, r, 1.1),
              1.0 - 1.0 / 1.1, 1e-12);
  // Weights decrease outward for every kernel but the uniform one.
  for (KernelType type : {KernelType::Cone, KernelType::Epanechnikov, KernelType::Silverman})
    EXPECT_GT(kernel_weight(type, 0.1, r), kernel_weight(type, 0.2, r)) << kernel_name(type);
}

TEST(Kernel, InvalidArgumentsThrow) {
  EXPECT_THROW(kernel_weight(KernelType::Uniform, 0.0, 0.0), std::invalid_argument);
  EXPECT_THROW(kernel_weight(KernelType::Uniform, 0.0, -1.0), std::invalid_argument);
  EXPECT_THROW(kernel_weight(KernelType::Silverman, 0.0, std::nan("")), std::invalid_argument);
  EXPECT_THROW(kernel_weight(KernelType::Silverman, 0.0, INFINITY), std::invalid_argument);
  EXPECT_THROW(kernel_weight(KernelType::Cone, 0.0, 1.0, 0.9), std::invalid_argument);
}

TEST(Kernel, Names) {
  EXPECT_EQ(std::string(kernel_name(KernelType::Uniform)), "uniform");
  EXPECT_EQ(std::string(kernel_name(KernelType::Cone)), "cone");
  EXPECT_EQ(std::string(kernel_name(KernelType::Epanechnikov)), "epanechnikov");
  EXPECT_EQ(std::string(kernel_name(KernelType::Silverman)), "silverman");
}

}  // namespace
}  // namespace dayphoton::engine
