// Tests of the SkyModel interface, the hemisphere quadrature, the uniform and CIE overcast
// skies and RADIANCE's ground radiance. Oracles: closed forms (E = pi L for a uniform sky,
// E = 7 pi / 9 Lz for the overcast sky, facts §3.1; integral of exp(d theta) cos theta over the
// hemisphere), and gendaymtx's ground formula (facts §2.4 step 5, §4.3).
#include "dayphoton/sky/sky_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dayphoton/core/units.h"

namespace dayphoton::sky {
namespace {

Vec3 from_altitude_azimuth(double altitude_deg, double compass_azimuth_deg) {
  const double h = deg_to_rad(altitude_deg), az = deg_to_rad(compass_azimuth_deg);
  return {std::cos(h) * std::sin(az), std::cos(h) * std::cos(az), std::sin(h)};
}

TEST(HemisphereQuadrature, CosineIntegralIsPi) {
  const double v = integrate_cosine_weighted_hemisphere([](const Vec3&) { return 1.0; }, std::nullopt);
  EXPECT_NEAR(v, Pi, 1e-12);
}

TEST(HemisphereQuadrature, PolynomialInCosTheta) {
  // integral of cos^3 theta * cos theta d omega = 2 pi / 5.
  const double v = integrate_cosine_weighted_hemisphere(
      [](const Vec3& d) { return d.z * d.z * d.z; }, std::nullopt);
  EXPECT_NEAR(v, 2 * Pi / 5, 1e-12);
}

TEST(HemisphereQuadrature, AzimuthalHarmonicIntegratesToZero) {
  // x^2 - y^2 = sin^2 theta cos 2 phi integrates to zero over azimuth.
  const double v = integrate_cosine_weighted_hemisphere(
      [](const Vec3& d) { return 1.0 + d.x * d.x - d.y * d.y; }, from_altitude_azimuth(40, 70));
  EXPECT_NEAR(v, Pi, 1e-10);
}

TEST(HemisphereQuadrature, CircumsolarPeakAtZenith) {
  // f = exp(d gamma) with the peak at the zenith: gamma = theta and
  // integral = 2 pi (exp(d pi/2) + 1) / (d^2 + 4). The kink of the peak sits at theta = 0.
  for (double d : {-1.0, -3.0, -7.2, -15.0}) {
    const double exact = 2 * Pi * (std::exp(d * Pi / 2) + 1) / (d * d + 4);
    const double v = integrate_cosine_weighted_hemisphere(
        [d](const Vec3& dir) { return std::exp(d * std::acos(std::min(1.0, dir.z))); },
        Vec3{0, 0, 1});
    EXPECT_NEAR(v / exact, 1.0, 1e-7) << "d = " << d;
  }
}

TEST(HemisphereQuadrature, CircumsolarPeakOffZenithMatchesRotationInvariance) {
  // The hemisphere integral of a function of the angle to the sun depends on the sun's
  // altitude only; moving the sun in azimuth moves the azimuthal breakpoints, so agreement
  // between azimuths checks that the breakpoints are placed correctly.
  auto integral = [](double az) {
    const Vec3 sun = from_altitude_azimuth(20, az);
    return integrate_cosine_weighted_hemisphere(
        [sun](const Vec3& dir) {
          return std::exp(-7.0 * std::acos(std::clamp(dot(dir, sun), -1.0, 1.0)));
        },
        sun);
  };
  const double ref = integral(0);
  for (double az : {33.0, 90.0, 181.0, 300.0}) EXPECT_NEAR(integral(az) / ref, 1.0, 1e-7);
}

TEST(UniformSky, LuminanceRadianceAndIlluminance) {
  const auto sky = make_uniform_sky(1234.5);
  for (double alt : {1.0, 30.0, 89.0}) {
    const Vec3 d = from_altitude_azimuth(alt, 123);
    EXPECT_DOUBLE_EQ(sky->luminance_cd_m2(d), 1234.5);
    const Vec3 rgb = sky->radiance_rgb(d);
    EXPECT_DOUBLE_EQ(rgb.x, rgb.y);
    EXPECT_DOUBLE_EQ(rgb.y, rgb.z);
    EXPECT_NEAR(rgb_to_photometric(rgb), 1234.5, 1e-9);
  }
  EXPECT_EQ(sky->luminance_cd_m2(from_altitude_azimuth(-10, 0)), 0.0);
  ASSERT_TRUE(sky->analytic_horizontal_illuminance_lux());
  EXPECT_DOUBLE_EQ(*sky->analytic_horizontal_illuminance_lux(), Pi * 1234.5);
  EXPECT_NEAR(sky->horizontal_illuminance_lux() / (Pi * 1234.5), 1.0, 1e-10);
  EXPECT_NE(sky->description().find("uniform"), std::string::npos);
}

TEST(UniformSky, RejectsInvalidLuminance) {
  EXPECT_THROW(make_uniform_sky(-1), std::invalid_argument);
  EXPECT_THROW(make_uniform_sky(std::nan("")), std::invalid_argument);
}

TEST(CieOvercastSky, DistributionAndExactIlluminance) {
  const auto sky = make_cie_overcast_sky(SkyScale::zenith_luminance_cd_m2(3000));
  EXPECT_DOUBLE_EQ(sky->zenith_luminance_cd_m2(), 3000);
  for (double alt : {0.5, 10.0, 45.0, 80.0}) {
    const double theta = deg_to_rad(90 - alt);
    EXPECT_NEAR(sky->luminance_cd_m2(from_altitude_azimuth(alt, 77)),
                3000 * (1 + 2 * std::cos(theta)) / 3, 1e-9);
  }
  // Horizon: one third of the zenith luminance.
  EXPECT_NEAR(sky->luminance_cd_m2(from_altitude_azimuth(1e-9, 0)), 1000, 1e-6);
  EXPECT_DOUBLE_EQ(*sky->analytic_horizontal_illuminance_lux(), 7 * Pi / 9 * 3000);
  EXPECT_NEAR(sky->horizontal_illuminance_lux() / (7 * Pi / 9 * 3000), 1.0, 1e-10);
}

TEST(CieOvercastSky, FromHorizontalIlluminance) {
  const auto sky = make_cie_overcast_sky(SkyScale::horizontal_illuminance_lux(10000));
  // facts §3.1: 10 000 lx -> Lz = 4092.56 cd/m^2 (printed to 0.01).
  EXPECT_NEAR(sky->zenith_luminance_cd_m2(), 4092.56, 0.005);
  EXPECT_NEAR(sky->horizontal_illuminance_lux(), 10000, 10000 * 1e-10);
  EXPECT_NEAR(rgb_to_photometric(sky->radiance_rgb({0, 0, 1})), sky->zenith_luminance_cd_m2(), 1e-9);
  EXPECT_THROW(make_cie_overcast_sky(SkyScale::horizontal_illuminance_lux(-5)), std::invalid_argument);
}

TEST(GroundRadiance, RadianceConvention) {
  const Vec3 rho{0.2, 0.3, 0.1};
  const Vec3 sun = from_altitude_azimuth(30, 180);  // sin(altitude) = 0.5
  const Vec3 g = ground_radiance_rgb(rho, 10000, 50000, sun);
  const double grey = (10000 + 50000 * 0.5) / (Pi * 179.0);
  EXPECT_NEAR(g.x, 0.2 * grey, 1e-12);
  EXPECT_NEAR(g.y, 0.3 * grey, 1e-12);
  EXPECT_NEAR(g.z, 0.1 * grey, 1e-12);
  // Sun below the horizon: no direct contribution (gendaymtx: only if altitude > 0).
  const Vec3 below = ground_radiance_rgb(rho, 10000, 50000, from_altitude_azimuth(-2, 90));
  EXPECT_NEAR(below.x, 0.2 * 10000 / (Pi * 179.0), 1e-12);
  // A grey ground under a uniform sky: luminance rho E / pi.
  const Vec3 grey_ground = ground_radiance_rgb({0.2, 0.2, 0.2}, Pi * 1000, 0, sun);
  EXPECT_NEAR(rgb_to_photometric(grey_ground), 0.2 * 1000, 1e-9);
  EXPECT_THROW(ground_radiance_rgb({-0.1, 0, 0}, 1, 1, sun), std::invalid_argument);
  EXPECT_THROW(ground_radiance_rgb(rho, -1, 1, sun), std::invalid_argument);
}

}  // namespace
}  // namespace dayphoton::sky
