// Perez all-weather sky + Perez 1990 efficacies.
//  - Check values of ../shared/facts/sky-and-metrics.md §2.7 (Chicago, T_d = 11 C, IES sun
//    position as gendaymtx), all columns, each to one unit of its last printed digit.
//  - Normalisation: for every record of the Oakland TMY3 EPW with I + E_d > 1e-4 W/m^2, the
//    sky's horizontal illuminance equals E_d * eta_diffuse within 1e-3 relative, measured
//    both with the library's quadrature and with an integrator written here (sun-centred
//    polar coordinates, trapezoid x Simpson), independent of it.
//  - RADIANCE edge cases of facts §2.6.
// The sun position in this file is the RADIANCE "IES handbook" formula of facts §1.1
// (sun.c sdec/stadj/salt/sazi); it only has to be plausible for the normalisation test.
#include "dayphoton/sky/perez.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "dayphoton/core/units.h"

namespace dayphoton::sky {
namespace {

int julian_day(int month, int day) {
  static const int cumulative[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
  return cumulative[month - 1] + day;
}

struct SunPosition {
  double altitude_rad, compass_azimuth_rad;
  Vec3 direction;
};

/// facts §1.1, IES formulas; longitude and standard meridian in degrees WEST.
SunPosition ies_sun(double latitude_deg, double longitude_west_deg, double meridian_west_deg,
                    int jd, double standard_time_h) {
  const double lat = deg_to_rad(latitude_deg);
  const double decl = 0.4093 * std::sin(2 * Pi * (jd - 81) / 365.0);
  const double solar_time = standard_time_h + 0.170 * std::sin(4 * Pi * (jd - 80) / 373.0) -
                            0.129 * std::sin(2 * Pi * (jd - 8) / 355.0) +
                            12.0 / Pi * deg_to_rad(meridian_west_deg - longitude_west_deg);
  const double hour_angle = Pi * solar_time / 12.0;
  const double alt = std::asin(std::sin(lat) * std::sin(decl) -
                               std::cos(lat) * std::cos(decl) * std::cos(hour_angle));
  const double azi_west_of_south =
      -std::atan2(std::cos(decl) * std::sin(hour_angle),
                  -std::cos(lat) * std::sin(decl) - std::sin(lat) * std::cos(decl) * std::cos(hour_angle));
  SunPosition s;
  s.altitude_rad = alt;
  s.compass_azimuth_rad = azi_west_of_south + Pi;
  // facts §0: (-sin A cos h, -cos A cos h, sin h) with A west of south.
  s.direction = {-std::sin(azi_west_of_south) * std::cos(alt),
                 -std::cos(azi_west_of_south) * std::cos(alt), std::sin(alt)};
  return s;
}

/// Independent hemisphere integral of L cos(zeta) in polar coordinates about the sun
/// (gamma, psi), psi measured from the great circle through the zenith: for each psi the
/// horizon is crossed at
///   gamma_h = pi/2 + atan2(sin Zs cos psi, cos Zs),
/// so the inner integral over [0, gamma_h] has a smooth integrand (Simpson; the circumsolar
/// kink is at the end point gamma = 0). gamma_h(psi) turns sharply at psi = +-pi/2 when the
/// sun is on the horizon, so the outer Simpson rule has breakpoints there.
double sun_centred_horizontal_illuminance(const SkyModel& sky, const Vec3& sun, int n_psi_quarter,
                                          int n_gamma) {
  const double cz = std::clamp(sun.z, 0.0, 1.0), sz = std::sqrt(1 - cz * cz);
  // Orthonormal frame: w = sun, u = toward the zenith (perpendicular to w), v = w x u.
  const Vec3 w = sun;
  Vec3 u = Vec3{0, 0, 1} - w * cz;
  if (length(u) < 1e-9) u = Vec3{1, 0, 0};
  u = normalize(u);
  const Vec3 v = cross(w, u);
  auto simpson_weight = [](int j, int n) { return (j == 0 || j == n) ? 1.0 : (j % 2 ? 4.0 : 2.0); };
  // Nodes are clustered toward the horizon end of each gamma range (gamma = gamma_h sin(pi t/2))
  // and toward both ends of each psi quarter (psi = start + pi/4 (1 - cos(pi t))), where the
  // near-horizon gradation and gamma_h(psi) vary fastest; Simpson in t.
  auto inner = [&](double psi) {
    const double gamma_h = 0.5 * Pi + std::atan2(sz * std::cos(psi), cz);
    if (gamma_h <= 0) return 0.0;
    const double dt = 1.0 / n_gamma;
    double sum = 0;
    for (int j = 0; j <= n_gamma; ++j) {
      const double t = j * dt;
      const double g = gamma_h * std::sin(0.5 * Pi * t);
      const double jacobian = gamma_h * 0.5 * Pi * std::cos(0.5 * Pi * t);
      const Vec3 d = w * std::cos(g) + (u * std::cos(psi) + v * std::sin(psi)) * std::sin(g);
      sum += simpson_weight(j, n_gamma) * jacobian * sky.luminance_cd_m2(d) * std::max(0.0, d.z) *
             std::sin(g);
    }
    return sum * dt / 3;
  };
  double total = 0;
  const double dt = 1.0 / n_psi_quarter;
  for (int quarter = 0; quarter < 4; ++quarter) {
    const double start = -Pi + quarter * 0.5 * Pi;
    for (int i = 0; i <= n_psi_quarter; ++i) {
      const double t = i * dt;
      const double psi = start + 0.25 * Pi * (1 - std::cos(Pi * t));
      const double jacobian = 0.25 * Pi * Pi * std::sin(Pi * t);
      if (jacobian > 0) total += simpson_weight(i, n_psi_quarter) * jacobian * inner(psi);
    }
  }
  return total * dt / 3;
}

// ---- facts §2.7 check values -------------------------------------------------------------

struct CheckCase {
  const char* name;
  int month, day;
  double hour, dni, dhi;
  double h_deg, az_deg, m, e0, eps, delta;
  int bin;
  double eta_diff, e_dv;
  double eta_dir, e_nv;  // eta_dir < 0: not printed ("--")
  double a, b, c, d, e;
};

const CheckCase Cases[] = {
    {"Jan 1 11.5h", 1, 1, 11.5, 521, 144, 24.7414, 173.5555, 2.37662, 1.035050, 2.42547, 0.24188, 5,
     136.786, 19697, 88.863, 46298, -0.970332, -0.516634, 12.346938, -3.227006, 0.038930},
    {"Jun 21 12.5h overcast", 6, 21, 12.5, 0, 150, 69.9400, 205.4024, 1.06381, 0.967443, 1.00000,
     0.12066, 1, 126.433, 18965, -1, 0, 1.169165, -0.618316, 0.330505, -0.279733, -0.035035},
    {"Jun 21 12.5h clear", 6, 21, 12.5, 850, 100, 69.9400, 205.4024, 1.06381, 0.967443, 9.13649,
     0.08044, 8, 130.519, 13052, 103.624, 88080, -0.995504, -0.221866, 23.835925, -5.997978,
     1.440218},
};

TEST(PerezSky, CheckValuesOfTheFactsSheet) {
  for (const CheckCase& k : Cases) {
    SCOPED_TRACE(k.name);
    // Chicago 41.98 N, 87.92 W, TZ -6 -> standard meridian 90 W.
    const SunPosition sun = ies_sun(41.98, 87.92, 90.0, julian_day(k.month, k.day), k.hour);
    EXPECT_NEAR(rad_to_deg(sun.altitude_rad), k.h_deg, 1e-4);
    EXPECT_NEAR(rad_to_deg(sun.compass_azimuth_rad), k.az_deg, 1e-4);

    PerezInputs in;
    in.direct_normal_irradiance_W_m2 = k.dni;
    in.diffuse_horizontal_irradiance_W_m2 = k.dhi;
    in.sun_direction = sun.direction;
    in.day_of_year = julian_day(k.month, k.day);
    in.dew_point_C = 11.0;
    const PerezSky p = make_perez_sky(in);
    const PerezState& s = p.state;
    EXPECT_NEAR(s.air_mass, k.m, 1e-5);
    EXPECT_NEAR(s.eccentricity, k.e0, 1e-6);
    EXPECT_NEAR(s.epsilon, k.eps, 1e-5);
    EXPECT_NEAR(s.delta, k.delta, 1e-5);
    EXPECT_EQ(s.bin, k.bin);
    EXPECT_NEAR(s.diffuse_efficacy_lm_W, k.eta_diff, 1e-3);
    EXPECT_NEAR(s.diffuse_horizontal_illuminance_lux, k.e_dv, 1.0);
    if (k.eta_dir >= 0) {
      EXPECT_NEAR(s.direct_efficacy_lm_W, k.eta_dir, 1e-3);
      EXPECT_NEAR(s.direct_normal_illuminance_lux, k.e_nv, 1.0);
    } else {
      EXPECT_EQ(s.direct_normal_illuminance_lux, 0.0);
    }
    EXPECT_NEAR(s.a, k.a, 1e-6);
    EXPECT_NEAR(s.b, k.b, 1e-6);
    EXPECT_NEAR(s.c, k.c, 1e-6);
    EXPECT_NEAR(s.d, k.d, 1e-6);
    EXPECT_NEAR(s.e, k.e, 1e-6);
    EXPECT_FALSE(s.sun_zenith_clamped);
    EXPECT_NEAR(p.sky->horizontal_illuminance_lux() / k.e_dv, 1.0, 1.0 / k.e_dv + 1e-6);
  }
  // The Jan 1 case has 1.065 < eps < 2.8 and Delta = 0.24 >= 0.2: no raise.
  PerezInputs in;
  in.direct_normal_irradiance_W_m2 = 521;
  in.diffuse_horizontal_irradiance_W_m2 = 144;
  in.sun_direction = ies_sun(41.98, 87.92, 90.0, 1, 11.5).direction;
  EXPECT_FALSE(perez_state(in).delta_raised_to_0_2);
  EXPECT_TRUE(perez_state(in).dew_point_defaulted);
  EXPECT_NEAR(perez_state(in).precipitable_water_cm, 2.0037, 1e-4);  // facts §2.1
}

// ---- normalisation over a real weather year ------------------------------------------------

struct EpwRecord {
  int month, day, hour;
  double dew_point_C, dni, dhi;
  bool dew_point_missing;
};

/// Tiny EPW reader for this test only: 8 header lines, then month (1), day (2), hour (3),
/// dew point (7), DNI (14), DHI (15). Not the project's weather reader.
std::vector<EpwRecord> read_epw(const std::string& path, double& latitude, double& longitude_east,
                                double& time_zone) {
  std::ifstream file(path);
  std::vector<EpwRecord> records;
  std::string line;
  int line_number = 0;
  while (std::getline(file, line)) {
    ++line_number;
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string field;
    while (std::getline(ss, field, ',')) f.push_back(field);
    if (line_number == 1) {
      latitude = std::stod(f.at(6));
      longitude_east = std::stod(f.at(7));
      time_zone = std::stod(f.at(8));
      continue;
    }
    if (line_number <= 8) continue;
    EpwRecord r;
    r.month = std::stoi(f.at(1));
    r.day = std::stoi(f.at(2));
    r.hour = std::stoi(f.at(3));
    r.dew_point_C = std::stod(f.at(7));
    r.dew_point_missing = r.dew_point_C >= 99.9;
    r.dni = std::stod(f.at(14));
    r.dhi = std::stod(f.at(15));
    records.push_back(r);
  }
  return records;
}

TEST(PerezSky, NormalisationOverTheOaklandYear) {
  const std::string path = std::string(DAYPHOTON_SOURCE_DIR) + "/projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw";
  ASSERT_TRUE(std::ifstream(path)) << "missing " << path;
  double lat = 0, lon_east = 0, tz = 0;
  const std::vector<EpwRecord> records = read_epw(path, lat, lon_east, tz);
  ASSERT_EQ(records.size(), 8760u);

  int daytime = 0, independent_checks = 0, bins[9] = {0}, raised = 0, b_clamped = 0, below = 0;
  double worst_library = 0, worst_independent = 0;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const EpwRecord& r = records[i];
    if (r.dni + r.dhi <= 1e-4) continue;
    ++daytime;
    const int jd = julian_day(r.month, r.day);
    // EPW hour h covers (h-1, h]: the sun at its midpoint, local standard time (DESIGN §4).
    const SunPosition sun = ies_sun(lat, -lon_east, -15.0 * tz, jd, r.hour - 0.5);
    PerezInputs in;
    in.direct_normal_irradiance_W_m2 = r.dni;
    in.diffuse_horizontal_irradiance_W_m2 = r.dhi;
    in.sun_direction = sun.direction;
    in.day_of_year = jd;
    if (!r.dew_point_missing) in.dew_point_C = r.dew_point_C;
    const PerezSky p = make_perez_sky(in);
    const double target = p.state.diffuse_horizontal_illuminance_lux;
    ASSERT_NEAR(target, r.dhi * p.state.diffuse_efficacy_lm_W, 1e-9 * target);
    ++bins[p.state.bin];
    raised += p.state.delta_raised_to_0_2;
    b_clamped += p.state.b_positive_clamped;
    below += sun.altitude_rad <= 0;
    if (target == 0) {
      EXPECT_EQ(p.sky->luminance_cd_m2({0, 0, 1}), 0.0);
      continue;
    }
    // The library's own quadrature repeats the normalising one (deterministic), so it checks
    // only the scaling; every 10th record is enough for that.
    if (daytime % 10 == 0) {
      const double library = p.sky->horizontal_illuminance_lux();
      worst_library = std::max(worst_library, std::abs(library / target - 1));
      EXPECT_NEAR(library / target, 1.0, 1e-3) << r.month << "/" << r.day << " " << r.hour;
    }
    // Independent integrator, 4 x 40 x 120 nodes: its own error here is below 1e-4.
    const Vec3 model_sun = p.sky->sun_direction().value_or(Vec3{0, 0, 1});
    const double independent = sun_centred_horizontal_illuminance(*p.sky, model_sun, 40, 120);
    worst_independent = std::max(worst_independent, std::abs(independent / target - 1));
    EXPECT_NEAR(independent / target, 1.0, 1e-3) << r.month << "/" << r.day << " " << r.hour;
    ++independent_checks;
  }
  std::printf("Oakland: %d records with daylight (%d with the sun below the horizon), %d checked "
              "independently; worst |E/E_target - 1|: library %.2e, independent %.2e; "
              "Delta raised to 0.2: %d, b > 0 clamped: %d; bins:",
              daytime, below, independent_checks, worst_library, worst_independent, raised, b_clamped);
  for (int b = 1; b <= 8; ++b) std::printf(" %d", bins[b]);
  std::printf("\n");
  EXPECT_GT(daytime, 4000);
  for (int b = 1; b <= 8; ++b) EXPECT_GT(bins[b], 0) << "bin " << b << " never occurs";
}

// ---- edge cases (facts §2.6) -----------------------------------------------------------

PerezInputs inputs(double dni, double dhi, double altitude_deg, double azimuth_deg = 180) {
  PerezInputs in;
  in.direct_normal_irradiance_W_m2 = dni;
  in.diffuse_horizontal_irradiance_W_m2 = dhi;
  const double h = deg_to_rad(altitude_deg), az = deg_to_rad(azimuth_deg);
  in.sun_direction = {std::cos(h) * std::sin(az), std::cos(h) * std::cos(az), std::sin(h)};
  in.day_of_year = 100;
  return in;
}

TEST(PerezSky, NightIsAZeroSky) {
  const PerezSky p = make_perez_sky(inputs(0, 0, -10));
  EXPECT_TRUE(p.state.night);
  EXPECT_EQ(p.sky->luminance_cd_m2({0, 0, 1}), 0.0);
  EXPECT_EQ(p.sky->horizontal_illuminance_lux(), 0.0);
}

TEST(PerezSky, ZeroDiffuseClampsEpsilonAndDelta) {
  const PerezSky p = make_perez_sky(inputs(800, 0, 50));
  EXPECT_TRUE(std::isinf(p.state.epsilon_unclamped));
  EXPECT_EQ(p.state.epsilon, 11.9);
  EXPECT_TRUE(p.state.epsilon_clamped);
  EXPECT_EQ(p.state.delta, 0.01);
  EXPECT_TRUE(p.state.delta_clamped);
  EXPECT_EQ(p.state.bin, 8);
  EXPECT_EQ(p.state.diffuse_horizontal_illuminance_lux, 0.0);
  EXPECT_GT(p.state.direct_normal_illuminance_lux, 0.0);
  EXPECT_EQ(p.sky->luminance_cd_m2({0, 0, 1}), 0.0);
}

TEST(PerezSky, SunBelowHorizonUsesZenith90) {
  const PerezSky p = make_perez_sky(inputs(30, 20, -3, 100));
  EXPECT_TRUE(p.state.sun_zenith_clamped);
  EXPECT_DOUBLE_EQ(p.state.sun_zenith_rad, 0.5 * Pi);
  EXPECT_NEAR(p.state.model_sun_direction.z, 0.0, 1e-15);
  EXPECT_TRUE(p.state.sun_below_horizon_with_direct);
  EXPECT_NEAR(p.state.air_mass, 1.0 / (0.15 * std::pow(3.885, -1.253)), 1e-12);  // m(90 deg)
  EXPECT_NEAR(p.sky->horizontal_illuminance_lux() / p.state.diffuse_horizontal_illuminance_lux, 1.0, 1e-5);
  // The model sun keeps the azimuth: brighter toward it than away from it.
  const double a = deg_to_rad(100);
  EXPECT_GT(p.sky->luminance_cd_m2(normalize(Vec3{std::sin(a), std::cos(a), 0.1})),
            p.sky->luminance_cd_m2(normalize(Vec3{-std::sin(a), -std::cos(a), 0.1})));
}

TEST(PerezSky, HighSunIsLimitedTo87Degrees) {
  const PerezSky p = make_perez_sky(inputs(900, 100, 89, 30));
  EXPECT_TRUE(p.state.sun_zenith_clamped);
  EXPECT_NEAR(rad_to_deg(p.state.sun_zenith_rad), 3.0, 1e-12);
  EXPECT_NEAR(rad_to_deg(std::acos(p.state.model_sun_direction.z)), 3.0, 1e-9);
  const PerezSky zenith = make_perez_sky(inputs(900, 100, 90));
  EXPECT_NEAR(length(zenith.state.model_sun_direction), 1.0, 1e-12);
}

TEST(PerezSky, DeltaRaisedForIntermediateClearness) {
  // Choose E_d so that Delta < 0.2 and I so that 1.065 < eps < 2.8.
  const PerezState s = perez_state(inputs(100, 60, 40));
  ASSERT_GT(s.epsilon, 1.065);
  ASSERT_LT(s.epsilon, 2.8);
  ASSERT_LT(s.delta, 0.2);
  EXPECT_TRUE(s.delta_raised_to_0_2);
  EXPECT_EQ(s.delta_luminance, 0.2);
  // The efficacies keep the unraised Delta.
  EXPECT_NEAR(s.diffuse_efficacy_lm_W,
              perez_diffuse_efficacy_lm_W(s.bin, s.precipitable_water_cm, s.sun_zenith_rad, s.delta), 1e-12);
}

TEST(PerezSky, ClearnessBins) {
  EXPECT_EQ(perez_clearness_bin(1.0), 1);
  EXPECT_EQ(perez_clearness_bin(1.0649), 1);
  EXPECT_EQ(perez_clearness_bin(1.065), 2);
  EXPECT_EQ(perez_clearness_bin(2.8), 6);
  EXPECT_EQ(perez_clearness_bin(6.2), 8);
  EXPECT_EQ(perez_clearness_bin(11.9), 8);
}

TEST(PerezSky, RadianceIsGreyAndMatchesLuminance) {
  const PerezSky p = make_perez_sky(inputs(600, 120, 35, 200));
  const Vec3 d = normalize(Vec3{0.3, -0.5, 0.6});
  const Vec3 rgb = p.sky->radiance_rgb(d);
  EXPECT_DOUBLE_EQ(rgb.x, rgb.z);
  EXPECT_NEAR(rgb_to_photometric(rgb), p.sky->luminance_cd_m2(d), 1e-9 * p.sky->luminance_cd_m2(d));
  EXPECT_EQ(p.sky->luminance_cd_m2({0.6, 0, -0.8}), 0.0);
  EXPECT_NE(p.sky->description().find("bin"), std::string::npos);
}

TEST(PerezSky, RejectsInvalidInputs) {
  EXPECT_THROW(perez_state(inputs(-1, 10, 30)), std::invalid_argument);
  EXPECT_THROW(perez_state(inputs(10, std::nan(""), 30)), std::invalid_argument);
  PerezInputs bad = inputs(10, 10, 30);
  bad.day_of_year = 0;
  EXPECT_THROW(perez_state(bad), std::invalid_argument);
  bad = inputs(10, 10, 30);
  bad.sun_direction = {0, 0, 0.5};
  EXPECT_THROW(perez_state(bad), std::invalid_argument);
}

}  // namespace
}  // namespace dayphoton::sky
