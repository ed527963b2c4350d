// SiteClock: record -> time step, local standard time -> UTC -> Julian day.
// Conventions and the reference-year decision: site_clock.h and docs/weather.md.
// Julian day: Meeus, "Astronomical Algorithms", 2nd ed. (1998), ch. 7 (Gregorian calendar,
// eq. 7.1 and the inverse method of the same chapter).
#include "dayphoton/weather/site_clock.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace dayphoton::weather {
namespace {

bool gregorian_leap(int year) { return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0; }

/// Julian day number (integer, the day starting at noon UT) of a Gregorian date, Meeus 7.1
/// evaluated at 12:00 UT.
long julian_day_number(int year, int month, int day) {
  return static_cast<long>(std::lround(julian_day(year, month, day, 12.0)));
}

/// Inverse of julian_day_number (Meeus ch. 7, "Calculation of the calendar date from JD").
void civil_from_julian_day_number(long jdn, int& year, int& month, int& day) {
  const long z = jdn;  // JD + 0.5 at midnight starting that day == jdn exactly
  const long alpha = static_cast<long>(std::floor((static_cast<double>(z) - 1867216.25) / 36524.25));
  const long a = z + 1 + alpha - alpha / 4;
  const long b = a + 1524;
  const long c = static_cast<long>(std::floor((static_cast<double>(b) - 122.1) / 365.25));
  const long d = static_cast<long>(std::floor(365.25 * static_cast<double>(c)));
  const long e = static_cast<long>(std::floor(static_cast<double>(b - d) / 30.6001));
  day = static_cast<int>(b - d - static_cast<long>(std::floor(30.6001 * static_cast<double>(e))));
  month = static_cast<int>(e < 14 ? e - 1 : e - 13);
  year = static_cast<int>(month > 2 ? c - 4716 : c - 4715);
}

}  // namespace

int day_of_year(int month, int day, bool leap) {
  if (month < 1 || month > 12 || day < 1 || day > days_in_month(month, leap)) return 0;
  int n = day;
  for (int m = 1; m < month; ++m) n += days_in_month(m, leap);
  return n;
}

double julian_day(int year, int month, int day, double hour_ut) {
  int y = year, m = month;
  if (m <= 2) {
    y -= 1;
    m += 12;
  }
  const int a = static_cast<int>(std::floor(y / 100.0));
  const int b = 2 - a + static_cast<int>(std::floor(a / 4.0));
  return std::floor(365.25 * (y + 4716)) + std::floor(30.6001 * (m + 1)) + day + b - 1524.5 +
         hour_ut / 24.0;
}

SiteClock::SiteClock(double time_zone_h, int year, bool leap_calendar)
    : m_time_zone_h(time_zone_h), m_year(year), m_leap(leap_calendar) {}

/// The year of a series' records: their common year, else the reference year.
static int clock_year(const std::vector<WeatherRecord>& records, bool leap) {
  int year = leap ? 2020 : 2021;
  if (!records.empty()) {
    const int first = records.front().year;
    bool uniform = true;
    for (const WeatherRecord& r : records) uniform = uniform && r.year == first;
    // An actual-year file keeps its year, unless its calendar contradicts it.
    if (uniform && first >= 1 && (!leap || gregorian_leap(first))) year = first;
  }
  return year;
}

SiteClock SiteClock::for_epw(const EpwFile& epw) {
  return SiteClock(epw.header.location.time_zone_h, clock_year(epw.records, epw.leap_day_present),
                   epw.leap_day_present);
}

SiteClock SiteClock::for_weather(const HourlyWeather& weather) {
  return SiteClock(weather.site.time_zone_h, clock_year(weather.records, weather.leap_day_present),
                   weather.leap_day_present);
}

TimeStep SiteClock::step(int month, int day, int hour) const {
  const int doy = day_of_year(month, day, m_leap);
  if (doy == 0 || hour < 1 || hour > 24)
    throw std::invalid_argument("SiteClock: no such time step " + std::to_string(month) + "/" +
                                std::to_string(day) + " hour " + std::to_string(hour) +
                                (m_leap ? " (366-day calendar)" : " (365-day calendar)"));
  TimeStep s;
  s.month = month;
  s.day = day;
  s.hour = hour;
  s.day_of_year = doy;
  s.hour_of_year = (doy - 1) * 24 + (hour - 1);
  s.hour_lst = hour - 0.5;
  return s;
}

std::vector<TimeStep> SiteClock::steps(const std::vector<WeatherRecord>& records) const {
  std::vector<TimeStep> out;
  out.reserve(records.size());
  for (const WeatherRecord& r : records) out.push_back(step(r.month, r.day, r.hour));
  return out;
}

UtcTime SiteClock::utc(const TimeStep& s) const {
  const double hour_utc = s.hour_lst - m_time_zone_h;  // zone is east positive
  const double shift_days = std::floor(hour_utc / 24.0);
  UtcTime t;
  t.hour = hour_utc - 24.0 * shift_days;
  civil_from_julian_day_number(julian_day_number(m_year, s.month, s.day) +
                                   static_cast<long>(shift_days),
                               t.year, t.month, t.day);
  return t;
}

double SiteClock::julian_day(const TimeStep& s) const {
  return weather::julian_day(m_year, s.month, s.day, s.hour_lst - m_time_zone_h);
}

}  // namespace dayphoton::weather
