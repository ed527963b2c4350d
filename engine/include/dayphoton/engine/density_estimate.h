// Density estimates on a photon map (seeds/000 section 3.1.3 and chapter 5; seeds/001
// section 4.1 eq. 18, the contribution estimate).
//
// Irradiance at x from the N nearest photons: E(x) = sum_j K(|x - x_j|, r) Phi_j, with K
// normalised over the disc of radius r (kernel.h) and (KernelRadius)
//   r = d_{N+1}               NextNeighbour, the default: the (N+1)-th photon is found but
//                             not used. Unbiased on a locally uniform density: given
//                             d_{N+1}, the N inner photons are independent and uniform in the
//                             disc, so E[sum K Phi] = N Phi / (pi r^2), and pi lambda d_{N+1}^2
//                             is Gamma(N+1)-distributed with E[1 / G] = 1 / N; the mean is
//                             lambda Phi exactly, the relative sigma 1 / sqrt(N - 1) (derived;
//                             tests/engine/density_estimate_test.cpp T-5),
//   r = (d_N + d_{N+1}) / 2   Averaged (Christensen, seeds/000 section 6.2, digest section
//                             2.3): halves the plain bias (+2.04 % -> +1.00 % at N = 50),
//   r = d_N                   Plain: bias +1/(N-1) on a uniform density,
//   r = max_radius_m          "short lookup" (seeds/001 section 5): the photon(s) that
//                             would define r lie beyond the maximum search radius, i.e.
//                             fewer than N+1 (next, averaged) or N (plain) photons are within it.
//                             Then ALL photons found count and the disc is the max-radius
//                             disc: the fixed-radius estimate, which for a locally uniform
//                             density is unbiased (Poisson count in a fixed disc). With no
//                             photon found the estimate is zero.
// The contribution form keeps the sum per emitting source: E_p(x) for every source p,
// from one lookup of the N nearest photons of ANY source (seeds/001 eq. 18, written there
// with K and 1/(pi r^2) both; here K carries the normalisation).
//
// If every photon that defines r lies exactly at x (r = 0, e.g. N+1 coincident photons on
// the query point) the density is a Dirac impulse, not a number: EngineError is thrown.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/kernel.h"
#include "dayphoton/engine/photon_map.h"

