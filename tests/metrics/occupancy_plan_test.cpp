// Occupancy schedules: weekdays from the weekday of 1 January, holidays, daylight saving
// time (EU and US dates checked against the published dates of 2025 and 2018), hourly
// lists; and DA300 under a weekday schedule with holidays against a synthetic series whose
// answer is counted by hand.
#include "dayphoton/metrics/occupancy_plan.h"

#include <gtest/gtest.h>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/metrics/annual_metrics.h"

using namespace dayphoton::metrics;

namespace {

std::vector<TimeStamp> hourly_year(bool leap = false) {
  const int days_in_month[12] = {31, leap ? 29 : 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  std::vector<TimeStamp> steps;
  for (int m = 1; m <= 12; ++m)
    for (int d = 1; d <= days_in_month[m - 1]; ++d)
      for (int h = 1; h <= 24; ++h) steps.push_back({m, d, h - 0.5});
  return steps;
}

std::size_t step_of(int month, int day, double hour, bool leap = false) {
  const YearCalendar c(Weekday::Monday, leap);
  return static_cast<std::size_t>(24 * c.day_of_year(month, day)) + static_cast<std::size_t>(hour);
}

OccupancyPlan school(Weekday january_1) {
  OccupancyPlan p;
  p.kind = OccupancyPlan::Kind::Weekly;
  for (int d = 0; d < 5; ++d) p.week[static_cast<std::size_t>(d)] = {{8, 16}};
  p.january_1 = january_1;
  return p;
}

}  // namespace

TEST(Calendar, WeekdaysAndDates) {
  const YearCalendar y2025(Weekday::Wednesday, false);  // 1 January 2025 was a Wednesday
  EXPECT_EQ(y2025.weekday(y2025.day_of_year(12, 25)), Weekday::Thursday);
  EXPECT_EQ(y2025.date(y2025.day_of_year(3, 1)), std::make_pair(3, 1));
  EXPECT_EQ(y2025.date(-1), std::make_pair(12, 31));
  EXPECT_EQ(y2025.date(365), std::make_pair(1, 1));
  const YearCalendar y2024(Weekday::Monday, true);  // 2024: leap, 1 January a Monday
  EXPECT_EQ(y2024.day_of_year(3, 1), 60);
  EXPECT_EQ(y2024.weekday(y2024.day_of_year(12, 31)), Weekday::Tuesday);
  EXPECT_EQ(parse_weekday("SUN"), Weekday::Sunday);
  EXPECT_EQ(parse_weekday("Thursday"), Weekday::Thursday);
  EXPECT_FALSE(parse_weekday("thu."));
  // A weather file starting on Sunday 1/1 (2017) and one starting on Monday 3/5 of 2018.
  EXPECT_EQ(january_1_from(Weekday::Sunday, 1, 1, false), Weekday::Sunday);
  EXPECT_EQ(january_1_from(Weekday::Monday, 3, 5, false), Weekday::Monday);  // 1 January 2018: Monday
}

TEST(Calendar, DaylightSavingDatesOf2025) {
  const YearCalendar y(Weekday::Wednesday, false);
  // EU 2025: 30 March to 26 October, 01:00 UTC = 02:00 CET (time zone +1).
  const auto eu = y.daylight_saving_hours(DaylightSaving::Eu, 1.0);
  ASSERT_TRUE(eu);
  EXPECT_EQ(eu->first, 24.0 * y.day_of_year(3, 30) + 2.0);
  EXPECT_EQ(eu->second, 24.0 * y.day_of_year(10, 26) + 2.0);
  // US 2025: 9 March 02:00 to 2 November 01:00 standard time.
  const auto us = y.daylight_saving_hours(DaylightSaving::Us, -5.0);
  ASSERT_TRUE(us);
  EXPECT_EQ(us->first, 24.0 * y.day_of_year(3, 9) + 2.0);
  EXPECT_EQ(us->second, 24.0 * y.day_of_year(11, 2) + 1.0);
  EXPECT_FALSE(y.daylight_saving_hours(DaylightSaving::None, 0));
}

TEST(OccupancyPlan, WeekdaysFromJanuaryFirst) {
  const auto steps = hourly_year();
  // 2018 began on a Monday: 261 weekdays x 8 hours.
  EXPECT_EQ(school(Weekday::Monday).schedule(steps, {}).occupied_count(), 261u * 8u);
  // Starting on a Saturday (2022): 260 weekdays.
  EXPECT_EQ(school(Weekday::Saturday).schedule(steps, {}).occupied_count(), 260u * 8u);
  // The weather file's weekday is used when the plan has none; the plan's overrides it.
  OccupancyPlan from_file = school(Weekday::Monday);
  from_file.january_1.reset();
  WeatherCalendar calendar;
  calendar.january_1 = Weekday::Saturday;
  EXPECT_EQ(from_file.schedule(steps, calendar).occupied_count(), 260u * 8u);
  EXPECT_EQ(school(Weekday::Monday).schedule(steps, calendar).occupied_count(), 261u * 8u);
  const OccupancySchedule s = school(Weekday::Monday).schedule(steps, {});
  EXPECT_TRUE(s.occupied(step_of(1, 1, 8.5)));    // Monday 08:30
  EXPECT_FALSE(s.occupied(step_of(1, 1, 16.5)));  // 16:30: after 16:00
  EXPECT_FALSE(s.occupied(step_of(1, 6, 10.5)));  // Saturday
}

TEST(OccupancyPlan, HolidaysHaveTheirOwnHoursAndWrapOverTheYearEnd) {
  const auto steps = hourly_year();
  OccupancyPlan p = school(Weekday::Monday);  // 2018
  // 24 December (Monday) .. 2 January (Tuesday): weekdays 24-28 and 31 Dec, 1-2 Jan = 8 days.
  p.holidays.push_back({12, 24, 1, 2});
  // 2-13 July 2018: 10 weekdays.
  p.holidays.push_back({7, 2, 7, 13});
  EXPECT_EQ(p.schedule(steps, {}).occupied_count(), (261u - 8u - 10u) * 8u);
  // Holidays open 09:00-12:00: the 18 weekday holidays and the 4 weekend holidays
  // (29-30 December, 7-8 July) get 3 hours.
  p.holiday_hours = {{9, 12}};
  EXPECT_EQ(p.schedule(steps, {}).occupied_count(), (261u - 18u) * 8u + (18u + 4u) * 3u);
}

TEST(OccupancyPlan, DaylightSavingShiftsClockHoursByOneHour) {
  const auto steps = hourly_year();
  OccupancyPlan p;
  p.kind = OccupancyPlan::Kind::Weekly;
  p.week.fill({{8, 18}});
  p.january_1 = Weekday::Wednesday;  // 2025
  p.daylight_saving = DaylightSaving::Eu;
  WeatherCalendar cet;
  cet.time_zone_h = 1;
  const OccupancySchedule s = p.schedule(steps, cet);
  EXPECT_EQ(s.occupied_count(), 3650u);  // every day still has ten occupied hours
  // Summer (1 July): clock 08:00-18:00 = standard 07:00-17:00.
  EXPECT_TRUE(s.occupied(step_of(7, 1, 7.5)));
  EXPECT_FALSE(s.occupied(step_of(7, 1, 17.5)));
  // Winter (1 December) and the days just before and at the switch.
  EXPECT_FALSE(s.occupied(step_of(12, 1, 7.5)));
  EXPECT_TRUE(s.occupied(step_of(12, 1, 17.5)));
  EXPECT_FALSE(s.occupied(step_of(3, 29, 7.5)));  // Saturday before the switch: winter
  EXPECT_TRUE(s.occupied(step_of(3, 30, 7.5)));   // Sunday 30 March: DST from 02:00
  EXPECT_TRUE(s.occupied(step_of(10, 25, 7.5)));  // Saturday before the end: summer
  EXPECT_FALSE(s.occupied(step_of(10, 26, 7.5))); // Sunday 26 October: winter again
  // US rule, same plan: 9 March starts summer.
  p.daylight_saving = DaylightSaving::Us;
  const OccupancySchedule us = p.schedule(steps, {});
  EXPECT_FALSE(us.occupied(step_of(3, 8, 7.5)));
  EXPECT_TRUE(us.occupied(step_of(3, 9, 7.5)));
  EXPECT_TRUE(us.occupied(step_of(11, 1, 7.5)));
  EXPECT_FALSE(us.occupied(step_of(11, 2, 7.5)));
}

TEST(OccupancyPlan, ClockTimePastMidnightBelongsToTheNextDay) {
  // Open only on Sundays 00:00-01:00 clock time, with DST: in summer the Saturday
  // 23:30-standard step is Sunday 00:30 clock time.
  const auto steps = hourly_year();
  OccupancyPlan p;
  p.kind = OccupancyPlan::Kind::Weekly;
  p.week[6] = {{0, 1}};
  p.january_1 = Weekday::Wednesday;  // 2025: 5 July a Saturday
  p.daylight_saving = DaylightSaving::Us;
  const OccupancySchedule s = p.schedule(steps, {});
  EXPECT_TRUE(s.occupied(step_of(7, 5, 23.5)));
  EXPECT_FALSE(s.occupied(step_of(7, 6, 0.5)));  // Sunday 01:30 clock time
  EXPECT_TRUE(s.occupied(step_of(1, 5, 0.5)));   // winter Sunday 00:30
}

TEST(OccupancyPlan, LeapYearWeatherFile) {
  const auto steps = hourly_year(true);
  // 2024: a Monday start, 262 weekdays.
  EXPECT_EQ(school(Weekday::Monday).schedule(steps, {}).occupied_count(), 262u * 8u);
  EXPECT_TRUE(school(Weekday::Monday).schedule(steps, {}).occupied(step_of(2, 29, 9.5, true)));  // Thursday
}

TEST(OccupancyPlan, ErrorsWhenThePlanDoesNotFitTheWeatherFile) {
  const auto steps = hourly_year();
  OccupancyPlan hourly;
  hourly.kind = OccupancyPlan::Kind::Hourly;
  hourly.hourly.assign(8784, true);
  hourly.hourly_source = "school.csv";
  hourly.location = {"project.yaml", 12, 11};
  try {
    hourly.schedule(steps, {});
    FAIL() << "no error";
  } catch (const dayphoton::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("project.yaml:12:11: error: the occupancy schedule school.csv has 8784 values "
                                         "but the weather file has 8760 records"),
              std::string::npos)
        << e.what();
  }
  OccupancyPlan weekly = school(Weekday::Monday);
  weekly.january_1.reset();
  WeatherCalendar unknown;
  unknown.january_1_source = "DATA PERIODS of x.epw gives 'Xday'";
  EXPECT_THROW(weekly.schedule(steps, unknown), dayphoton::InputError);
}

