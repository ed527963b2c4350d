// Internal helpers shared by the solar-position algorithm files (not a public header).
// Calendar arithmetic: Meeus, Astronomical Algorithms (1998) ch. 7, as restated in
// Reda & Andreas (2004) eq. 4.
#pragma once

#include "dayphoton/sky/solar_position.h"

namespace dayphoton::sky::detail {

/// Julian day (UT) of a Gregorian calendar date plus a fractional day (may be < 0 or > 1).
double julian_day(int year, int month, double day_with_fraction);

/// Julian day (UT) of a site-local standard-time instant.
double julian_day_utc(const SolarSite& site, const SolarTime& time);

/// Fill direction, sun_up and disc_visible from altitude_rad and azimuth_rad.
void finish_position(SolarPosition& p);

/// Wrap an angle in degrees to [0, 360).
double wrap_360(double deg);

SolarPosition spa_position(const SolarSite& site, double jd_ut, double delta_t_s,
                           const SolarPositionOptions& options);
SolarPosition radiance_ies_position(const SolarSite& site, int day_of_year, double hours_lst);
SolarPosition radiance_michalsky_position(const SolarSite& site, double jd_ut);

}  // namespace dayphoton::sky::detail
