// RADIANCE's solar-position formulas, restated from ../shared/facts/sky-and-metrics.md
// section 1.1 (read there from RADIANCE src/gen/sun.c v2.7, 2019-11-07):
//   - the "IES handbook" set (sdec, stadj, salt, sazi) that gendaymtx always uses, with the
//     declination constant 365 (the 2019 correction of 368), no year, no refraction;
//   - Michalsky 1988, "The Astronomical Almanac's algorithm for approximate solar position
//     (1950-2050)", Solar Energy 40(3) 227-235, as sun.c applies it for gensky/gendaylit -y.
// Both give geometric altitudes; azimuth is converted from RADIANCE's "west of south" to
// clockwise from north (+180 deg). Measured differences to SPA: facts section 1.5 and
// docs/sky-geometry.md.
#include <cmath>

#include "dayphoton/core/units.h"
#include "solar_position_detail.h"

namespace dayphoton::sky {
namespace {

// Altitude and compass azimuth from declination and solar time (sun.c salt/sazi).
void altitude_azimuth(double latitude_rad, double declination_rad, double solar_time_h,
                      SolarPosition& p) {
  const double w = Pi * solar_time_h / 12.0;
  p.altitude_rad = std::asin(std::sin(latitude_rad) * std::sin(declination_rad) -
                             std::cos(latitude_rad) * std::cos(declination_rad) * std::cos(w));
  const double azimuth_west_of_south =
      -std::atan2(std::cos(declination_rad) * std::sin(w),
                  -std::cos(latitude_rad) * std::sin(declination_rad) -
                      std::sin(latitude_rad) * std::cos(declination_rad) * std::cos(w));
  p.azimuth_rad = deg_to_rad(detail::wrap_360(rad_to_deg(azimuth_west_of_south) + 180.0));
  p.true_altitude_rad = p.altitude_rad;
  p.declination_rad = declination_rad;
  p.hour_angle_rad = std::remainder(w - Pi, 2.0 * Pi);
}

}  // namespace

int radiance_day_of_year(int month, int day, bool series_has_leap_day) {
  static constexpr int cumulative[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
  const int m = month < 1 ? 1 : (month > 12 ? 12 : month);
  int j = cumulative[m - 1] + day;
  if (series_has_leap_day && m > 2) j += 1;  // 29 Feb is already 31 + 29 = 60
  return j;
}

namespace detail {

SolarPosition radiance_ies_position(const SolarSite& site, int day_of_year, double hours_lst) {
  const double J = day_of_year;
  const double declination = 0.4093 * std::sin(2.0 * Pi * (J - 81.0) / 365.0);
  // Standard meridian and longitude in RADIANCE's west-positive convention (facts section 0).
  const double meridian_west_rad = deg_to_rad(-15.0 * site.time_zone_h);
  const double longitude_west_rad = deg_to_rad(-site.longitude_deg);
  const double solar_time_h = hours_lst + 0.170 * std::sin(4.0 * Pi * (J - 80.0) / 373.0) -
                              0.129 * std::sin(2.0 * Pi * (J - 8.0) / 355.0) +
                              12.0 * (meridian_west_rad - longitude_west_rad) / Pi;
  SolarPosition p;
  altitude_azimuth(deg_to_rad(site.latitude_deg), declination, solar_time_h, p);
  finish_position(p);
  return p;
}

SolarPosition radiance_michalsky_position(const SolarSite& site, double jd_ut) {
  const double n = jd_ut - 2451545.0;  // days from 2000-01-01 12:00 UT
  const double L = wrap_360(280.460 + 0.9856474 * n);
  const double g = deg_to_rad(wrap_360(357.528 + 0.9856003 * n));
  const double lambda = deg_to_rad(L + 1.915 * std::sin(g) + 0.020 * std::sin(2.0 * g));
  const double eps = deg_to_rad(23.439 - 4e-7 * n);
  const double ra_h =
      wrap_360(rad_to_deg(std::atan2(std::sin(lambda) * std::cos(eps), std::cos(lambda)))) / 15.0;
  const double declination = std::asin(std::sin(eps) * std::sin(lambda));
  // UT hours of the instant: fractional part of the Julian day counted from midnight.
  const double jd0 = std::floor(jd_ut - 0.5) + 0.5;
  const double ut_h = (jd_ut - jd0) * 24.0;
  const double gmst_h = 6.697375 + 0.0657098242 * n + ut_h;
  const double lmst_h = gmst_h + site.longitude_deg / 15.0;
  double solar_time_h = std::fmod(lmst_h - ra_h + 12.0, 24.0);
  if (solar_time_h < 0.0) solar_time_h += 24.0;
  SolarPosition p;
  altitude_azimuth(deg_to_rad(site.latitude_deg), declination, solar_time_h, p);
  finish_position(p);
  return p;
}

}  // namespace detail
}  // namespace dayphoton::sky