TEST(OccupancyPlan, DescriptionGroupsDays) {
  OccupancyPlan p = school(Weekday::Monday);
  p.week[5] = {{8, 12}, {13, 15.5}};
  p.holidays.push_back({7, 1, 8, 31});
  p.daylight_saving = DaylightSaving::Eu;
  EXPECT_EQ(p.description(),
            "Monday-Friday 08:00-16:00; Saturday 08:00-12:00, 13:00-15:30; Sunday closed; holidays (1 period) closed; "
            "local clock time with EU daylight saving time");
  EXPECT_EQ(OccupancyPlan::daily_hours(7, 19).description(), "07:00-19:00 every day, local standard time");
}

// DA300 under a weekday schedule with holidays equals the count of a synthetic series:
// sensor 0 sees 500 lx on every Monday and Wednesday from 08:00 to 12:00 and nothing else;
// sensor 1 sees 400 lx at every hour. School: weekdays 08:00-16:00, holidays 2-13 July and
// 24 December - 2 January (2018 calendar, 1 January a Monday).
TEST(OccupancyPlan, DaylightAutonomyOfAWeekdayScheduleWithHolidays) {
  const auto steps = hourly_year();
  const YearCalendar year(Weekday::Monday, false);
  IlluminanceTable table(steps, 2);
  for (std::size_t t = 0; t < steps.size(); ++t) {
    const int day = year.day_of_year(steps[t].month, steps[t].day);
    const Weekday w = year.weekday(day);
    const bool lit = (w == Weekday::Monday || w == Weekday::Wednesday) && steps[t].hour > 8 && steps[t].hour < 12;
    table.lux(t, 0) = lit ? 500.f : 0.f;
    table.lux(t, 1) = 400.f;
  }
  OccupancyPlan p = school(Weekday::Monday);
  p.holidays.push_back({7, 2, 7, 13});
  p.holidays.push_back({12, 24, 1, 2});
  const OccupancySchedule occ = p.schedule(steps, {});
  // 2018 has 53 Mondays and 52 Wednesdays; the holidays take 5 Mondays (2 and 9 July, 24
  // and 31 December, 1 January) and 3 Wednesdays (4 and 11 July, 26 December).
  const double lit_hours = ((53 - 5) + (52 - 3)) * 4.0;
  const double occupied_hours = (261 - 18) * 8.0;
  ASSERT_EQ(occ.occupied_count(), static_cast<std::size_t>(occupied_hours));
  const auto m = compute_sensor_metrics(table, occ);
  EXPECT_DOUBLE_EQ(m[0].da_percent, 100.0 * lit_hours / occupied_hours);
  EXPECT_DOUBLE_EQ(m[1].da_percent, 100.0);
  // The every-day default counts the same lit hours over 3650 hours.
  const auto every_day = compute_sensor_metrics(table, OccupancySchedule::daily_hours(steps));
  EXPECT_DOUBLE_EQ(every_day[0].da_percent, 100.0 * (53 + 52) * 4.0 / 3650.0);
}
