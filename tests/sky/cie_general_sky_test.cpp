// ISO 15469 / CIE S 011 general skies against the reference table of
// ../shared/facts/sky-and-metrics.md §3.5 (D_v / Lz for all 15 types at sun altitudes
// 15..75 deg, printed to 4 decimals), the CIE 110 clear-sky formula (§3.2) for type 12, and
// the closed forms for the sun-independent types.
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

// facts §3.5 [CALC]: D_v / L_z by type (rows) and sun altitude 15, 30, 45, 60, 75 deg.
constexpr double IlluminancePerZenithLuminance[15][5] = {
    {2.4496, 2.4496, 2.4496, 2.4496, 2.4496}, {2.6615, 2.5566, 2.3635, 2.0860, 1.7465},
    {2.7700, 2.7700, 2.7700, 2.7700, 2.7700}, {3.0298, 2.8902, 2.6468, 2.3154, 1.9269},
    {3.1416, 3.1416, 3.1416, 3.1416, 3.1416}, {3.4558, 3.2779, 2.9775, 2.5842, 2.1386},
    {3.9021, 3.6731, 3.1431, 2.4213, 1.6713}, {4.4212, 4.1231, 3.3388, 2.3284, 1.4031},
    {4.8653, 4.5528, 4.0588, 3.4594, 2.8266}, {5.5938, 5.1450, 4.2535, 3.1703, 2.1391},
    {6.4518, 5.8177, 4.4854, 2.9891, 1.7468}, {7.2049, 6.3942, 4.8486, 3.1906, 1.8505},
    {8.0731, 6.9953, 4.9827, 3.0259, 1.6309}, {9.1179, 7.7083, 5.3754, 3.2170, 1.7195},
    {10.3383, 8.1162, 5.2712, 3.0159, 1.5926}};
constexpr double Altitudes[5] = {15, 30, 45, 60, 75};

/// Independent quadrature for the check below: polar coordinates about the sun (gamma, psi),
/// the horizon crossed at gamma_h = pi/2 + atan2(sin Zs cos psi, cos Zs); Simpson in gamma
/// (smooth there: the circumsolar kink is at gamma = 0, an end point), trapezoid in the
/// periodic psi.
double sun_centred_horizontal_integral(const SkyModel& sky, const Vec3& sun, int n_psi, int n_gamma) {
  const double cz = sun.z, sz = std::sqrt(std::max(0.0, 1 - cz * cz));
  Vec3 u = Vec3{0, 0, 1} - sun * cz;
  u = length(u) < 1e-9 ? Vec3{1, 0, 0} : normalize(u);
  const Vec3 v = cross(sun, u);
  double total = 0;
  for (int i = 0; i < n_psi; ++i) {
    const double psi = 2 * Pi * i / n_psi;
    const double gamma_h = 0.5 * Pi + std::atan2(sz * std::cos(psi), cz);
    const double h = gamma_h / n_gamma;
    double inner = 0;
    for (int j = 0; j <= n_gamma; ++j) {
      const double g = j * h;
      const Vec3 d = sun * std::cos(g) + (u * std::cos(psi) + v * std::sin(psi)) * std::sin(g);
      const double w = (j == 0 || j == n_gamma) ? 1 : (j % 2 ? 4 : 2);
      inner += w * sky.luminance_cd_m2(d) * std::max(0.0, d.z) * std::sin(g);
    }
    total += inner * h / 3;
  }
  return total * 2 * Pi / n_psi;
}

TEST(CieGeneralSky, AllFifteenTypesMatchTheReferenceTable) {
  // The facts table was computed on a 720 x 1440 midpoint grid and printed to 4 decimals;
  // its own error reaches 3.3e-4 (3.6e-5 relative; type 14 at 15 deg) next to the
  // circumsolar peak and 0.6e-4 for type 1, whose exact value is 2.449541 (closed form
  // below), so it is compared to 1e-4 relative -- the accuracy the quadrature must reach.
  // The tight check is the next one: an independent quadrature to 1e-6.
  for (int type = 1; type <= 15; ++type) {
    for (int k = 0; k < 5; ++k) {
      const Vec3 sun = from_altitude_azimuth(Altitudes[k], 40.0 + 57.0 * k);
      const auto sky = make_cie_general_sky(type, sun, SkyScale::zenith_luminance_cd_m2(1.0));
      const double ratio = sky->horizontal_illuminance_lux() / sky->zenith_luminance_cd_m2();
      const double table = IlluminancePerZenithLuminance[type - 1][k];
      EXPECT_NEAR(ratio / table, 1.0, 1e-4) << "type " << type << " sun altitude " << Altitudes[k];
    }
  }
}

