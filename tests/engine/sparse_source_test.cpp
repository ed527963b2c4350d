// Sparse sources on a receiver plane (daylight_coefficients.h, "Sparse sources"): a source
// with far fewer photons than the others must keep its light where it falls.
//
// Plane 4 m x 4 m. Source 0, the typical one: 10000 photons, irradiance 1. Source 1, the
// sparse one: 200 photons over x in [0, 2] only, with irradiance E1(x) = 1 + 1.5 x rising 4x
// across its strip, nothing beyond x = 2. With the project bandwidth (100) a lookup of
// source 1 took half its photons, a disc of ~1.1 m that spans the strip: the fitted plane
// flattened the ramp and reached points at x = 3.5 that it never lights. Now its bandwidth is
// 8 (the floor) and no disc exceeds MaxRadiusFactor x the typical radius (0.90 m here).
//
// Tolerances: beyond the cap the estimate is exactly zero (no photon within reach). Inside
// the strip, the mean over 7 sensors x 64 seeds at each x is compared with E1(x) within 4
// standard errors of that mean (computed from the 64 seed means); the local-linear fit is
// exact for a linear density, so no bias allowance is added.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/random.h"

namespace dayphoton::engine {
namespace {

Photon lattice_photon(double x, double y, double flux, std::uint32_t source) {
  Photon p;
  p.position = {float(x), float(y), 0.8f};
  p.flux = {float(flux), float(flux), float(flux)};
  p.source = source;
  p.path_class = PathClass::Global;
  p.set_normal({0, 0, 1});
  return p;
}

double sparse_irradiance(double x) { return x <= 2.0 ? 1.0 + 1.5 * x : 0.0; }

DaylightCoefficients estimate(const std::vector<SensorPoint>& sensors, std::uint64_t seed) {
  const ReceiverPlane plane(0.8, true, {{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  Rng rng(seed, 0, 0, RandomStream::Emission);
  std::vector<Photon> photons;

  // Equal-flux photons at uniform random positions with density proportional to the
  // irradiance, as the forward pass stores them (a Poisson-like pattern, for which the
  // next-neighbour radius is unbiased; a lattice is not).
  for (int i = 0; i < 10000; ++i) photons.push_back(lattice_photon(4 * rng.uniform(), 4 * rng.uniform(), 16.0 / 10000, 0));
  // E1 integrates to 4 m x 5 = 20 over the strip; x from the inverse of its CDF (x + 0.75 x^2) / 5.
  for (int i = 0; i < 200; ++i) {
    const double x = (-1.0 + std::sqrt(1.0 + 15.0 * rng.uniform())) / 1.5;
    photons.push_back(lattice_photon(x, 4 * rng.uniform(), 20.0 / 200, 1));
  }
  const GridPhotons grid = GridPhotons::for_plane(plane, photons, 2);
  CoefficientOptions o;
  o.density.bandwidth = 100;
  DaylightCoefficients c;
  c.sensors = sensors.size();
  c.sources = 2;
  c.caustic.assign(c.sensors * 2, Vec3{});
  c.global.assign(c.sensors * 2, Vec3{});
  estimate_photon_coefficients(grid, sensors, o, c);
  return c;
}

TEST(SparseSources, BandwidthScalesDownWithTheSourcesCount) {
  const ReceiverPlane plane(0.8, true, {{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  std::vector<Photon> photons;
  for (int i = 0; i < 1000; ++i) photons.push_back(lattice_photon(0.002 * i + 0.001, 1, 1, 0));
  for (int i = 0; i < 1000; ++i) photons.push_back(lattice_photon(0.002 * i + 0.001, 2, 1, 1));
  for (int i = 0; i < 50; ++i) photons.push_back(lattice_photon(0.002 * i + 0.001, 3, 1, 2));
  for (int i = 0; i < 16000; ++i) photons.push_back(lattice_photon(0.0002 * i + 0.001, 0.5, 1, 3));
  const GridPhotons grid = GridPhotons::for_plane(plane, photons, 4);
  EXPECT_EQ(grid.bandwidth_of(0, 100), 100u);                    // typical (median 1000)
  EXPECT_EQ(grid.bandwidth_of(2, 100), MinimumSourceBandwidth);  // 5 -> the floor
  EXPECT_EQ(grid.bandwidth_of(3, 100), 1600u);                   // 16 x photons: 16 x bandwidth
  EXPECT_EQ(grid.bandwidth_of(2, 4), 4u);                        // the floor never exceeds the bandwidth
}

TEST(SparseSources, LightStaysWhereItFalls) {
  const std::vector<double> xs = {0.5, 1.0, 1.5, 3.0, 3.5};
  std::vector<SensorPoint> sensors;
  for (double x : xs)
    for (int j = 0; j < 7; ++j) sensors.push_back({{x, 0.5 + 0.5 * j, 0.8}, {0, 0, 1}});
  constexpr int Seeds = 64;
  const double cap_m = MaxRadiusFactor * std::sqrt(100 * 16.0 / (3.14159265358979 * 10000));
  std::vector<std::vector<double>> column_means(xs.size());
  for (int r = 0; r < Seeds; ++r) {
    const DaylightCoefficients c = estimate(sensors, 1 + static_cast<std::uint64_t>(r));
    for (std::size_t k = 0; k < xs.size(); ++k) {
      double sum = 0;
      for (int j = 0; j < 7; ++j) {
        const double e1 = c.global[(k * 7 + static_cast<std::size_t>(j)) * 2 + 1].x;
        if (xs[k] > 2.0 + cap_m) {
          EXPECT_EQ(e1, 0.0) << "x = " << xs[k] << ": a point the sparse source never lights";
        }
        sum += e1;
      }
      column_means[k].push_back(sum / 7);
    }
  }
  for (std::size_t k = 0; k < xs.size(); ++k) {
    if (xs[k] > 2.0) continue;
    double mean = 0, sq = 0;
    for (double v : column_means[k]) mean += v / Seeds;
    for (double v : column_means[k]) sq += (v - mean) * (v - mean);
    const double se = std::sqrt(sq / (Seeds - 1) / Seeds);
    EXPECT_NEAR(mean, sparse_irradiance(xs[k]), 4 * se) << "x = " << xs[k];
    EXPECT_LT(4 * se, 0.15 * sparse_irradiance(xs[k])) << "too noisy to tell a flattened ramp";
  }
}

}  // namespace
}  // namespace dayphoton::engine
