// The variance estimators of estimate_variance.h against closed forms.
//
// Kernel estimate: for a Poisson density lambda and the next-neighbour radius,
// pi lambda d_{N+1}^2 = G ~ Gamma(N + 1), the estimate is N Phi lambda / G and its variance
// (lambda Phi)^2 / (N - 1); the reported variance, the sum of the squared terms
// N Phi^2 lambda^2 / G^2, has the same mean (E[1/G^2] = 1 / (N (N - 1))). Independent trials
// (a fresh photon set each), so a mean over T trials has standard error sd / sqrt(T) with sd
// the trials' own standard deviation, and a sample variance s^2 has standard error
// sqrt((m4 - s^4) / T) (m4 the fourth central moment); tolerances are 4 of those.
//
// Stratified sampling: one jittered sample per stratum of a linear integrand f(u) = a + b u
// on [0, 1) in k strata; the estimate (1/k) sum f(u_j) has variance b^2 / (12 k^3) exactly,
// and the second differences of StratifiedVariance cancel the trend, so their mean is that
// value too (first differences would add b^2 / k^4 per pair, 6 times the variance).
#include "dayphoton/engine/estimate_variance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/density_estimate.h"

namespace dayphoton::engine {
namespace {

struct Moments {
  double mean = 0, variance = 0, fourth = 0;
};
Moments moments(const std::vector<double>& x) {
  Moments m;
  for (double v : x) m.mean += v / double(x.size());
  for (double v : x) {
    const double d = (v - m.mean) * (v - m.mean);
    m.variance += d / double(x.size() - 1);
    m.fourth += d * d / double(x.size());
  }
  return m;
}

TEST(EstimateVariance, KernelEstimateReportsItsOwnVariance) {
  constexpr std::size_t N = 50;
  constexpr int Trials = 20000;
  constexpr double RGen = 6.0;  // mean 113 photons; P(fewer than 51) < 1e-9
  const double closed_form = 1.0 / (N - 1);  // lambda = 1, Phi luminance 1
  std::mt19937_64 rng(424242);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  DensityEstimateOptions options;
  options.bandwidth = N;
  options.max_radius_m = RGen;
  std::vector<double> estimate, reported;
  for (int t = 0; t < Trials; ++t) {
    std::poisson_distribution<int> count(Pi * RGen * RGen);
    const int n = count(rng);
    std::vector<Photon> photons(static_cast<std::size_t>(n));
    for (Photon& p : photons) {
      const double r = RGen * std::sqrt(uni(rng)), phi = 2 * Pi * uni(rng);
      p.position = {static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)), 0.0f};
      p.flux = {1.0f, 1.0f, 1.0f};  // luminance 1
      p.set_normal({0, 0, 1});
    }
    const PhotonMap map(std::move(photons));
    const DensityEstimate e = estimate_irradiance(map, {0, 0, 0}, PhotonFilter{}, options);
    ASSERT_EQ(e.photon_count, N);
    estimate.push_back(luminance_of(e.irradiance));
    reported.push_back(e.luminance_variance);
  }
  const Moments r = moments(reported), x = moments(estimate);
  EXPECT_NEAR(x.mean, 1.0, 4 * std::sqrt(x.variance / Trials));
  // The reported variance is unbiased for the closed form...
  EXPECT_NEAR(r.mean, closed_form, 4 * std::sqrt(r.variance / Trials));
  // ...which is the estimates' observed variance.
  EXPECT_NEAR(x.variance, closed_form, 4 * std::sqrt((x.fourth - x.variance * x.variance) / Trials));
  std::printf("reported %.5f, observed %.5f, closed form %.5f\n", r.mean, x.variance, closed_form);
}

TEST(EstimateVariance, SecondDifferencesCancelALinearTrend) {
  constexpr int Trials = 40000;
  const double a = 0.3, b = 2.0;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (const int k : {3, 4, 8, 9}) {
    const double closed_form = b * b / (12.0 * k * k * k);
    std::vector<double> estimate, reported;
    for (int t = 0; t < Trials; ++t) {
      double variance = 0, sum = 0;
      StratifiedVariance strata(k, &variance);
      for (int j = 0; j < k; ++j) {
        const double z = (a + b * (j + uni(rng)) / k) / k;
        sum += z;
        strata.add(0, z);
      }
      estimate.push_back(sum);
      reported.push_back(variance);
    }
    const Moments r = moments(reported), x = moments(estimate);
    EXPECT_NEAR(r.mean, closed_form, 4 * std::sqrt(r.variance / Trials)) << "k = " << k;
    EXPECT_NEAR(x.variance, closed_form, 4 * std::sqrt((x.fourth - x.variance * x.variance) / Trials)) << "k = " << k;
  }
}

TEST(EstimateVariance, SharedStrataAreTakenOnTheSumAndShared) {
  // A row of 4 strata, the second credited to source 1: the runs are taken on the values
  // whatever their source, (1, 3, 1) -> (1 - 6 + 1)^2 = 16 and (3, 1, 1) -> (3 - 2 + 1)^2 = 4,
  // times 4 / 2 / 6, each shared by |c_i z_i| (c = 1, -2, 1): the first run 2/8 to source 0
  // and 6/8 to source 1, the second 3/6 to source 1 and 3/6 to source 0.
  double variance[2] = {0, 0};
  StratifiedVariance strata(4, variance);
  strata.add(0, 1.0);
  strata.add(1, 3.0);
  strata.add(0, 1.0);
  strata.add(0, 1.0);
  const double scale = 4.0 / 2.0 / 6.0;
  EXPECT_DOUBLE_EQ(variance[0], scale * (16.0 * 2.0 / 8.0 + 4.0 * 3.0 / 6.0));
  EXPECT_DOUBLE_EQ(variance[1], scale * (16.0 * 6.0 / 8.0 + 4.0 * 3.0 / 6.0));
  // Where two sources split a flat integrand, the sum has no variance: a boundary between
  // sources is not an edge.
  double flat[2] = {0, 0};
  StratifiedVariance split(6, flat);
  for (int j = 0; j < 6; ++j) split.add(j < 3 ? 0 : 1, 2.0);
  EXPECT_EQ(flat[0], 0.0);
  EXPECT_EQ(flat[1], 0.0);
  // Rows of two and of one: the pair's squared difference; the lone value's square.
  double two[1] = {0}, one[1] = {0};
  StratifiedVariance pair(2, two), single(1, one);
  pair.add(0, 1.0);
  pair.add(0, 4.0);
  single.add(0, 3.0);
  EXPECT_DOUBLE_EQ(two[0], 9.0);
  EXPECT_DOUBLE_EQ(one[0], 9.0);
}

}  // namespace
}  // namespace dayphoton::engine
