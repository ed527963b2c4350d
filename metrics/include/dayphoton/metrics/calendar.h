// Calendar: the weekday of every date of a weather year and the daylight-saving-time
// intervals, for occupancy schedules (docs/metrics.md, "Occupancy schedules").
//
// A weather year is the list of dates its time steps carry (month, day; a leap year when
// they include 29 February). Weekdays follow from the weekday of 1 January, which the
// caller takes from the weather file (EPW DATA PERIODS start day) or from the project.
// Days are counted from 1 January = day 0; instants are hours of local STANDARD time since
// 1 January 00:00 (the time base of the weather records).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dayphoton/metrics/illuminance_table.h"

namespace dayphoton::metrics {

enum class Weekday { Monday, Tuesday, Wednesday, Thursday, Friday, Saturday, Sunday };

/// "monday" .. "sunday" or "mon" .. "sun", any case; nullopt otherwise.
std::optional<Weekday> parse_weekday(const std::string& text);
/// "Monday" .. "Sunday".
const char* weekday_name(Weekday day);

/// Daylight saving time rules: the clock runs one hour ahead of standard time between
/// the start and end instants of each year.
///  - Eu (Directive 2000/84/EC, articles 2-3): from the last Sunday of March to the last
///    Sunday of October, both at 01:00 UTC;
///  - Us (Energy Policy Act of 2005, section 110): from the second Sunday of March at
///    02:00 local standard time to the first Sunday of November at 02:00 local daylight
///    time (01:00 standard time).
enum class DaylightSaving { None, Eu, Us };

/// "none", "eu", "us"; nullopt otherwise.
std::optional<DaylightSaving> parse_daylight_saving(const std::string& text);
/// One sentence stating the rule's dates and times.
std::string describe_daylight_saving(DaylightSaving rule);

/// The calendar of one weather year.
class YearCalendar {
 public:
  /// `leap_year`: 29 February exists (366 days).
  YearCalendar(Weekday january_1, bool leap_year) : m_january_1(january_1), m_leap(leap_year) {}
  /// A leap year when any step falls on 29 February.
  static bool has_leap_day(const std::vector<TimeStamp>& steps);

  int days() const { return m_leap ? 366 : 365; }
  /// Day of the year of month/day, 1 January = 0. Month 1..12, day 1..31 (not checked).
  int day_of_year(int month, int day) const;
  /// Month and day of a day of the year, taken modulo the year's length (day -1 is 31 December).
  std::pair<int, int> date(int day_of_year) const;
  /// Weekday of a day of the year (any integer: the weeks run on across the year's ends).
  Weekday weekday(int day_of_year) const;
  /// Daylight-saving interval [start, end) in hours of local standard time since 1 January
  /// 00:00, for a site `time_zone_h` hours east of UTC; nullopt for DaylightSaving::None.
  std::optional<std::pair<double, double>> daylight_saving_hours(DaylightSaving rule, double time_zone_h) const;

 private:
  /// Day of the year of the last `day` of a month.
  int last(Weekday day, int month) const;
  /// Day of the year of the n-th (1-based) `day` of a month.
  int nth(int n, Weekday day, int month) const;

  Weekday m_january_1;
  bool m_leap;
};

/// The weekday of 1 January, from a weather file's start date and its weekday.
Weekday january_1_from(Weekday start_weekday, int start_month, int start_day, bool leap_year);

}  // namespace dayphoton::metrics
