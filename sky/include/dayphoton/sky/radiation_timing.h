// The clock of a weather file's radiation against the sun's (docs/weather.md, "The records'
// clock against the sun").
//
// An hourly record's sun is computed at its mid-hour on the clock its header names
// (weather/site_clock.h). Files whose radiation is stamped on another clock read without an
// error, yet every hour's sun then stands where it was an hour (or a fraction of one) before
// or after the light was measured: EPW files written from satellite or reanalysis data in UTC
// with a local zone in the header (PVGIS, ERA5 converters), data in true solar time (older
// test reference years), records stamped in daylight-saving time, or a converter that moved
// every record by an hour. The direct sun then lands elsewhere in the room and the annual
// metrics move, silently.
//
// The radiation of a day with the sun shining is near symmetric about the sun's transit, so
// the irradiance-weighted mean hour angle of the clearest days measures the offset: the
// weighted mean of the hours from transit of the records' mid-hours, weighted by DNI + DHI,
// over the ClearDayShare of the days with the most direct normal irradiation (clouds that
// favour the afternoon or the morning shift a cloudy day's light; they shift a clear day's
// little). Measured on the files at hand (docs/validation.md, "The records' clock against the
// sun"): Oakland TMY3 -0.08 h, and its records moved by one hour -1.08 h and +0.92 h.
#pragma once

#include <cstddef>

#include "dayphoton/sky/solar_position.h"
#include "dayphoton/weather/hourly_weather.h"

namespace dayphoton::sky {

/// The share of a file's days, those with the most direct normal irradiation, whose
/// radiation is weighed.
constexpr double ClearDayShare = 0.2;

/// Fewer clear days than this (a file of a few weeks, a polar file) give no measure.
constexpr std::size_t RadiationTimingMinimumDays = 10;

struct RadiationTiming {
  bool measured = false;     ///< enough days with direct light
  double offset_h = 0.0;     ///< mean hours from transit of the clear days' radiation (+: after transit)
  std::size_t days = 0;      ///< clear days weighed
};

/// The offset of `weather`'s radiation from the sun's transit at `site` (on the file's clock;
/// std::invalid_argument for a site on another), with NREL SPA's hour angle at each record's
/// mid-hour.
RadiationTiming radiation_timing(const weather::HourlyWeather& weather, const SolarSite& site);

}  // namespace dayphoton::sky
