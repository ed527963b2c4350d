#include "dayphoton/metrics/occupancy_plan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dayphoton/core/diagnostics.h"

namespace dayphoton::metrics {

namespace {

std::string clock(double h) {
  const int minutes = static_cast<int>(std::lround(h * 60.0));
  char text[16];
  std::snprintf(text, sizeof text, "%02d:%02d", minutes / 60, minutes % 60);
  return text;
}

std::string day_hours_text(const DayHours& hours) {
  if (hours.empty()) return "closed";
  std::string s;
  for (const HourWindow& w : hours) s += (s.empty() ? "" : ", ") + format_window(w);
  return s;
}

bool same(const DayHours& a, const DayHours& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].start_h != b[i].start_h || a[i].end_h != b[i].end_h) return false;
  return true;
}

bool open_at(const DayHours& hours, double clock_h) {
  for (const HourWindow& w : hours)
    if (clock_h >= w.start_h && clock_h < w.end_h) return true;
  return false;
}

}  // namespace

std::string format_window(const HourWindow& window) { return clock(window.start_h) + "-" + clock(window.end_h); }

bool DateRange::contains(int month, int day) const {
  const int key = 100 * month + day, from = 100 * from_month + from_day, to = 100 * to_month + to_day;
  return from <= to ? (key >= from && key <= to) : (key >= from || key <= to);
}

OccupancyPlan OccupancyPlan::daily_hours(double start_h, double end_h) {
  OccupancyPlan plan;
  plan.daily = {start_h, end_h};
  return plan;
}

std::string OccupancyPlan::description() const {
  switch (kind) {
    case Kind::Daily:
      return format_window(daily) + " every day, local standard time";
    case Kind::Hourly:
      return "hourly schedule " + hourly_source;
    case Kind::Weekly: break;
  }
  // Runs of consecutive weekdays with the same hours: "Monday-Friday 08:00-17:00".
  std::string s;
  for (int i = 0; i < 7;) {
    int j = i;
    while (j + 1 < 7 && same(week[static_cast<std::size_t>(j + 1)], week[static_cast<std::size_t>(i)])) ++j;
    std::string days = weekday_name(static_cast<Weekday>(i));
    if (j > i) days += std::string(j == i + 1 ? ", " : "-") + weekday_name(static_cast<Weekday>(j));
    s += (s.empty() ? "" : "; ") + days + " " + day_hours_text(week[static_cast<std::size_t>(i)]);
    i = j + 1;
  }
  if (!holidays.empty())
    s += "; holidays (" + std::to_string(holidays.size()) + (holidays.size() == 1 ? " period) " : " periods) ") +
         day_hours_text(holiday_hours);
  s += daylight_saving == DaylightSaving::None ? "; local standard time"
       : daylight_saving == DaylightSaving::Eu ? "; local clock time with EU daylight saving time"
                                               : "; local clock time with US daylight saving time";
  return s;
}

std::optional<std::pair<Weekday, std::string>> OccupancyPlan::january_1_of(const WeatherCalendar& calendar) const {
  if (january_1) return std::make_pair(*january_1, std::string("the project"));
  if (calendar.january_1) return std::make_pair(*calendar.january_1, calendar.january_1_source);
  return std::nullopt;
}

OccupancySchedule OccupancyPlan::schedule(const std::vector<TimeStamp>& steps, const WeatherCalendar& calendar) const {
  if (kind == Kind::Daily) return OccupancySchedule::daily_hours(steps, daily.start_h, daily.end_h);
  if (kind == Kind::Hourly) {
    if (hourly.size() != steps.size())
      throw InputError(location, "the occupancy schedule " + hourly_source + " has " + std::to_string(hourly.size()) +
                                     " values but the weather file has " + std::to_string(steps.size()) +
                                     " records (one value per record, in file order)");
    return OccupancySchedule(hourly);
  }
  const auto first = january_1_of(calendar);
  if (!first)
    throw InputError(location, "the weekday of 1 January is unknown (" + calendar.january_1_source +
                                   "): write it as 'january_1: monday' (or the day it is) in the occupancy");
  const YearCalendar year(first->first, YearCalendar::has_leap_day(steps));
  const auto dst = year.daylight_saving_hours(daylight_saving, calendar.time_zone_h);
  std::vector<bool> occupied(steps.size(), false);
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const TimeStamp& st = steps[i];
    // Hours of standard time since 1 January 00:00, then of clock time.
    const double standard_h = 24.0 * year.day_of_year(st.month, st.day) + st.hour;
    const bool summer = dst && standard_h >= dst->first && standard_h < dst->second;
    const double clock_h = standard_h + (summer ? 1.0 : 0.0);
    const int day = static_cast<int>(std::floor(clock_h / 24.0));  // the clock's date (23:30 + 1 h is tomorrow)
    const double hour = clock_h - 24.0 * day;
    const auto [month, day_of_month] = year.date(day);
    const bool holiday = std::any_of(holidays.begin(), holidays.end(),
                                     [&](const DateRange& r) { return r.contains(month, day_of_month); });
    const DayHours& hours = holiday ? holiday_hours : week[static_cast<std::size_t>(year.weekday(day))];
    occupied[i] = open_at(hours, hour);
  }
  return OccupancySchedule(std::move(occupied));
}

}  // namespace dayphoton::metrics
