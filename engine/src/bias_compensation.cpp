// The bias-compensating operator of Schregle's thesis (seeds/000 section 5.3, Alg. 5.1;
// digest sections 4.3, 4.6, 4.7): a binary search on the bandwidth N in [n_min, n_max].
//
// It gathers the n_max nearest photons once, forms the weighted mean mu and variance
// sigma^2 of the estimates f(x, j), j = 1..n_min, with weights w(j) = j^2 (eqs. 5.4-5.6),
// then bisects: the estimate f(x, N_mid) deviates from mu by eps (5.7); with probability
// p = exp(-eps^2 / (2 sigma^2)) (5.8) the deviation is taken for noise, f(x, N_mid) joins mu
// and sigma^2 and the search moves up, else it is taken for bias and the search moves down.
// Colour (the thesis's chromatic variant): mu, sigma^2, eps and p per RGB channel, p
// averaged over the channels, one decision.
//
// Deviations from Alg. 5.1, each for a stated reason:
//  1. Every f(x, j) uses the averaged radius (d_j + d_{j+1}) / 2 like our fixed estimates
//     (so n_max + 1 photons are gathered). Besides halving the k-NN radius bias, it tames
//     the heavy tails at tiny j (digest 4.6: with the plain radius f(x,1) has an infinite
//     mean and f(x,2) an infinite variance; with the averaged one f(x,1) has a finite mean
//     and f(x,2) a finite variance), which otherwise inflate sigma^2 and let bias through.
//  2. Integer-safe loop (digest 4.6: with N_mid = (N_min + N_max)/2 the printed loop never
//     ends once N_max = N_min + 1 and the test accepts). Here `lo` is the last accepted
//     bandwidth (initially n_min) and `hi` the first rejected one (initially n_max + 1, so
//     n_max itself is reachable); mid = lo + (hi - lo) / 2 lies strictly between them, the
//     loop runs while hi - lo > 1, i.e. ceil(log2(n_max - n_min + 1)) times, and returns
//     f(x, lo), the last accepted estimate (the printed return value f(x, N_mid) can be a
//     rejected one).
//  3. No partition step: PhotonMap::nearest returns its neighbours sorted (the max-heap is
//     heap-sorted at the end, O(k log k), the same order as the search itself), so the
//     partial quicksort of Alg. 5.1 has nothing left to do. bench/photon_map_bench.cpp
//     reports the resulting cost against a fixed n_max (thesis Table 5.1: +20-30 %).
//  4. mu and sigma^2 are updated with West's weighted incremental algorithm (D. H. D. West,
//     "Updating mean and variance estimates: an improved method", CACM 22(9), 1979): the
//     same weighted population variance as (5.6), without the cancellation of
//     mu[f^2] - mu[f]^2. A channel with sigma^2 = 0 gives p = 1 if eps = 0, else p = 0.
//  5. Short lookups (fewer than n_max + 1 photons within the maximum search radius): for
//     bandwidths beyond the photons found, f(x, j) is the fixed-radius estimate of all of
//     them over the max-radius disc (density_estimate.h), so the search needs no special
//     case and returns what estimate_irradiance would for a short lookup.
//  6. In the initial pass, an f(x, j) whose radius is 0 (j+1 photons exactly on the query
//     point) is left out: it is infinite, not a sample of the noise.
//  7. xi comes from Rng(rng_seed, 0, rng_index, RandomStream::Estimate), one draw per
//     iteration, so results are reproducible per query point (digest 4.6).
#include "dayphoton/engine/density_estimate.h"

#include <cmath>
#include <stdexcept>

#include "dayphoton/engine/random.h"

namespace dayphoton::engine {
namespace {

void check_options(const BiasCompensationOptions& options) {
  if (options.n_min == 0)
    throw std::invalid_argument("bias compensation: n_min must be at least 1 photon");
  if (options.n_max < options.n_min)
    throw std::invalid_argument("bias compensation: n_max must not be below n_min");
  if (!(options.max_radius_m > 0) || !std::isfinite(options.max_radius_m))
    throw std::invalid_argument("bias compensation: the maximum search radius must be positive and finite");
  if (options.weight_power < 0)
    throw std::invalid_argument("bias compensation: the weight power must be >= 0");
}

/// Weighted running mean and variance per RGB channel (West 1979).
class WeightedMoments {
 public:
  void add(double weight, const Vec3& value) {
    m_weight_sum += weight;
    for (int c = 0; c < 3; ++c) {
      const double delta = value[c] - m_mean[c];
      m_mean[c] += weight / m_weight_sum * delta;
      m_m2[c] += weight * delta * (value[c] - m_mean[c]);
    }
  }
  bool empty() const { return !(m_weight_sum > 0); }

