// SiteClock: midpoints, day of year, hour index, leap calendar, UTC and Julian day.
// Julian-day checks are Meeus, "Astronomical Algorithms" 2nd ed., ch. 7 (J2000.0 and
// Example 7.a) and the USNO value for 2021-01-01 0h UT.
#include "dayphoton/weather/site_clock.h"

#include <gtest/gtest.h>

#include <fstream>

#include "epw_test_support.h"

namespace dayphoton::weather {
namespace {

TEST(SiteClock, MidpointsAndHourIndex) {
  const SiteClock clock(-8.0, 2021, false);
  const TimeStep first = clock.step(1, 1, 1);
  EXPECT_EQ(first.hour_lst, 0.5);
  EXPECT_EQ(first.day_of_year, 1);
  EXPECT_EQ(first.hour_of_year, 0);
  const TimeStep noon = clock.step(1, 1, 12);
  EXPECT_EQ(noon.hour_lst, 11.5);  // EPW hour 12 covers (11, 12]
  const TimeStep last = clock.step(12, 31, 24);
  EXPECT_EQ(last.day_of_year, 365);
  EXPECT_EQ(last.hour_of_year, 8759);
  EXPECT_EQ(last.hour_lst, 23.5);
  EXPECT_EQ(clock.step(3, 1, 1).day_of_year, 60);
  EXPECT_EQ(clock.hours_in_year(), 8760);
  EXPECT_THROW(clock.step(2, 29, 1), std::invalid_argument);
  EXPECT_THROW(clock.step(1, 1, 0), std::invalid_argument);
  EXPECT_THROW(clock.step(13, 1, 1), std::invalid_argument);
}

TEST(SiteClock, LeapCalendar) {
  const SiteClock clock(1.0, 2020, true);
  EXPECT_EQ(clock.step(2, 29, 1).day_of_year, 60);
  EXPECT_EQ(clock.step(3, 1, 1).day_of_year, 61);
  EXPECT_EQ(clock.step(12, 31, 24).day_of_year, 366);
  EXPECT_EQ(clock.step(12, 31, 24).hour_of_year, 8783);
  EXPECT_EQ(clock.hours_in_year(), 8784);
  EXPECT_EQ(day_of_year(12, 31, false), 365);
  EXPECT_EQ(day_of_year(12, 31, true), 366);
  EXPECT_EQ(day_of_year(2, 29, false), 0);
}

TEST(SiteClock, JulianDayMatchesPublishedValues) {
  EXPECT_DOUBLE_EQ(julian_day(2000, 1, 1, 12.0), 2451545.0);            // J2000.0
  EXPECT_NEAR(julian_day(1957, 10, 4, 0.81 * 24.0), 2436116.31, 1e-6);  // Meeus Example 7.a
  EXPECT_DOUBLE_EQ(julian_day(2021, 1, 1, 0.0), 2459215.5);
  EXPECT_DOUBLE_EQ(julian_day(2020, 3, 1, 0.0) - julian_day(2020, 2, 28, 0.0), 2.0);
}

TEST(SiteClock, UtcAndJulianDayOfAStep) {
  const SiteClock oakland(-8.0, 2021, false);
  // Jan 1, EPW hour 1: 00:30 PST = 08:30 UTC.
  const TimeStep s = oakland.step(1, 1, 1);
  const UtcTime u = oakland.utc(s);
  EXPECT_EQ(u.year, 2021);
  EXPECT_EQ(u.month, 1);
  EXPECT_EQ(u.day, 1);
  EXPECT_DOUBLE_EQ(u.hour, 8.5);
  EXPECT_DOUBLE_EQ(oakland.julian_day(s), 2459215.5 + 8.5 / 24.0);
  // Dec 31, EPW hour 24: 23:30 PST = 07:30 UTC on Jan 1 of the next year.
  const UtcTime v = oakland.utc(oakland.step(12, 31, 24));
  EXPECT_EQ(v.year, 2022);
  EXPECT_EQ(v.month, 1);
  EXPECT_EQ(v.day, 1);
  EXPECT_DOUBLE_EQ(v.hour, 7.5);
  // East of Greenwich: Jan 1 00:30 CET = Dec 31 23:30 UTC of the previous year.
  const SiteClock mannheim(1.0, 2005, false);
  const UtcTime w = mannheim.utc(mannheim.step(1, 1, 1));
  EXPECT_EQ(w.year, 2004);
  EXPECT_EQ(w.month, 12);
  EXPECT_EQ(w.day, 31);
  EXPECT_DOUBLE_EQ(w.hour, 23.5);
  // Across a leap day.
  const SiteClock leap(-8.0, 2020, true);
  const UtcTime x = leap.utc(leap.step(2, 28, 24));
  EXPECT_EQ(x.month, 2);
  EXPECT_EQ(x.day, 29);
  EXPECT_DOUBLE_EQ(x.hour, 7.5);
}

TEST(SiteClock, ForEpwChoosesCalendarAndYear) {
  // Synthetic file: every record says 1999 -> that year; 365 days.
  const EpwFile plain = test::SyntheticEpw().read();
  const SiteClock a = SiteClock::for_epw(plain);
  EXPECT_EQ(a.year(), 1999);
  EXPECT_FALSE(a.leap_calendar());
  EXPECT_EQ(a.time_zone_h(), -8.0);
  const std::vector<TimeStep> steps = a.steps(plain.records);
  ASSERT_EQ(steps.size(), 8760u);
  for (std::size_t i = 0; i < steps.size(); ++i) ASSERT_EQ(steps[i].hour_of_year, static_cast<int>(i));

  // Leap-day records with year 1999 (not a leap year): reference leap year 2020.
  const EpwFile leap = test::SyntheticEpw(true, true).read();
  const SiteClock b = SiteClock::for_epw(leap);
  EXPECT_EQ(b.year(), 2020);
  EXPECT_TRUE(b.leap_calendar());
  const std::vector<TimeStep> leap_steps = b.steps(leap.records);
  ASSERT_EQ(leap_steps.size(), 8784u);
  EXPECT_EQ(leap_steps.back().hour_of_year, 8783);
  EXPECT_EQ(leap_steps.back().day_of_year, 366);
}

TEST(SiteClock, TmyFileWithMixedYearsUsesTheReferenceYear) {
  const std::string path = std::string(DAYPHOTON_SOURCE_DIR) + "/projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw";
  ASSERT_TRUE(std::ifstream(path)) << "missing " << path;
  const EpwFile epw = read_epw(path);
  const SiteClock clock = SiteClock::for_epw(epw);
  EXPECT_EQ(clock.year(), 2021);
  EXPECT_FALSE(clock.leap_calendar());
  const std::vector<TimeStep> steps = clock.steps(epw.records);
  ASSERT_EQ(steps.size(), 8760u);
  EXPECT_EQ(steps.back().day_of_year, 365);
  EXPECT_EQ(steps[12].hour_lst, 12.5);
}

}  // namespace
}  // namespace dayphoton::weather
