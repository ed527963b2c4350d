// Density-estimation kernels, radially symmetric and normalised over the disc of radius
// r: integral_0^r K(s) 2 pi s ds = 1 (seeds/000 eqs. 3.19-3.22; the thesis prints the 1-D
// condition, digest section 2.3 gives the correct 2-D one).
//
// Why a disc: photons "dangle in space" (seeds/000 section 3.1.3) and the estimate assumes
// they lie on a plane through the query point, so the kernel integrates to one over the
// disc the k-NN search found, not over a sphere. tests/engine/kernel_test.cpp checks the
// normalisation by quadrature (digest T-6).
#pragma once

namespace dayphoton::engine {

enum class KernelType {
  Uniform,       ///< 1 / (pi r^2)                                             (3.19)
  Cone,          ///< Jensen's cone filter (1 - s/(k r)) / (pi r^2 (1 - 2/(3k)))  (3.20)
  Epanechnikov,  ///< (2 / (pi r^2)) (1 - (s/r)^2)                             (3.21)
  Silverman,     ///< biweight, (3 / (pi r^2)) (1 - (s/r)^2)^2                 (3.22)
};

/// Jensen's cone slope ("Realistic Image Synthesis Using Photon Mapping", 2001); the thesis
/// does not state the k it used (digest section 10).
inline constexpr double DefaultConeSlope = 1.1;

/// Kernel value (1/m^2) at distance `s_m` from the centre for bandwidth radius `r_m`;
/// zero for s > r. `cone_slope` is the cone filter's k (>= 1; ignored by other kernels).
/// Throws std::invalid_argument if r_m is not positive and finite or cone_slope < 1.
double kernel_weight(KernelType type, double s_m, double r_m,
                     double cone_slope = DefaultConeSlope);

/// Name for messages and docs ("uniform", "cone", "epanechnikov", "silverman").
const char* kernel_name(KernelType type);

}  // namespace dayphoton::engine
