// Density estimates (seeds/000 section 3.1.3 and 6.2, digest section 2.3 and T-5; seeds/001
// eq. 18 for contributions; seeds/001 section 5 for the maximum search radius).
//
// Statistical tests draw independent trials: each trial is a fresh Poisson process of
// intensity lambda = 1 photon/m^2 on a disc of radius R_gen around the query point, in its
// own PhotonMap, so trials are independent and the tolerance of a mean over T trials is
// 4 sigma / sqrt(T) with sigma the sample standard deviation of the T values (for T in the
// thousands the sampling error of sigma itself is a few per cent). R_gen is chosen so that
// the N+1 nearest photons lie inside it except with probability < 1e-9 (Poisson tail), and
// every trial asserts that the estimate did find them.
#include "dayphoton/engine/density_estimate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "dayphoton/core/units.h"
#include "estimate_statistics.h"
#include "dayphoton/engine/engine_error.h"

namespace dayphoton::engine {
namespace {

Photon photon_at(const Vec3& p, const Vec3& flux, std::uint32_t source = 0) {
  Photon photon;
  photon.position = {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)};
  photon.flux = {static_cast<float>(flux.x), static_cast<float>(flux.y), static_cast<float>(flux.z)};
  photon.source = source;
  photon.path_class = PathClass::Global;
  photon.set_normal({0, 0, 1});
  return photon;
}

/// Poisson process of intensity 1/m^2 on the disc of radius r_gen about `centre` in the
/// plane spanned by the orthonormal u, v; each photon's flux from `flux`.
template <typename Flux>
std::vector<Photon> poisson_disc(std::mt19937_64& rng, const Vec3& centre, const Vec3& u,
                                 const Vec3& v, double r_gen, Flux&& flux) {
  std::poisson_distribution<int> count(Pi * r_gen * r_gen);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  const int n = count(rng);
  std::vector<Photon> photons;
  photons.reserve(n);
  for (int i = 0; i < n; ++i) {
    const double r = r_gen * std::sqrt(uni(rng)), phi = 2 * Pi * uni(rng);
    photons.push_back(photon_at(centre + u * (r * std::cos(phi)) + v * (r * std::sin(phi)), flux(rng)));
  }
  return photons;
}

using test::all_photons;
using test::Stats;

// Digest T-5. For a Poisson density lambda, pi lambda d_N^2 ~ Gamma(N, 1), so the plain
// estimate N Phi / (pi d_N^2) has mean lambda Phi N/(N-1): +2.0408 % at N = 50, per-trial
// relative sigma N / ((N-1) sqrt(N-2)) = 14.7 %. With the next-neighbour radius d_{N+1} the
// N photons inside are uniform in the disc given d_{N+1}, pi lambda d_{N+1}^2 ~ Gamma(N+1),
// and the mean is exactly lambda Phi, relative sigma 1 / sqrt(N - 1) = 14.3 %. With the
// averaged radius,
// pi lambda d_{N+1}^2 = G + X (X ~ Exp(1) independent of G), and the mean
// E[4N / (sqrt(G) + sqrt(G + X))^2] = 1.010049 at N = 50 (2-D Simpson quadrature over the
// joint density, 4000 x 4000 panels; the digest's Monte Carlo gave +0.98 % +- 0.03 %).
// 40000 trials: 4 sigma / sqrt(T) = 0.29 % for each mean; the difference of the two
// (paired on the same photons) is far more precise and must be about half the plain bias.
TEST(DensityEstimate, NearestNeighbourRadiusBiasT5) {
  constexpr std::size_t N = 50;
  constexpr int Trials = 40000;
  constexpr double PlainMean = 50.0 / 49.0;
  constexpr double AveragedMean = 1.010049;
  constexpr double RGen = 6.0;  // mean 113 photons; P(fewer than 51) < 1e-9
  std::mt19937_64 rng(20240501);
  const Vec3 centre{0.3, -1.2, 0.8}, u{1, 0, 0}, v{0, 1, 0};
  DensityEstimateOptions plain;
  plain.bandwidth = N;
  plain.radius = KernelRadius::Plain;
  plain.max_radius_m = RGen;
  DensityEstimateOptions averaged = plain;
  averaged.radius = KernelRadius::Averaged;
  DensityEstimateOptions next = plain;
  next.radius = KernelRadius::NextNeighbour;
  Stats plain_stats, averaged_stats, next_stats, difference;
  for (int t = 0; t < Trials; ++t) {
    const PhotonMap map(poisson_disc(rng, centre, u, v, RGen,
                                     [](std::mt19937_64&) { return Vec3{1, 1, 1}; }));
    const DensityEstimate a = estimate_irradiance(map, centre, all_photons(), plain);
    const DensityEstimate b = estimate_irradiance(map, centre, all_photons(), averaged);
    const DensityEstimate c = estimate_irradiance(map, centre, all_photons(), next);
    ASSERT_EQ(c.photon_count, N);
    ASSERT_GT(c.radius_m, b.radius_m);
    next_stats.add(c.irradiance.y);
    ASSERT_EQ(a.photon_count, N);
    ASSERT_EQ(b.photon_count, N);
    ASSERT_LT(b.radius_m, RGen);
    ASSERT_GT(b.radius_m, a.radius_m);  // the (N+1)-th photon is farther (no ties in a.s.)
    plain_stats.add(a.irradiance.y);  // exact density lambda Phi = 1
    averaged_stats.add(b.irradiance.y);
    difference.add(a.irradiance.y - b.irradiance.y);
  }
  EXPECT_NEAR(plain_stats.sigma(), 50.0 / (49.0 * std::sqrt(48.0)), 0.05 * plain_stats.sigma());
  EXPECT_NEAR(plain_stats.mean(), PlainMean, plain_stats.tolerance());
  EXPECT_NEAR(averaged_stats.mean(), AveragedMean, averaged_stats.tolerance());
  EXPECT_NEAR(next_stats.mean(), 1.0, next_stats.tolerance());
  EXPECT_NEAR(next_stats.sigma(), 1.0 / std::sqrt(49.0), 0.05 * next_stats.sigma());
  EXPECT_NEAR(difference.mean(), PlainMean - AveragedMean, difference.tolerance());
  RecordProperty("plain_bias_percent", std::to_string(100 * (plain_stats.mean() - 1)));
  RecordProperty("averaged_bias_percent", std::to_string(100 * (averaged_stats.mean() - 1)));
  RecordProperty("next_neighbour_bias_percent", std::to_string(100 * (next_stats.mean() - 1)));
}

// A uniform density with random RGB fluxes (each channel uniform in [0, 2] x base, mean
// base) on a tilted plane: every kernel's estimate averages to lambda x base within noise.
// N = 1000: the remaining k-NN bias is O(1/N) and at most the plain uniform-kernel bias
// 1/(N-1) = 0.1 % (weighted kernels give less weight to the rim photon that causes it),
// added to the 4-sigma tolerance.
TEST(DensityEstimate, UniformDensityAllKernels) {
  constexpr std::size_t N = 1000;
  constexpr int Trials = 300;
  constexpr double RGen = 21.0;  // mean 1385 photons; P(fewer than 1001) < 1e-9
  const Vec3 base{0.2, 0.5, 1.0};
  const Vec3 centre{1.0, 2.0, 3.0};
  const Vec3 u = normalize(Vec3{1, 1, 0.3});
  const Vec3 v = normalize(cross(Vec3{0.2, -0.4, 1.0}, u));
  const KernelType kernels[] = {KernelType::Uniform, KernelType::Cone, KernelType::Epanechnikov,
                                KernelType::Silverman};
  Stats stats[4][3];
  std::mt19937_64 rng(77);
  for (int t = 0; t < Trials; ++t) {
    const PhotonMap map(poisson_disc(rng, centre, u, normalize(v), RGen, [&](std::mt19937_64& r) {
      std::uniform_real_distribution<double> two(0.0, 2.0);
      return Vec3{two(r) * base.x, two(r) * base.y, two(r) * base.z};
    }));
    for (int k = 0; k < 4; ++k) {
      DensityEstimateOptions options;
      options.bandwidth = N;
      options.kernel = kernels[k];
      options.max_radius_m = RGen;
      const DensityEstimate e = estimate_irradiance(map, centre, all_photons(), options);
      ASSERT_EQ(e.photon_count, N);
      for (int c = 0; c < 3; ++c) stats[k][c].add(e.irradiance[c] / base[c]);
    }
  }
  for (int k = 0; k < 4; ++k)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(stats[k][c].mean(), 1.0, stats[k][c].tolerance() + 1.0 / (N - 1))
          << kernel_name(kernels[k]) << " channel " << c;
}

TEST(DensityEstimate, RadiusRulesOnAKnownConfiguration) {
  // Photons on the x axis at distances 1, 2, ..., 10 from the origin, flux 1 each.
  std::vector<Photon> photons;
  for (int i = 1; i <= 10; ++i) photons.push_back(photon_at({double(i), 0, 0}, {1, 2, 3}));
  const PhotonMap map(photons);
  DensityEstimateOptions options;
  options.bandwidth = 4;
  DensityEstimate e = estimate_irradiance(map, {0, 0, 0}, all_photons(), options);
  EXPECT_EQ(e.photon_count, 4u);  // the default: next-neighbour radius d_5, 4 photons
  EXPECT_DOUBLE_EQ(e.radius_m, 5.0);
  EXPECT_DOUBLE_EQ(e.irradiance.x, 4.0 / (Pi * 25.0));
  EXPECT_DOUBLE_EQ(e.irradiance.z, 12.0 / (Pi * 25.0));

  options.radius = KernelRadius::Averaged;
  e = estimate_irradiance(map, {0, 0, 0}, all_photons(), options);
  EXPECT_EQ(e.photon_count, 4u);
  EXPECT_DOUBLE_EQ(e.radius_m, 4.5);  // (d_4 + d_5) / 2
  EXPECT_DOUBLE_EQ(e.irradiance.x, 4.0 / (Pi * 4.5 * 4.5));
  EXPECT_DOUBLE_EQ(e.irradiance.z, 12.0 / (Pi * 4.5 * 4.5));

  options.radius = KernelRadius::Plain;
  e = estimate_irradiance(map, {0, 0, 0}, all_photons(), options);
  EXPECT_DOUBLE_EQ(e.radius_m, 4.0);
  EXPECT_DOUBLE_EQ(e.irradiance.x, 4.0 / (Pi * 16.0));

  // Short lookups: fewer than the defining photons within the max radius -> all found
  // photons over the max-radius disc.
  options.max_radius_m = 3.5;  // 3 photons inside, N = 4
  e = estimate_irradiance(map, {0, 0, 0}, all_photons(), options);
  EXPECT_EQ(e.photon_count, 3u);
  EXPECT_DOUBLE_EQ(e.radius_m, 3.5);
  EXPECT_DOUBLE_EQ(e.irradiance.x, 3.0 / (Pi * 3.5 * 3.5));
  options.radius = KernelRadius::Averaged;
  options.max_radius_m = 4.8;  // exactly N = 4 inside: the (N+1)-th is beyond
  e = estimate_irradiance(map, {0, 0, 0}, all_photons(), options);
  EXPECT_EQ(e.photon_count, 4u);
  EXPECT_DOUBLE_EQ(e.radius_m, 4.8);
  EXPECT_DOUBLE_EQ(e.irradiance.x, 4.0 / (Pi * 4.8 * 4.8));
  options.max_radius_m = 5.0;  // the 5th photon at exactly the max radius is found
  e = estimate_irradiance(map, {0, 0, 0}, all_photons(), options);
  EXPECT_EQ(e.photon_count, 4u);
  EXPECT_DOUBLE_EQ(e.radius_m, 4.5);
  options.max_radius_m = 0.5;  // nothing inside
  e = estimate_irradiance(map, {0, 0, 0}, all_photons(), options);
  EXPECT_EQ(e.photon_count, 0u);
  EXPECT_EQ(e.irradiance, Vec3(0, 0, 0));
  EXPECT_DOUBLE_EQ(e.radius_m, 0.5);

  // The filter applies: no photon passes -> zero.
  PhotonFilter caustic_only;
  caustic_only.path_classes = path_class_bit(PathClass::Caustic);
  options.max_radius_m = 100;
  e = estimate_irradiance(map, {0, 0, 0}, caustic_only, options);
  EXPECT_EQ(e.photon_count, 0u);
  EXPECT_EQ(e.irradiance, Vec3(0, 0, 0));

  // Empty map.
  e = estimate_irradiance(PhotonMap{}, {0, 0, 0}, all_photons(), options);
  EXPECT_EQ(e.photon_count, 0u);
  EXPECT_EQ(e.irradiance, Vec3(0, 0, 0));
}

TEST(DensityEstimate, InvalidOptionsAndInfiniteDensityThrow) {
  const PhotonMap map(std::vector<Photon>(5, photon_at({1, 1, 1}, {1, 1, 1})));
  DensityEstimateOptions options;
  options.bandwidth = 0;
  EXPECT_THROW(estimate_irradiance(map, {0, 0, 0}, all_photons(), options), std::invalid_argument);
  options.bandwidth = 3;
  options.max_radius_m = 0;
  EXPECT_THROW(estimate_irradiance(map, {0, 0, 0}, all_photons(), options), std::invalid_argument);
  options.max_radius_m = INFINITY;
  EXPECT_THROW(estimate_irradiance(map, {0, 0, 0}, all_photons(), options), std::invalid_argument);
  options.max_radius_m = 10;
  // Four coincident photons on the query point define the averaged radius 0.
  EXPECT_THROW(estimate_irradiance(map, {1, 1, 1}, all_photons(), options), EngineError);
  // Off the point, the same photons are a finite density.
  const DensityEstimate e = estimate_irradiance(map, {1, 1, 2}, all_photons(), options);
  EXPECT_DOUBLE_EQ(e.radius_m, 1.0);
  EXPECT_DOUBLE_EQ(e.irradiance.x, 3.0 / Pi);
}

// Contributions (seeds/001 eq. 18): one lookup of any source, flux binned by source. Checked
// against an independent computation (sort all photons by distance, take the N nearest,
// bin), and summed over sources against estimate_irradiance with the same settings.
TEST(DensityEstimate, ContributionsBinBySourceAndSumToIrradiance) {
  constexpr std::uint32_t Sources = 20;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> pos(0.0, 2.0), fl(0.0, 1.0);
  std::uniform_int_distribution<std::uint32_t> src(0, Sources - 2);  // source 19 never occurs
  std::vector<Photon> photons;
  for (int i = 0; i < 3000; ++i)
    photons.push_back(photon_at({pos(rng), pos(rng), 0.1 * pos(rng)}, {fl(rng), fl(rng), fl(rng)},
                                src(rng)));
  const PhotonMap map(photons);
  const KernelType kernels[] = {KernelType::Uniform, KernelType::Cone, KernelType::Epanechnikov,
                                KernelType::Silverman};
  for (KernelType kernel : kernels)
    for (bool average : {true, false})
      for (double max_radius : {1e30, 0.1})
        for (int q = 0; q < 10; ++q) {
          const Vec3 point{pos(rng), pos(rng), 0.1};
          DensityEstimateOptions options;
          options.bandwidth = 60;
          options.kernel = kernel;
          options.radius = average ? KernelRadius::NextNeighbour : KernelRadius::Plain;
          options.max_radius_m = max_radius;
          PhotonFilter one_source = all_photons();
          one_source.source = 4;  // ignored by the contribution estimate
          std::vector<Vec3> per_source(Sources);
          const DensityEstimate c = estimate_contributions(map, point, one_source, options, per_source);
          const DensityEstimate e = estimate_irradiance(map, point, all_photons(), options);
          ASSERT_EQ(c.photon_count, e.photon_count);
          ASSERT_EQ(c.radius_m, e.radius_m);
          Vec3 sum{};
          for (const Vec3& s : per_source) sum += s;
          for (int ch = 0; ch < 3; ++ch) {
            EXPECT_NEAR(sum[ch], e.irradiance[ch], 1e-12 * e.irradiance[ch]);
            EXPECT_NEAR(c.irradiance[ch], e.irradiance[ch], 1e-12 * e.irradiance[ch]);
          }
          EXPECT_EQ(per_source[Sources - 1], Vec3(0, 0, 0));

          // Independent: brute-force neighbours, binned.
          std::vector<std::pair<double, std::size_t>> by_distance;
          for (std::size_t i = 0; i < map.size(); ++i) {
            const Vec3 d = map.photons()[i].position_m() - point;
            by_distance.push_back({dot(d, d), i});
          }
          std::sort(by_distance.begin(), by_distance.end());
          std::vector<Vec3> expected(Sources);
          const std::size_t inside = c.photon_count;
          for (std::size_t j = 0; j < inside; ++j) {
            const Photon& p = map.photons()[by_distance[j].second];
            expected[p.source] +=
                p.flux_rgb() * kernel_weight(kernel, std::sqrt(by_distance[j].first), c.radius_m);
          }
          if (inside < options.bandwidth) {
            ASSERT_EQ(c.radius_m, max_radius);  // short lookup
            if (inside > 0) {
              ASSERT_LE(by_distance[inside - 1].first, max_radius * max_radius);
            }
            ASSERT_GT(by_distance[inside].first, max_radius * max_radius);
          }
          for (std::uint32_t s = 0; s < Sources; ++s)
            for (int ch = 0; ch < 3; ++ch)
              EXPECT_NEAR(per_source[s][ch], expected[s][ch], 1e-12 * (1 + e.irradiance[ch]));
        }
}

TEST(DensityEstimate, ContributionsAccumulateAndCheckSlots) {
  std::vector<Photon> photons;
  for (int i = 0; i < 10; ++i) photons.push_back(photon_at({0.1 * i, 0, 0}, {1, 1, 1}, i % 3));
  const PhotonMap map(photons);
  DensityEstimateOptions options;
  options.bandwidth = 5;
  std::vector<Vec3> per_source(3);
  estimate_contributions(map, {0, 0, 0}, all_photons(), options, per_source);
  const std::vector<Vec3> once = per_source;
  estimate_contributions(map, {0, 0, 0}, all_photons(), options, per_source);
  for (int s = 0; s < 3; ++s) EXPECT_EQ(per_source[s], once[s] * 2.0);  // not cleared
  std::vector<Vec3> too_few(2);
  EXPECT_THROW(estimate_contributions(map, {0, 0, 0}, all_photons(), options, too_few),
               std::out_of_range);
  EXPECT_EQ(too_few[0], Vec3(0, 0, 0));  // nothing added before the check
}

}  // namespace
}  // namespace dayphoton::engine
