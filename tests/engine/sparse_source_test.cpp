// Sparse sources on a receiver plane (daylight_coefficients.h, "Sparse sources"): a source
// with far fewer photons than the others must keep its light where it falls. Photons here lie
// on deterministic lattices (no sampling noise), so the expected values are exact and the
// tolerances are those of the lattice discretisation.
//
// Plane 4 m x 4 m. Source 0, the typical one: 100 x 100 photons of equal flux over the whole
// plane (irradiance 1). Source 1, the sparse one: 10 x 20 photons over x in [0, 2] only, with
// irradiance E1(x) = 1 + 1.5 x rising 4x across its strip, nothing beyond x = 2. With the
// project bandwidth (100) a lookup of source 1 took half its photons, a disc of ~1.1 m that
// spans the strip: the fitted plane flattened the ramp and reached points at x = 3.5 that it
// never lights.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dayphoton/engine/daylight_coefficients.h"

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

DaylightCoefficients estimate(const std::vector<SensorPoint>& sensors) {
  const ReceiverPlane plane(0.8, true, {{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  std::vector<Photon> photons;
  const int n0 = 100;
  const double h0 = 4.0 / n0;
  for (int i = 0; i < n0; ++i)
    for (int j = 0; j < n0; ++j) photons.push_back(lattice_photon((i + 0.5) * h0, (j + 0.5) * h0, h0 * h0, 0));
  const int nx = 10, ny = 20;
  const double hx = 2.0 / nx, hy = 4.0 / ny;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      const double x = (i + 0.5) * hx;
      photons.push_back(lattice_photon(x, (j + 0.5) * hy, sparse_irradiance(x) * hx * hy, 1));
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
  // Sensors in the middle row (y = 2), away from the plane's edges in y.
  std::vector<SensorPoint> sensors;
  for (double x : {0.5, 1.0, 1.5, 3.0, 3.5}) sensors.push_back({{x, 2.0, 0.8}, {0, 0, 1}});
  const DaylightCoefficients c = estimate(sensors);
  for (std::size_t s = 0; s < sensors.size(); ++s) {
    const double x = sensors[s].position.x;
    // The typical source is untouched: irradiance 1 everywhere (a uniform lattice).
    EXPECT_NEAR(c.global[s * 2 + 0].x, 1.0, 0.02) << "x = " << x;
    const double e1 = c.global[s * 2 + 1].x;
    if (x > 2.0 + MaxRadiusFactor * std::sqrt(100 * 16.0 / (3.14159265 * 10000))) {
      EXPECT_EQ(e1, 0.0) << "x = " << x << ": a point the sparse source never lights";
    } else if (x < 2.0) {
      // Its own photons, 8 of them (the scaled bandwidth) about 0.2 m apart: the ramp is
      // followed within the lattice's resolution (one lattice step of E1: 0.3).
      EXPECT_NEAR(e1, sparse_irradiance(x), 0.3) << "x = " << x;
    }
  }
}

}  // namespace
}  // namespace dayphoton::engine
