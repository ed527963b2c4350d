// SiteClock: turns hourly weather records into time steps with the project's time
// conventions (DESIGN.md §4 "Time"; docs/weather.md).
//
//  - EPW hour h (1..24) covers (h-1, h] in local STANDARD time; the sky and sun for that
//    record are evaluated at the midpoint h - 0.5 (as RADIANCE gendaymtx does with the
//    .wea time stamps written by epw2wea). Daylight saving time is never applied.
//  - Calendar: a 365-day year, or 366 days when the file holds Feb 29 (EpwFile::
//    leap_day_present). hour_of_year = (day_of_year - 1) * 24 + (hour - 1): 0..8759 or
//    0..8783.
//  - Year used for UTC / Julian day: if every record carries the same year field (an actual
//    meteorological year) that year, else (TMY files mix years) a fixed reference year:
//    2021 for 365-day files, 2020 for 366-day files. Solar position depends on the year only
//    through the ~6 h drift of the leap cycle; a fixed year keeps runs reproducible.
//  - Julian day (UT) by the Gregorian-calendar formula of Meeus, "Astronomical Algorithms"
//    (2nd ed., 1998) ch. 7; JD 2451545.0 = 2000-01-01 12:00 UT.
#pragma once

#include <vector>

#include "dayphoton/weather/epw_reader.h"
#include "dayphoton/weather/hourly_weather.h"

namespace dayphoton::weather {

/// One evaluation time of the annual simulation.
struct TimeStep {
  int month = 1;          ///< 1..12
  int day = 1;            ///< 1..31
  int hour = 1;           ///< EPW hour 1..24, covers (hour-1, hour] local standard time
  int day_of_year = 1;    ///< 1..365 (1..366 in a 366-day calendar)
  int hour_of_year = 0;   ///< 0..8759 (0..8783): (day_of_year-1)*24 + hour-1
  double hour_lst = 0.5;  ///< evaluation time: midpoint hour - 0.5, local standard time
};

/// A calendar instant in UTC.
struct UtcTime {
  int year = 2021;
  int month = 1;
  int day = 1;
  double hour = 0.0;  ///< [0, 24)
};

/// Maps records to time steps for one site and calendar.
class SiteClock {
 public:
  /// A clock for a site `time_zone_h` hours east of UTC (EPW convention, -8 = PST), with
  /// calendar year `year` for UTC/Julian-day conversion and a 366-day calendar if
  /// `leap_calendar`.
  SiteClock(double time_zone_h, int year, bool leap_calendar);

  /// The clock of an EPW file: its time zone, its calendar (366 days iff it has Feb 29) and
  /// its year if all records share one, else the reference year (2021, or 2020 if 366 days).
  static SiteClock for_epw(const EpwFile& epw);

  /// The same rule for a format-neutral series (hourly_weather.h): its site's time zone, its
  /// calendar, its records' common year (.wea records have none: the reference year).
  static SiteClock for_weather(const HourlyWeather& weather);

  /// The time step of hour `hour` (1..24) on `month`/`day`. Throws std::invalid_argument for
  /// an impossible date (including Feb 29 in a 365-day calendar).
  TimeStep step(int month, int day, int hour) const;

  /// step() for every record, in order.
  std::vector<TimeStep> steps(const std::vector<WeatherRecord>& records) const;

  /// The evaluation instant of `step` in UTC (local standard time minus the zone offset),
  /// normalised to a calendar date (may fall on the previous or next day or year).
  UtcTime utc(const TimeStep& step) const;

  /// Julian day (UT) of the evaluation instant of `step`, for solar position algorithms.
  double julian_day(const TimeStep& step) const;

  double time_zone_h() const { return m_time_zone_h; }
  int year() const { return m_year; }
  bool leap_calendar() const { return m_leap; }
  /// 8760 or 8784.
  int hours_in_year() const { return m_leap ? 8784 : 8760; }

 private:
  double m_time_zone_h;
  int m_year;
  bool m_leap;
};

/// Day of year 1..366 of `month`/`day` in a 365-day (`leap` false) or 366-day calendar.
/// Dec 31 is 365 (366 if `leap`). Returns 0 for an impossible date.
int day_of_year(int month, int day, bool leap);

/// Julian day of a Gregorian calendar date at `hour_ut` hours UT (Meeus ch. 7).
double julian_day(int year, int month, int day, double hour_ut);

}  // namespace dayphoton::weather
