// The bias-compensating operator (seeds/000 chapter 5, Alg. 5.1; digest sections 4.2-4.7,
// T-8): the "highlight" case study, a uniform density, a chromatic boundary, the degenerate
// bandwidth ranges of the integer-safe loop, short lookups, determinism and the
// contribution form.
//
// Tolerances: each statistical test averages independent replicates (photon sets drawn
// with their own seeds) and uses 4 sigma / sqrt(R), sigma the sample standard deviation of
// the R replicate values. Within one photon set the estimates share photons and are
// correlated, which is why the replicate, not the single estimate, is the unit.
#include "dayphoton/engine/density_estimate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "dayphoton/core/units.h"
#include "estimate_statistics.h"

namespace dayphoton::engine {
namespace {

using test::all_photons;
using test::Stats;

Photon photon_at(double x, double y, const Vec3& flux) {
  Photon p;
  p.position = {static_cast<float>(x), static_cast<float>(y), 0.0f};
  p.flux = {static_cast<float>(flux.x), static_cast<float>(flux.y), static_cast<float>(flux.z)};
  p.path_class = PathClass::Global;
  p.set_normal({0, 0, 1});
  return p;
}

/// Poisson process of intensity 1/m^2 on the disc of radius r_gen about the origin (z = 0);
/// flux(x) gives each photon's RGB flux from its x coordinate.
template <typename Flux>
std::vector<Photon> poisson_disc(std::mt19937_64& rng, double r_gen, Flux&& flux) {
  std::poisson_distribution<int> count(Pi * r_gen * r_gen);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = count(rng);
  std::vector<Photon> photons;
  photons.reserve(n);
  for (int i = 0; i < n; ++i) {
    const double r = r_gen * std::sqrt(u(rng)), phi = 2 * Pi * u(rng);
    const double x = r * std::cos(phi);
    photons.push_back(photon_at(x, r * std::sin(phi), flux(x)));
  }
  return photons;
}

/// The highlight case study as the digest reconstructs it (section 4.2): 50000 photons on
/// the unit square, irradiance 10 W/m^2 within radius 0.0536 of the centre and 1 W/m^2
/// elsewhere, so Phi_p = (1 + 9 pi 0.0536^2) / 50000; estimates on the circle of radius
/// 0.204 about the centre, outside the highlight (true value 1).
constexpr int HighlightPhotons = 50000;
constexpr double HighlightRadius = 0.0536;
constexpr double CircleRadius = 0.204;

PhotonMap highlight_map(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double flux = (1.0 + 9.0 * Pi * HighlightRadius * HighlightRadius) / HighlightPhotons;
  std::vector<Photon> photons;
  photons.reserve(HighlightPhotons);
  while (photons.size() < static_cast<std::size_t>(HighlightPhotons)) {  // rejection on 1 : 10
    const double x = u(rng), y = u(rng);
    const bool inside = (x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5) < HighlightRadius * HighlightRadius;
    if (10.0 * u(rng) < (inside ? 10.0 : 1.0)) photons.push_back(photon_at(x, y, {flux, flux, flux}));
  }
  return PhotonMap(std::move(photons));
}

Vec3 circle_point(int i, int count, double phase) {
  const double a = 2 * Pi * (i + phase) / count;
  return {0.5 + CircleRadius * std::cos(a), 0.5 + CircleRadius * std::sin(a), 0};
}

// Digest T-8 at the thesis's full size: N in 50..5000, w(j) = j^2, uniform kernel.
// The fixed uniform-kernel estimate at N = 5000 reaches into the highlight (onset about
// 3300 photons) and is biased by about +13 % (digest: +13.1 %); the operator must bring the
// mean bias down to the digest's "<~ 1 %" (thesis: 0.2 %), within the 4-sigma noise of the
// replicate mean. Sizes: 12 photon sets x 100 points (not 1 x 1000) because the
// replicate is the independent unit; about 1.3 s.
// Measured (these seeds): fixed +12.9 %, compensated +0.10 % (4 sigma of the mean: 1.2 %),
// mean bandwidth 1810. With w(j) = 1 instead the operator leaves +5.2 % (scratch run, 20 x
// 100 points), so this test does tell the weightings apart.
TEST(BiasCompensation, HighlightCaseStudyT8) {
  constexpr int Sets = 12, Points = 100;
  Stats fixed_bias, compensated_bias, bandwidth;
  for (int s = 0; s < Sets; ++s) {
    const PhotonMap map = highlight_map(1000 + s);
    const double phase = (s + 0.5) / Sets;  // different points in every set
    double fixed_sum = 0, compensated_sum = 0, bandwidth_sum = 0;
    for (int i = 0; i < Points; ++i) {
      const Vec3 q = circle_point(i, Points, phase);
      if (s < 2) {  // the fixed estimate's bias is 30x its noise: two sets suffice
        DensityEstimateOptions fixed;
        fixed.bandwidth = 5000;
        fixed_sum += estimate_irradiance(map, q, all_photons(), fixed).irradiance.x - 1.0;
      }
      BiasCompensationOptions options;
      options.n_min = 50;
      options.n_max = 5000;
      options.rng_seed = 7;
      options.rng_index = static_cast<std::uint64_t>(s * Points + i);
      const DensityEstimate e = estimate_irradiance_bias_compensated(map, q, all_photons(), options);
      compensated_sum += e.irradiance.x - 1.0;
      bandwidth_sum += static_cast<double>(e.photon_count);
      EXPECT_GE(e.photon_count, 50u);
      EXPECT_LE(e.photon_count, 5000u);
    }
    if (s < 2) fixed_bias.add(fixed_sum / Points);
    compensated_bias.add(compensated_sum / Points);
    bandwidth.add(bandwidth_sum / Points);
  }
  EXPECT_GT(fixed_bias.mean(), 0.10);
  EXPECT_LT(std::fabs(compensated_bias.mean()), 0.01 + compensated_bias.tolerance());
  EXPECT_LT(std::fabs(compensated_bias.mean()), fixed_bias.mean() / 5);
  RecordProperty("fixed_5000_bias_percent", std::to_string(100 * fixed_bias.mean()));
  RecordProperty("compensated_bias_percent", std::to_string(100 * compensated_bias.mean()));
  RecordProperty("compensated_bias_4sigma_percent", std::to_string(100 * compensated_bias.tolerance()));
  RecordProperty("mean_bandwidth", std::to_string(bandwidth.mean()));
}

// On a uniform density there is no proximity bias to find; what remains is the k-NN radius
// bias of the averaged radius at the chosen bandwidth, at most its value at n_min
// (+1.005 % at N = 50, density_estimate_test.cpp), added to the 4-sigma tolerance.
// Independent trials: a fresh Poisson disc each (radius 15: mean 707 photons,
// P(fewer than 501) < 1e-14). Measured: +0.33 %, per-estimate RMS 10 % (a fixed N = 500
// would give 4.5 %: the operator favours small bandwidths, as digest 4.7 also found), mean
// bandwidth 270.
TEST(BiasCompensation, UniformDensityIsUnbiasedWithinNoise) {
  constexpr int Trials = 3000;
  constexpr double RGen = 15.0;
  std::mt19937_64 rng(31);
  Stats value, bandwidth;
  for (int t = 0; t < Trials; ++t) {
    const PhotonMap map(poisson_disc(rng, RGen, [](double) { return Vec3{1, 1, 1}; }));
    BiasCompensationOptions options;
    options.n_min = 50;
    options.n_max = 500;
    options.max_radius_m = RGen;
    options.rng_index = static_cast<std::uint64_t>(t);
    const DensityEstimate e = estimate_irradiance_bias_compensated(map, {0, 0, 0}, all_photons(), options);
    ASSERT_LT(e.radius_m, RGen);
    value.add(e.irradiance.x);
    bandwidth.add(static_cast<double>(e.photon_count));
  }
  EXPECT_NEAR(value.mean(), 1.0, 0.01005 + value.tolerance());
  EXPECT_GT(bandwidth.mean(), 50.0);
  RecordProperty("bias_percent", std::to_string(100 * (value.mean() - 1)));
  RecordProperty("rms_percent", std::to_string(100 * value.sigma()));
  RecordProperty("mean_bandwidth", std::to_string(bandwidth.mean()));
}

// The chromatic variant (seeds/000 section 5.3, fig. 5.8): photons left of x = -8 carry
// (2, 1, 0), the others (0, 1, 2): the channel average is 1 everywhere, so only the
// per-channel test sees the boundary. Same positions and the same xi with grey photons
// (1, 1, 1) must let the operator choose smaller bandwidths with colour (paired
// difference, 4 sigma), and the red channel at the origin (true value 0) must be less
// biased than the fixed n_max estimate's. Measured: bandwidth -108 photons (4 sigma: 54);
// red 0.14 against 0.45 for fixed N = 1000 (scratch run, 1000 trials).
TEST(BiasCompensation, ChromaticBoundaryIsDetected) {
  constexpr int Trials = 500;
  constexpr double RGen = 21.0;  // mean 1385 photons; P(fewer than 1001) < 1e-9
  std::mt19937_64 rng(41);
  Stats bandwidth_difference, red_improvement;
  for (int t = 0; t < Trials; ++t) {
    std::vector<Photon> coloured = poisson_disc(rng, RGen, [](double x) {
      return x < -8.0 ? Vec3{2, 1, 0} : Vec3{0, 1, 2};
    });
    std::vector<Photon> grey = coloured;
    for (Photon& p : grey) p.flux = {1, 1, 1};
    const PhotonMap coloured_map(std::move(coloured)), grey_map(std::move(grey));
    BiasCompensationOptions options;
    options.n_min = 50;
    options.n_max = 1000;
    options.max_radius_m = RGen;
    options.rng_index = static_cast<std::uint64_t>(t);
    const DensityEstimate c =
        estimate_irradiance_bias_compensated(coloured_map, {0, 0, 0}, all_photons(), options);
    const DensityEstimate g =
        estimate_irradiance_bias_compensated(grey_map, {0, 0, 0}, all_photons(), options);
    DensityEstimateOptions fixed;
    fixed.bandwidth = 1000;
    fixed.max_radius_m = RGen;
    const DensityEstimate f = estimate_irradiance(coloured_map, {0, 0, 0}, all_photons(), fixed);
    bandwidth_difference.add(static_cast<double>(c.photon_count) - static_cast<double>(g.photon_count));
    red_improvement.add(f.irradiance.x - c.irradiance.x);
  }
  EXPECT_LT(bandwidth_difference.mean(), -bandwidth_difference.tolerance());
  EXPECT_GT(red_improvement.mean(), red_improvement.tolerance());
  RecordProperty("bandwidth_difference", std::to_string(bandwidth_difference.mean()));
  RecordProperty("bandwidth_difference_4sigma", std::to_string(bandwidth_difference.tolerance()));
}

TEST(BiasCompensation, DegenerateRangesShortLookupsAndInvalidOptions) {
  std::mt19937_64 rng(3);
  const PhotonMap map(poisson_disc(rng, 12.0, [](double x) { return Vec3{1, 0.5, x > 0 ? 2 : 0.25}; }));
  const Vec3 q{0.5, -0.25, 0};

  // n_min = n_max: no search; exactly the fixed averaged-radius estimate at n_min.
  BiasCompensationOptions options;
  options.n_min = options.n_max = 40;
  DensityEstimateOptions fixed;
  fixed.bandwidth = 40;
  fixed.radius = KernelRadius::Averaged;
  for (KernelType kernel : {KernelType::Uniform, KernelType::Silverman}) {
    options.kernel = fixed.kernel = kernel;
    const DensityEstimate b = estimate_irradiance_bias_compensated(map, q, all_photons(), options);
    const DensityEstimate f = estimate_irradiance(map, q, all_photons(), fixed);
    EXPECT_EQ(b.photon_count, 40u);
    EXPECT_EQ(b.radius_m, f.radius_m);
    EXPECT_EQ(b.irradiance, f.irradiance);
  }

  // n_max = n_min + 1 (the printed loop never ends here): one test, either bandwidth.
  options.kernel = fixed.kernel = KernelType::Uniform;
  options.n_max = 41;
  for (std::uint64_t i = 0; i < 20; ++i) {
    options.rng_index = i;
    const std::size_t n = estimate_irradiance_bias_compensated(map, q, all_photons(), options).photon_count;
    EXPECT_TRUE(n == 40u || n == 41u) << n;
  }

  // Short lookup: fewer photons than n_min within the max radius -> the fixed-radius
  // estimate over the max-radius disc, as estimate_irradiance gives.
  options.n_min = 50;
  options.n_max = 400;
  options.max_radius_m = fixed.max_radius_m = 2.5;  // about 20 photons inside
  fixed.bandwidth = 50;
  const DensityEstimate b = estimate_irradiance_bias_compensated(map, q, all_photons(), options);
  const DensityEstimate f = estimate_irradiance(map, q, all_photons(), fixed);
  EXPECT_LT(f.photon_count, 50u);
  EXPECT_EQ(b.photon_count, f.photon_count);
  EXPECT_EQ(b.radius_m, 2.5);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(b.irradiance[c], f.irradiance[c], 1e-12 * f.irradiance[c]);

  // Empty map: zero.
  const DensityEstimate none = estimate_irradiance_bias_compensated(PhotonMap{}, q, all_photons(), options);
  EXPECT_EQ(none.photon_count, 0u);
  EXPECT_EQ(none.irradiance, Vec3(0, 0, 0));

  BiasCompensationOptions bad;
  bad.n_min = 0;
  EXPECT_THROW(estimate_irradiance_bias_compensated(map, q, all_photons(), bad), std::invalid_argument);
  bad = BiasCompensationOptions{};
  bad.n_max = 10;  // below n_min = 50
  EXPECT_THROW(estimate_irradiance_bias_compensated(map, q, all_photons(), bad), std::invalid_argument);
  bad = BiasCompensationOptions{};
  bad.max_radius_m = -1;
  EXPECT_THROW(estimate_irradiance_bias_compensated(map, q, all_photons(), bad), std::invalid_argument);
  bad = BiasCompensationOptions{};
  bad.weight_power = -1;
  EXPECT_THROW(estimate_irradiance_bias_compensated(map, q, all_photons(), bad), std::invalid_argument);
}

TEST(BiasCompensation, DeterministicPerSeedAndIndexAcrossThreads) {
  const PhotonMap map = highlight_map(5);
  constexpr int Points = 40;
  auto run = [&](std::uint64_t seed, std::vector<DensityEstimate>& out) {
    out.clear();
    for (int i = 0; i < Points; ++i) {
      BiasCompensationOptions options;
      options.n_max = 1000;
      options.rng_seed = seed;
      options.rng_index = static_cast<std::uint64_t>(i);
      out.push_back(estimate_irradiance_bias_compensated(map, circle_point(i, Points, 0.3),
                                                         all_photons(), options));
    }
  };
  std::vector<DensityEstimate> reference, other_seed;
  run(1, reference);
  run(2, other_seed);
  int differing = 0;
  for (int i = 0; i < Points; ++i) differing += other_seed[i].photon_count != reference[i].photon_count;
  EXPECT_GT(differing, 0);  // xi really is drawn from the seed

  constexpr int Threads = 3;
  std::vector<std::vector<DensityEstimate>> results(Threads);
  std::vector<std::thread> threads;
  for (int t = 0; t < Threads; ++t) threads.emplace_back([&, t] { run(1, results[t]); });
  for (auto& thread : threads) thread.join();
  for (int t = 0; t < Threads; ++t)
    for (int i = 0; i < Points; ++i) {
      EXPECT_EQ(results[t][i].photon_count, reference[i].photon_count);
      EXPECT_EQ(results[t][i].irradiance, reference[i].irradiance);
    }
}

TEST(BiasCompensation, ContributionsSumToTheIrradiance) {
  std::mt19937_64 rng(17);
  std::vector<Photon> photons = poisson_disc(rng, 20.0, [](double x) { return Vec3{1, 2, x > 3 ? 4.0 : 1.0}; });
  std::uniform_int_distribution<std::uint32_t> source(0, 5);
  for (Photon& p : photons) p.source = source(rng);
  const PhotonMap map(std::move(photons));
  for (int i = 0; i < 20; ++i) {
    BiasCompensationOptions options;
    options.n_max = 800;
    options.rng_index = static_cast<std::uint64_t>(i);
    const Vec3 q{0.3 * i - 3.0, 0.1 * i, 0};
    PhotonFilter one_source = all_photons();
    one_source.source = 2;  // ignored by the contribution form
    std::vector<Vec3> per_source(6);
    const DensityEstimate c =
        estimate_contributions_bias_compensated(map, q, one_source, options, per_source);
    const DensityEstimate e = estimate_irradiance_bias_compensated(map, q, all_photons(), options);
    EXPECT_EQ(c.photon_count, e.photon_count);
    EXPECT_EQ(c.radius_m, e.radius_m);
    Vec3 sum{};
    for (const Vec3& s : per_source) sum += s;
    for (int ch = 0; ch < 3; ++ch) {
      EXPECT_NEAR(sum[ch], e.irradiance[ch], 1e-12 * e.irradiance[ch]);
      EXPECT_NEAR(c.irradiance[ch], e.irradiance[ch], 1e-12 * e.irradiance[ch]);
    }
  }
}

}  // namespace
}  // namespace dayphoton::engine