TEST(CieGeneralSky, AllFifteenTypesMatchAnIndependentQuadrature) {
  // 360 x 500 Simpson/trapezoid nodes: converged to ~1e-9 for these skies (checked against
  // 720 x 1000); the library's adaptive Gauss-Kronrod targets 1e-7.
  for (int type = 1; type <= 15; ++type) {
    for (int k = 0; k < 5; ++k) {
      const Vec3 sun = from_altitude_azimuth(Altitudes[k], 10.0 + 71.0 * k);
      const auto sky = make_cie_general_sky(type, sun, SkyScale::zenith_luminance_cd_m2(1.0));
      const double independent = sun_centred_horizontal_integral(*sky, sun, 360, 500);
      EXPECT_NEAR(sky->horizontal_illuminance_lux() / independent, 1.0, 1e-6)
          << "type " << type << " sun altitude " << Altitudes[k];
    }
  }
}

TEST(CieGeneralSky, NormalisedToHorizontalIlluminance) {
  for (int type = 1; type <= 15; ++type) {
    const Vec3 sun = from_altitude_azimuth(33, 200);
    const auto sky = make_cie_general_sky(type, sun, SkyScale::horizontal_illuminance_lux(25000));
    EXPECT_NEAR(sky->horizontal_illuminance_lux() / 25000, 1.0, 1e-6) << "type " << type;
    // Relative luminance is 1 at the zenith by definition, so the zenith value is Lz.
    const auto unit = make_cie_general_sky(type, sun, SkyScale::zenith_luminance_cd_m2(1.0));
    EXPECT_NEAR(unit->luminance_cd_m2({0, 0, 1}), 1.0, 1e-12) << "type " << type;
    EXPECT_NEAR(rgb_to_photometric(sky->radiance_rgb(from_altitude_azimuth(20, 10))),
                sky->luminance_cd_m2(from_altitude_azimuth(20, 10)), 1e-9);
  }
}

TEST(CieGeneralSky, SunIndependentTypesHaveClosedForms) {
  // Type 5 is uniform: D_v/Lz = pi. Types 1 and 3 through E3 (the analytic value of the model).
  for (int type : {1, 3, 5}) {
    const auto sky =
        make_cie_general_sky(type, from_altitude_azimuth(50, 0), SkyScale::zenith_luminance_cd_m2(1));
    ASSERT_TRUE(sky->analytic_horizontal_illuminance_lux()) << type;
    EXPECT_NEAR(sky->horizontal_illuminance_lux() / *sky->analytic_horizontal_illuminance_lux(),
                1.0, 1e-9)
        << type;
  }
  const auto uniform = make_cie_general_sky(5, {0, 0, 1}, SkyScale::zenith_luminance_cd_m2(2));
  EXPECT_NEAR(*uniform->analytic_horizontal_illuminance_lux(), 2 * Pi, 1e-12);
  // Type 1 is close to, but not the same as, the Moon & Spencer overcast sky (7 pi / 9).
  const auto t1 = make_cie_general_sky(1, {0, 0, 1}, SkyScale::zenith_luminance_cd_m2(1));
  // 2 pi (1/2 + 4 E3(0.7)) / (1 + 4 e^-0.7) = 2.449541 (a 200 000-interval Simpson rule gives
  // 2.4495408740206); the facts table prints 2.4496 (see the reference-table test).
  EXPECT_NEAR(*t1->analytic_horizontal_illuminance_lux(), 2.4495408740206, 1e-12);
  EXPECT_GT(*t1->analytic_horizontal_illuminance_lux() - 7 * Pi / 9, 0.005);
  // The sun does not matter for them, even below the horizon.
  EXPECT_NO_THROW(make_cie_general_sky(3, from_altitude_azimuth(-20, 0), SkyScale::zenith_luminance_cd_m2(1)));
}