namespace dayphoton::engine {

/// Which neighbour distance sets the kernel radius (header comment).
enum class KernelRadius : std::uint8_t { Plain = 0, Averaged = 1, NextNeighbour = 2 };

/// Neighbours a lookup must gather for `bandwidth` photons under `radius`.
inline std::size_t neighbours_needed(std::size_t bandwidth, KernelRadius radius) {
  return radius == KernelRadius::Plain ? bandwidth : bandwidth + 1;
}

struct DensityEstimateOptions {
  std::size_t bandwidth = 50;  ///< N, photons per estimate (>= 1)
  double max_radius_m = 1e30;  ///< maximum search radius (> 0)
  KernelType kernel = KernelType::Uniform;
  KernelRadius radius = KernelRadius::NextNeighbour;
  PhotonFlux flux = PhotonFlux::AsTraced;  ///< the photons' flux or times their sky ratios (photon.h)
};

struct DensityEstimate {
  Vec3 irradiance;                ///< W/m^2 per unit source radiance, RGB
  double radius_m = 0;            ///< kernel radius used
  std::size_t photon_count = 0;   ///< photons inside the kernel
  /// Sum of the squared luminance terms (K Phi_j), the estimate's variance
  /// (estimate_variance.h); times the square of any factor the caller applies.
  double luminance_variance = 0;
};

/// The disc an estimate uses, by the rules above, from a neighbour list sorted by distance
/// (PhotonMap::nearest gathered with the same max radius and k >= neighbours_needed(); a
/// longer list is fine, only its head is used).
struct KernelDisc {
  double radius_m = 0;
  std::size_t photon_count = 0;  ///< the first photon_count neighbours are inside
};
KernelDisc kernel_disc(const std::vector<NeighbourPhoton>& sorted, std::size_t bandwidth,
                       KernelRadius radius, double max_radius_m);

/// sum_j K(d_j, disc.radius_m) Phi_j over the disc's photons (the head of `sorted`). If
/// `per_source` is given, each term is also added to (*per_source)[photon.source]; a source
/// without a slot throws std::out_of_range before anything is added. Throws EngineError
/// for a disc of radius 0 that holds photons (see above).
Vec3 accumulate_disc(const PhotonMap& map, const std::vector<NeighbourPhoton>& sorted,
                     const KernelDisc& disc, KernelType kernel,
                     std::vector<Vec3>* per_source = nullptr, double* luminance_variance = nullptr,
                     std::vector<double>* per_source_variance = nullptr, PhotonFlux flux = PhotonFlux::AsTraced);

/// Irradiance from the photons passing `filter`. Throws std::invalid_argument for
/// bandwidth 0 or a max radius that is not positive.
DensityEstimate estimate_irradiance(const PhotonMap& map, const Vec3& point,
                                    const PhotonFilter& filter,
                                    const DensityEstimateOptions& options);

/// Contribution estimate: one lookup (filter.source is ignored: all sources), the kernel-
/// weighted flux added to per_source[photon.source] (which must have a slot for every
/// source present, else std::out_of_range; it is NOT cleared). Returns the radius and count
/// as above, and in `irradiance` the sum over all sources (equal to estimate_irradiance
/// with filter.source = AnySource, up to summation order).
DensityEstimate estimate_contributions(const PhotonMap& map, const Vec3& point,
                                       const PhotonFilter& filter,
                                       const DensityEstimateOptions& options,
                                       std::vector<Vec3>& per_source,
                                       std::vector<double>* per_source_variance = nullptr);

/// Bias-compensating operator (seeds/000 chapter 5, Alg. 5.1; digest sections 4.3, 4.6,
/// 4.7): binary search on the bandwidth between n_min and n_max, accepting larger
/// bandwidths while the estimated bias stays below the estimated noise; weights j^2,
/// integer-safe loop, per-channel decision averaged. Randomised by uniforms from
/// Rng(rng_seed, 0, rng_index, RandomStream::Estimate): deterministic for a given seed and
/// index (give each query point its own index). Deviations from Alg. 5.1 are listed in
/// engine/src/bias_compensation.cpp.
struct BiasCompensationOptions {
  std::size_t n_min = 50;      ///< >= 1; the thesis uses 50 throughout
  std::size_t n_max = 1000;    ///< >= n_min; the thesis recommends 5-20 x n_min
  double max_radius_m = 1e30;  ///< as DensityEstimateOptions::max_radius_m
  KernelType kernel = KernelType::Uniform;  ///< the thesis does not say; uniform matches fig. 5.2
  int weight_power = 2;        ///< w(j) = j^weight_power (>= 0); 2 is the thesis's choice
  std::uint64_t rng_seed = 1;
  std::uint64_t rng_index = 0;  ///< query point index, so that points draw independent xi
  PhotonFlux flux = PhotonFlux::AsTraced;  ///< as DensityEstimateOptions::flux
};

/// The bias-compensated irradiance; photon_count is the bandwidth the search chose.
DensityEstimate estimate_irradiance_bias_compensated(const PhotonMap& map, const Vec3& point,
                                                     const PhotonFilter& filter,
                                                     const BiasCompensationOptions& options);

/// The contribution form: the bandwidth is chosen on the total irradiance of all sources
/// (filter.source is ignored), then that one disc is binned per source as in
/// estimate_contributions.
DensityEstimate estimate_contributions_bias_compensated(const PhotonMap& map,
                                                        const Vec3& point,
                                                        const PhotonFilter& filter,
                                                        const BiasCompensationOptions& options,
                                                        std::vector<Vec3>& per_source,
                                                        std::vector<double>* per_source_variance = nullptr);

}  // namespace dayphoton::engine
