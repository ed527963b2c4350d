// Solar position front end: input checks, calendar and time-zone conversion, dispatch to
// the SPA and RADIANCE algorithms, and sunrise/transit/sunset by bisection.
// Calendar arithmetic: Meeus, Astronomical Algorithms 2nd ed. (1998) ch. 7, as restated in
// Reda & Andreas (2004) eq. 4. Conventions: ../shared/facts/sky-and-metrics.md sections 0
// and 1.2; docs/sky-geometry.md.
#include <cmath>
#include <stdexcept>
#include <string>

#include "dayphoton/core/units.h"
#include "solar_position_detail.h"

namespace dayphoton::sky {
namespace {

bool is_leap_year(int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

int days_in_month(int y, int m) {
  static constexpr int days[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return m == 2 && is_leap_year(y) ? 29 : days[m - 1];
}

void check_inputs(const SolarSite& site, int year, int month, int day, double hours) {
  if (month < 1 || month > 12)
    throw std::invalid_argument("solar position: month " + std::to_string(month) +
                                " is outside 1..12");
  if (day < 1 || day > days_in_month(year, month))
    throw std::invalid_argument("solar position: day " + std::to_string(day) +
                                " does not exist in month " + std::to_string(month) + " of " +
                                std::to_string(year));
  if (!std::isfinite(hours)) throw std::invalid_argument("solar position: time is not finite");
  if (!(site.latitude_deg >= -90.0 && site.latitude_deg <= 90.0))
    throw std::invalid_argument("solar position: latitude must lie in [-90, 90] degrees");
  if (!(site.longitude_deg >= -180.0 && site.longitude_deg <= 180.0))
    throw std::invalid_argument("solar position: longitude must lie in [-180, 180] degrees");
  if (!(std::abs(site.time_zone_h) <= 15.0))
    throw std::invalid_argument("solar position: time zone must lie in [-15, 15] hours");
  if (!std::isfinite(site.elevation_m) || !std::isfinite(site.pressure_mbar) ||
      !std::isfinite(site.temperature_c))
    throw std::invalid_argument("solar position: elevation, pressure or temperature not finite");
}

// Gregorian calendar date (and fractional hours) of a Julian day; Meeus ch. 7.
void calendar_from_julian_day(double jd, int& year, int& month, int& day, double& hours) {
  const double z = std::floor(jd + 0.5);
  const double f = jd + 0.5 - z;
  double a = z;
  if (z >= 2299161.0) {
    const double alpha = std::floor((z - 1867216.25) / 36524.25);
    a = z + 1.0 + alpha - std::floor(alpha / 4.0);
  }
  const double b = a + 1524.0;
  const double c = std::floor((b - 122.1) / 365.25);
  const double d = std::floor(365.25 * c);
  const double e = std::floor((b - d) / 30.6001);
  day = static_cast<int>(b - d - std::floor(30.6001 * e));
  month = static_cast<int>(e < 14.0 ? e - 1.0 : e - 13.0);
  year = static_cast<int>(month > 2 ? c - 4716.0 : c - 4715.0);
  hours = f * 24.0;
}

}  // namespace

namespace detail {

double wrap_360(double deg) {
  double r = std::fmod(deg, 360.0);
  if (r < 0.0) r += 360.0;
  return r;
}

double julian_day(int year, int month, double day_with_fraction) {
  int y = year, m = month;
  if (m <= 2) {
    y -= 1;
    m += 12;
  }
  double jd = std::floor(365.25 * (y + 4716)) + std::floor(30.6001 * (m + 1)) +
              day_with_fraction - 1524.5;
  if (jd > 2299160.0) {
    const double a = std::floor(y / 100.0);
    jd += 2.0 - a + std::floor(a / 4.0);
  }
  return jd;
}

double julian_day_utc(const SolarSite& site, const SolarTime& time) {
  return julian_day(time.year, time.month,
                    time.day + (time.hours_lst - site.time_zone_h) / 24.0);
}

void finish_position(SolarPosition& p) {
  const double c = std::cos(p.altitude_rad);
  p.direction = Vec3{std::sin(p.azimuth_rad) * c, std::cos(p.azimuth_rad) * c,
                     std::sin(p.altitude_rad)};
  p.sun_up = p.altitude_rad > 0.0;
  p.disc_visible = p.altitude_rad > -SunHalfAngle_rad;
}

}  // namespace detail

SolarPosition solar_position(const SolarSite& site, const SolarTime& time,
                             const SolarPositionOptions& options) {
  check_inputs(site, time.year, time.month, time.day, time.hours_lst);
  switch (options.algorithm) {
    case SolarPositionAlgorithm::Radiance:
      return detail::radiance_ies_position(
          site, radiance_day_of_year(time.month, time.day, options.radiance_series_has_leap_day),
          time.hours_lst);
    case SolarPositionAlgorithm::RadianceMichalsky:
      return detail::radiance_michalsky_position(site, detail::julian_day_utc(site, time));
    case SolarPositionAlgorithm::Spa:
      break;
  }
  const double dt = options.delta_t_s ? *options.delta_t_s
                                      : delta_t_s(time.year + (time.month - 0.5) / 12.0);
  if (!std::isfinite(dt)) throw std::invalid_argument("solar position: delta T is not finite");
  return detail::spa_position(site, detail::julian_day_utc(site, time), dt, options);
}

SolarPosition solar_position_utc(const SolarSite& site, int year, int month, int day,
                                 double hour_utc, const SolarPositionOptions& options) {
  check_inputs(site, year, month, day, hour_utc);
  const double jd_local = detail::julian_day(year, month, day + (hour_utc + site.time_zone_h) / 24.0);
  SolarTime local;
  calendar_from_julian_day(jd_local, local.year, local.month, local.day, local.hours_lst);
  return solar_position(site, local, options);
}

SunEvents sun_events(const SolarSite& site, int year, int month, int day,
                     const SolarPositionOptions& options, double horizon_altitude_deg) {
  SolarPositionOptions opt = options;
  opt.apply_refraction = false;  // events are defined on the true altitude
  auto at = [&](double t) { return solar_position(site, SolarTime{year, month, day, t}, opt); };

  // Transit: geocentric hour angle crosses zero, within +-2 h of 12 h mean solar time
  // (|equation of time| < 17 min).
  const double guess = 12.0 + site.time_zone_h - site.longitude_deg / 15.0;
  double lo = guess - 2.0, hi = guess + 2.0;
  while (hi - lo > 1e-7) {
    const double mid = 0.5 * (lo + hi);
    (at(mid).hour_angle_rad < 0.0 ? lo : hi) = mid;
  }
  SunEvents ev;
  ev.transit_h = 0.5 * (lo + hi);

  const double h0 = deg_to_rad(horizon_altitude_deg);
  auto f = [&](double t) { return at(t).true_altitude_rad - h0; };
  if (f(ev.transit_h) <= 0.0) return ev;  // polar night
  auto crossing = [&](double a, double b) {  // f(a) and f(b) of opposite signs
    const bool rising = f(a) < 0.0;
    while (b - a > 1e-7) {
      const double mid = 0.5 * (a + b);
      ((f(mid) < 0.0) == rising ? a : b) = mid;
    }
    return 0.5 * (a + b);
  };
  if (f(ev.transit_h - 12.0) < 0.0) ev.sunrise_h = crossing(ev.transit_h - 12.0, ev.transit_h);
  if (f(ev.transit_h + 12.0) < 0.0) ev.sunset_h = crossing(ev.transit_h, ev.transit_h + 12.0);
  return ev;
}

}  // namespace dayphoton::sky