TEST(CieGeneralSky, Type12IsTheCie110ClearSky) {
  // CIE 110 (facts §3.2): L/Lz = (0.91 + 10 e^{-3 g} + 0.45 cos^2 g)(1 - e^{-0.32/cos z}) /
  //                             ((0.91 + 10 e^{-3 Zs} + 0.45 cos^2 Zs)(1 - e^{-0.32})).
  // ISO's indicatrix is the same with 0.91 replaced by 1 - 10 e^{-3 pi/2} = 0.910167, so the
  // two ratios differ by at most 2 * 0.000167 / 0.91 relative.
  const double shift = (1 - 10 * std::exp(-3 * Pi / 2)) - 0.91;
  const double bound = 2 * shift / 0.91 + 1e-12;
  auto cie110 = [](double zeta, double gamma, double zs) {
    auto f = [](double g) { return 0.91 + 10 * std::exp(-3 * g) + 0.45 * std::cos(g) * std::cos(g); };
    return f(gamma) * (1 - std::exp(-0.32 / std::cos(zeta))) / (f(zs) * (1 - std::exp(-0.32)));
  };
  for (double sun_alt : {10.0, 35.0, 70.0}) {
    const Vec3 sun = from_altitude_azimuth(sun_alt, 180);
    const auto sky = make_cie_general_sky(12, sun, SkyScale::zenith_luminance_cd_m2(1.0));
    for (double alt = 2; alt < 90; alt += 11) {
      for (double az = 0; az < 360; az += 29) {
        const Vec3 d = from_altitude_azimuth(alt, az);
        const double gamma = std::acos(std::clamp(dot(d, sun), -1.0, 1.0));
        const double expected = cie110(deg_to_rad(90 - alt), gamma, deg_to_rad(90 - sun_alt));
        EXPECT_NEAR(sky->luminance_cd_m2(d) / expected, 1.0, bound) << alt << " " << az;
      }
    }
  }
}

TEST(CieGeneralSky, SymmetricAboutTheSunMeridianAndBrightestNearTheSun) {
  const Vec3 sun = from_altitude_azimuth(40, 135);
  const auto sky = make_cie_general_sky(13, sun, SkyScale::zenith_luminance_cd_m2(5000));
  for (double dz : {10.0, 50.0, 120.0})
    EXPECT_NEAR(sky->luminance_cd_m2(from_altitude_azimuth(25, 135 + dz)),
                sky->luminance_cd_m2(from_altitude_azimuth(25, 135 - dz)), 1e-9);
  EXPECT_GT(sky->luminance_cd_m2(from_altitude_azimuth(41, 135)),
            sky->luminance_cd_m2(from_altitude_azimuth(41, 315)));
}

TEST(CieGeneralSky, RejectsInvalidInput) {
  const Vec3 sun = from_altitude_azimuth(30, 0);
  EXPECT_THROW(make_cie_general_sky(0, sun, SkyScale::zenith_luminance_cd_m2(1)), std::invalid_argument);
  EXPECT_THROW(make_cie_general_sky(16, sun, SkyScale::zenith_luminance_cd_m2(1)), std::invalid_argument);
  EXPECT_THROW(make_cie_general_sky(12, from_altitude_azimuth(-1, 0), SkyScale::zenith_luminance_cd_m2(1)),
               std::invalid_argument);
  EXPECT_THROW(make_cie_general_sky(12, Vec3{0, 0, 2}, SkyScale::zenith_luminance_cd_m2(1)),
               std::invalid_argument);
  EXPECT_THROW(make_cie_general_sky(12, sun, SkyScale::horizontal_illuminance_lux(-1)),
               std::invalid_argument);
  EXPECT_EQ(cie_general_sky_parameters(15).c, 24);
  EXPECT_EQ(cie_general_sky_parameters(7).e, 0.30);
}

}  // namespace
}  // namespace dayphoton::sky
