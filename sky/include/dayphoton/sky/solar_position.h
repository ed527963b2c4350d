// Solar position: where the sun is for a site and a local-standard-time instant.
//
// Three algorithms behind one call (see docs/sky-geometry.md for the measured differences):
//   - Spa: NREL Solar Position Algorithm, Reda & Andreas, Solar Energy 76(5) 577-589 (2004),
//     NREL/TP-560-34302 rev. 2008; stated accuracy +-0.0003 deg for years -2000..6000.
//     Topocentric (parallax) altitude; atmospheric refraction optional (off by default).
//   - Radiance: the "IES handbook" formulas of RADIANCE src/gen/sun.c (sdec, stadj, salt,
//     sazi) that gendaymtx always uses; no year, no refraction, ~1 deg altitude error.
//     Use it to reproduce gendaymtx sky matrices bin for bin.
//   - RadianceMichalsky: Michalsky 1988 (Solar Energy 40(3)), as RADIANCE sun.c uses it for
//     gensky/gendaylit -y; ~0.01 deg for 1950-2050; geometric altitude.
// Formulas and published numbers: ../shared/facts/sky-and-metrics.md section 1.
//
// Conventions (facts section 0): latitude north +, longitude EAST + (EPW; RADIANCE's west +
// is converted inside), time zone in hours east of UTC (EPW: -5 for EST), times are local
// STANDARD time (no DST). Azimuth is measured clockwise from north (east = pi/2), the
// direction vector uses RADIANCE axes +X east, +Y north, +Z up.
#pragma once

#include <optional>

#include "dayphoton/core/vec3.h"

namespace dayphoton::sky {

enum class SolarPositionAlgorithm { Spa, Radiance, RadianceMichalsky };

/// Observer. Elevation, pressure and temperature only affect SPA (parallax, refraction).
struct SolarSite {
  double latitude_deg = 0.0;   ///< north positive
  double longitude_deg = 0.0;  ///< EAST positive
  double time_zone_h = 0.0;    ///< standard time offset from UTC, east positive (EPW)
  double elevation_m = 0.0;
  double pressure_mbar = 1013.25;
  double temperature_c = 12.0;
};

/// A local-standard-time instant. hours_lst may lie outside [0, 24): it is then counted
/// from midnight of the given date (SPA and Michalsky roll the date; the RADIANCE IES mode
/// keeps the day of year of the given date, as gendaymtx does with its .wea hours).
struct SolarTime {
  int year = 2001;
  int month = 1;  ///< 1..12
  int day = 1;    ///< 1..31
  double hours_lst = 12.0;
};

struct SolarPositionOptions {
  SolarPositionAlgorithm algorithm = SolarPositionAlgorithm::Spa;
  /// SPA only: add atmospheric refraction (Bennett formula with pressure and temperature,
  /// as in SPA step 3.14) to give the apparent altitude. RADIANCE modes never refract.
  bool apply_refraction = false;
  /// SPA only: refraction at the horizon (deg) that decides whether refraction is applied
  /// (the sun's upper limb must be above -(0.26667 + this)); SPA's default 0.5667.
  double horizon_refraction_deg = 0.5667;
  /// SPA only: Delta T = TT - UT1 in seconds; default delta_t_s(year + (month - 0.5)/12).
  std::optional<double> delta_t_s;
  /// Radiance (IES) mode only: the time series contains a 29 February record, so (like
  /// gendaymtx) 29 Feb is day 60 and every later day of the year is shifted by one.
  bool radiance_series_has_leap_day = false;
};

struct SolarPosition {
  double altitude_rad = 0.0;  ///< apparent if refraction was applied, else true/geometric
  double true_altitude_rad = 0.0;  ///< without refraction (== altitude_rad for RADIANCE)
  double azimuth_rad = 0.0;        ///< clockwise from north, [0, 2 pi)
  Vec3 direction;                  ///< unit vector to the sun from altitude_rad/azimuth_rad
  double declination_rad = 0.0;    ///< geocentric (SPA step 3.10)
  double hour_angle_rad = 0.0;     ///< geocentric local hour angle, [-pi, pi], 0 at transit
  bool sun_up = false;             ///< centre of the disc above the horizon: altitude_rad > 0
  /// Any part of the 0.533 deg disc above the horizon: altitude_rad > -0.2665 deg
  /// (gendaymtx's sun-up test, facts section 1.2).
  bool disc_visible = false;
};

/// Half-angle of the solar disc used by RADIANCE (facts section 0), radians.
constexpr double SunHalfAngle_rad = 0.2665 * 3.14159265358979323846 / 180.0;

/// Solar position for a site and local-standard-time instant. Throws std::invalid_argument
/// for a month/day outside the calendar or a non-finite input.
SolarPosition solar_position(const SolarSite& site, const SolarTime& time,
                             const SolarPositionOptions& options = {});

/// Same, with the instant given in UTC (hour_utc fractional); converted with site.time_zone_h.
SolarPosition solar_position_utc(const SolarSite& site, int year, int month, int day,
                                 double hour_utc, const SolarPositionOptions& options = {});

/// Delta T = TT - UT1 (s) from the Espenak & Meeus (NASA, 2006) polynomials, valid
/// 1800-2150 (the long-term parabola -20 + 32 u^2 outside), decimal year y.
double delta_t_s(double decimal_year);

/// Sunrise, solar transit and sunset of one local standard date, in local standard hours
/// (may fall outside [0, 24) for sites far from their zone meridian). Rise and set are the
/// instants where the true (unrefracted) altitude of the disc centre equals
/// horizon_altitude_deg: -0.8333 deg (upper limb on the horizon with 0.5667 deg refraction,
/// the SPA definition). Transit: local hour angle zero. Found by bisection to < 0.01 s.
/// Empty optionals in polar day / night.
struct SunEvents {
  std::optional<double> sunrise_h;
  double transit_h = 12.0;
  std::optional<double> sunset_h;
};
SunEvents sun_events(const SolarSite& site, int year, int month, int day,
                     const SolarPositionOptions& options = {},
                     double horizon_altitude_deg = -0.8333);

/// Day of year as RADIANCE's jdate(): non-leap cumulative month table + day (1..365);
/// with series_has_leap_day, 29 Feb -> 60 and later days +1 (gendaymtx).
int radiance_day_of_year(int month, int day, bool series_has_leap_day = false);

}  // namespace dayphoton::sky
