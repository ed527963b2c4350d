// OccupancyPlan: the occupied hours as a user states them (docs/metrics.md, "Occupancy
// schedules"), turned into an OccupancySchedule for the time steps of one weather year:
//  - Daily: one window every day in local standard time (the LM-83 analysis period as tools
//    implement it; the project keys occupancy_start / occupancy_end);
//  - Weekly: windows per weekday (local clock time), holidays with their own windows, the
//    weekday of 1 January, optional daylight saving time;
//  - Hourly: one 0/1 value per time step (a CSV schedule).
// Occupancy is binary: every metric counts occupied hours (docs/metrics.md says why).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "dayphoton/core/source_location.h"
#include "dayphoton/metrics/calendar.h"
#include "dayphoton/metrics/illuminance_table.h"
#include "dayphoton/metrics/occupancy.h"

namespace dayphoton::metrics {

/// Occupied when start_h <= clock time < end_h; 0 <= start_h < end_h <= 24.
struct HourWindow {
  double start_h = 8;
  double end_h = 18;
};
/// The windows of one kind of day, in time order, not overlapping; empty: closed all day.
using DayHours = std::vector<HourWindow>;

/// Holidays: the days from `from` to `to` (month, day), both included; a `to` before `from`
/// runs over the end of the year (24 December to 2 January).
struct DateRange {
  int from_month = 1, from_day = 1;
  int to_month = 1, to_day = 1;
  bool contains(int month, int day) const;
};

/// What the weather file says about its calendar.
struct WeatherCalendar {
  std::optional<Weekday> january_1;  ///< from the EPW DATA PERIODS start day; nullopt if unknown
  std::string january_1_source;      ///< e.g. "DATA PERIODS of x.epw: Sunday 1/1", or why unknown
  double time_zone_h = 0;            ///< east of UTC, for the EU daylight-saving instants
};

struct OccupancyPlan {
  enum class Kind { Daily, Weekly, Hourly };
  Kind kind = Kind::Daily;

  // Daily
  HourWindow daily;  ///< default 08:00-18:00 local standard time

  // Weekly
  std::array<DayHours, 7> week;  ///< Monday .. Sunday
  DayHours holiday_hours;        ///< default closed
  std::vector<DateRange> holidays;
  std::optional<Weekday> january_1;  ///< overrides the weather file's
  DaylightSaving daylight_saving = DaylightSaving::None;

  // Hourly
  std::vector<bool> hourly;     ///< one per time step of the weather file
  std::string hourly_source;    ///< the CSV file

  /// Where the plan was written (the project's `occupancy` key), for errors found when it
  /// meets the weather file. Unknown for the default.
  SourceLocation location;

  static OccupancyPlan daily_hours(double start_h, double end_h);

  /// One line for logs and summaries, e.g. "Monday-Friday 08:00-17:00; Saturday, Sunday
  /// closed; 3 holiday periods closed; EU daylight saving time".
  std::string description() const;

  /// The occupied steps. Throws InputError (at `location`) when the plan does not fit the
  /// weather file: an hourly list of another length, or a weekly plan without a weekday of
  /// 1 January from either the plan or `calendar`.
  OccupancySchedule schedule(const std::vector<TimeStamp>& steps, const WeatherCalendar& calendar) const;

  /// The weekday of 1 January used for `calendar` (the plan's, else the weather file's),
  /// with where it came from; nullopt when neither gives one.
  std::optional<std::pair<Weekday, std::string>> january_1_of(const WeatherCalendar& calendar) const;
};

/// "08:00-18:00" (minutes shown when not whole: "07:30-16:45").
std::string format_window(const HourWindow& window);

}  // namespace dayphoton::metrics