  /// Probability that `value` differs from the mean by noise, eq. 5.8, averaged over RGB.
  double noise_probability(const Vec3& value) const {
    double p_sum = 0;
    for (int c = 0; c < 3; ++c) {
      const double eps = value[c] - m_mean[c];
      const double variance = m_m2[c] > 0 ? m_m2[c] / m_weight_sum : 0.0;
      if (variance > 0)
        p_sum += std::exp(-eps * eps / (2.0 * variance));
      else
        p_sum += eps == 0 ? 1.0 : 0.0;
    }
    return p_sum / 3.0;
  }

 private:
  double m_weight_sum = 0;
  Vec3 m_mean{};
  Vec3 m_m2{};
};

struct Choice {
  KernelDisc disc;
  Vec3 irradiance;
};

/// Alg. 5.1 on an already gathered, sorted neighbour list, on the photons' own fluxes whatever
/// options.flux says: the estimate with their sky ratios (photon.h) uses the same disc.
Choice choose_bandwidth(const PhotonMap& map, const std::vector<NeighbourPhoton>& neighbours,
                        const BiasCompensationOptions& options) {
  auto estimate = [&](std::size_t bandwidth) {
    Choice choice;
    choice.disc = kernel_disc(neighbours, bandwidth, KernelRadius::Averaged, options.max_radius_m);
    return choice;
  };
  auto evaluate = [&](Choice& choice) {
    choice.irradiance = accumulate_disc(map, neighbours, choice.disc, options.kernel);
  };
  auto weight = [&](std::size_t j) { return std::pow(static_cast<double>(j), options.weight_power); };

  WeightedMoments moments;
  Choice accepted;
  for (std::size_t j = 1; j <= options.n_min; ++j) {
    Choice f = estimate(j);
    if (f.disc.photon_count > 0 && !(f.disc.radius_m > 0)) {
      if (j == options.n_min) evaluate(f);  // throws: the n_min estimate itself is infinite
      continue;                             // deviation 6
    }
    evaluate(f);
    moments.add(weight(j), f.irradiance);
    if (j == options.n_min) accepted = f;
  }

  Rng rng(options.rng_seed, 0, options.rng_index, RandomStream::Estimate);
  std::size_t lo = options.n_min;
  std::size_t hi = options.n_max + 1;
  while (hi - lo > 1) {
    const std::size_t mid = lo + (hi - lo) / 2;
    Choice f = estimate(mid);
    evaluate(f);
    const double p = moments.noise_probability(f.irradiance);
    if (rng.uniform() < p) {  // probably noise: widen
      moments.add(weight(mid), f.irradiance);
      accepted = f;
      lo = mid;
    } else {  // probably bias: narrow
      hi = mid;
    }
  }
  return accepted;
}

Choice gather_and_choose(const PhotonMap& map, const Vec3& point, const PhotonFilter& filter,
                         const BiasCompensationOptions& options,
                         std::vector<NeighbourPhoton>& neighbours) {
  check_options(options);
  map.nearest(point, options.n_max + 1, options.max_radius_m, filter, neighbours);
  return choose_bandwidth(map, neighbours, options);
}

}  // namespace

DensityEstimate estimate_irradiance_bias_compensated(const PhotonMap& map, const Vec3& point,
                                                     const PhotonFilter& filter,
                                                     const BiasCompensationOptions& options) {
  std::vector<NeighbourPhoton> neighbours;
  const Choice choice = gather_and_choose(map, point, filter, options, neighbours);
  DensityEstimate result;
  result.radius_m = choice.disc.radius_m;
  result.photon_count = choice.disc.photon_count;
  // The estimate at the chosen bandwidth (with options.flux) and its variance
  // (estimate_variance.h): the choice itself depends on the photons, which this leaves out.
  if (choice.disc.photon_count > 0)
    result.irradiance = accumulate_disc(map, neighbours, choice.disc, options.kernel, nullptr,
                                        &result.luminance_variance, nullptr, options.flux);
  return result;
}

DensityEstimate estimate_contributions_bias_compensated(const PhotonMap& map,
                                                        const Vec3& point,
                                                        const PhotonFilter& filter,
                                                        const BiasCompensationOptions& options,
                                                        std::vector<Vec3>& per_source,
                                                        std::vector<double>* per_source_variance) {
  PhotonFilter any_source = filter;
  any_source.source = PhotonFilter::AnySource;
  std::vector<NeighbourPhoton> neighbours;
  const Choice choice = gather_and_choose(map, point, any_source, options, neighbours);
  DensityEstimate result;
  result.irradiance =
      accumulate_disc(map, neighbours, choice.disc, options.kernel, &per_source, &result.luminance_variance,
                      per_source_variance, options.flux);
  result.radius_m = choice.disc.radius_m;
  result.photon_count = choice.disc.photon_count;
  return result;
}

}  // namespace dayphoton::engine
