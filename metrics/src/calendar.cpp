#include "dayphoton/metrics/calendar.h"

#include <algorithm>
#include <cctype>

namespace dayphoton::metrics {

namespace {

constexpr const char* WeekdayNames[7] = {"Monday", "Tuesday", "Wednesday", "Thursday",
                                         "Friday", "Saturday", "Sunday"};
constexpr int DaysBeforeMonth[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};

int modulo(int a, int n) { return ((a % n) + n) % n; }

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::optional<Weekday> parse_weekday(const std::string& text) {
  const std::string t = lower(text);
  for (int i = 0; i < 7; ++i) {
    const std::string name = lower(WeekdayNames[i]);
    if (t == name || t == name.substr(0, 3)) return static_cast<Weekday>(i);
  }
  return std::nullopt;
}

const char* weekday_name(Weekday day) { return WeekdayNames[static_cast<int>(day)]; }

std::optional<DaylightSaving> parse_daylight_saving(const std::string& text) {
  const std::string t = lower(text);
  if (t == "none") return DaylightSaving::None;
  if (t == "eu") return DaylightSaving::Eu;
  if (t == "us") return DaylightSaving::Us;
  return std::nullopt;
}

std::string describe_daylight_saving(DaylightSaving rule) {
  switch (rule) {
    case DaylightSaving::None: return "no daylight saving time (local standard time all year)";
    case DaylightSaving::Eu:
      return "EU daylight saving time: clocks one hour ahead from the last Sunday of March to the last Sunday "
             "of October, both at 01:00 UTC";
    case DaylightSaving::Us:
      return "US daylight saving time: clocks one hour ahead from the second Sunday of March at 02:00 to the "
             "first Sunday of November at 02:00 local time";
  }
  return {};
}

bool YearCalendar::has_leap_day(const std::vector<TimeStamp>& steps) {
  return std::any_of(steps.begin(), steps.end(), [](const TimeStamp& s) { return s.month == 2 && s.day == 29; });
}

int YearCalendar::day_of_year(int month, int day) const {
  return DaysBeforeMonth[month - 1] + day - 1 + (m_leap && month > 2 ? 1 : 0);
}

std::pair<int, int> YearCalendar::date(int day_of_year) const {
  const int d = modulo(day_of_year, days());
  for (int m = 12; m >= 1; --m) {
    const int first = DaysBeforeMonth[m - 1] + (m_leap && m > 2 ? 1 : 0);
    if (d >= first) return {m, d - first + 1};
  }
  return {1, 1};  // not reached: d >= 0
}

Weekday YearCalendar::weekday(int day_of_year) const {
  return static_cast<Weekday>(modulo(static_cast<int>(m_january_1) + day_of_year, 7));
}

int YearCalendar::nth(int n, Weekday day, int month) const {
  const int first = day_of_year(month, 1);
  const int offset = modulo(static_cast<int>(day) - static_cast<int>(weekday(first)), 7);
  return first + offset + 7 * (n - 1);
}

int YearCalendar::last(Weekday day, int month) const {
  const int next_month_first = month == 12 ? days() : day_of_year(month + 1, 1);
  const int last_day = next_month_first - 1;
  return last_day - modulo(static_cast<int>(weekday(last_day)) - static_cast<int>(day), 7);
}

std::optional<std::pair<double, double>> YearCalendar::daylight_saving_hours(DaylightSaving rule,
                                                                            double time_zone_h) const {
  switch (rule) {
    case DaylightSaving::None: return std::nullopt;
    case DaylightSaving::Eu: {
      // 01:00 UTC is 01:00 + time zone in local standard time.
      const double at = 1.0 + time_zone_h;
      return std::make_pair(24.0 * last(Weekday::Sunday, 3) + at, 24.0 * last(Weekday::Sunday, 10) + at);
    }
    case DaylightSaving::Us:
      // 02:00 standard time in March; 02:00 daylight time = 01:00 standard time in November.
      return std::make_pair(24.0 * nth(2, Weekday::Sunday, 3) + 2.0, 24.0 * nth(1, Weekday::Sunday, 11) + 1.0);
  }
  return std::nullopt;
}

Weekday january_1_from(Weekday start_weekday, int start_month, int start_day, bool leap_year) {
  const YearCalendar probe(Weekday::Monday, leap_year);
  const int start = probe.day_of_year(start_month, start_day);
  return static_cast<Weekday>(modulo(static_cast<int>(start_weekday) - start, 7));
}

}  // namespace dayphoton::metrics
