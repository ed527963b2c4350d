// Density-estimation kernels (seeds/000 eqs. 3.19-3.22, normalised in 2-D as digest section
// 2.3 corrects). Formulas and the normalisation argument: see kernel.h.
#include "dayphoton/engine/kernel.h"

#include <cmath>
#include <stdexcept>

#include "dayphoton/core/units.h"

namespace dayphoton::engine {

double kernel_weight(KernelType type, double s_m, double r_m, double cone_slope) {
  if (!(r_m > 0) || !std::isfinite(r_m))
    throw std::invalid_argument("kernel_weight: the kernel radius must be positive and finite");
  if (!(s_m <= r_m)) return 0.0;  // outside the disc (or NaN distance)
  const double disc_m2 = Pi * r_m * r_m;
  const double u = s_m / r_m;
  switch (type) {
    case KernelType::Uniform:
      return 1.0 / disc_m2;
    case KernelType::Cone:
      if (!(cone_slope >= 1.0))
        throw std::invalid_argument("kernel_weight: the cone slope k must be >= 1");
      // integral_0^r (1 - s/(k r)) 2 pi s ds = pi r^2 (1 - 2/(3k)).
      return (1.0 - u / cone_slope) / (disc_m2 * (1.0 - 2.0 / (3.0 * cone_slope)));
    case KernelType::Epanechnikov:
      // integral_0^1 (1 - u^2) 2 u du = 1/2.
      return 2.0 / disc_m2 * (1.0 - u * u);
    case KernelType::Silverman: {
      // integral_0^1 (1 - u^2)^2 2 u du = 1/3.
      const double t = 1.0 - u * u;
      return 3.0 / disc_m2 * t * t;
    }
  }
  throw std::invalid_argument("kernel_weight: unknown kernel type");
}

const char* kernel_name(KernelType type) {
  switch (type) {
    case KernelType::Uniform: return "uniform";
    case KernelType::Cone: return "cone";
    case KernelType::Epanechnikov: return "epanechnikov";
    case KernelType::Silverman: return "silverman";
  }
  return "unknown";
}

}  // namespace dayphoton::engine
