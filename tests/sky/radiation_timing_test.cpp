// The clock of a weather file's radiation against the sun's (sky/radiation_timing.h): a clear
// day's radiation made from the sun itself and moved by a known time is measured to be off by
// that time; the Oakland TMY3 file, whose records are on its header's clock, is within 0.2 h;
// its records moved by one hour either way (a UTC-stamped or converter-shifted file) are
// measured off by about an hour (the study's warning on them: SunSite.RecordsOnAnotherClock...
// in tests/study/sun_site_test.cpp); too few sunny days give no measure.
#include "dayphoton/sky/radiation_timing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "dayphoton/core/units.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/weather/site_clock.h"

using namespace dayphoton;
using namespace dayphoton::sky;

namespace {

const std::string OaklandEpw =
    std::string(DAYPHOTON_SOURCE_DIR) + "/projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw";

/// The file's radiation moved by `records` hours: record t takes the values of record
/// t + records (a file whose stamps are `records` hours behind the light).
weather::HourlyWeather moved(const weather::HourlyWeather& w, int records) {
  weather::HourlyWeather out = w;
  const auto n = static_cast<long>(w.records.size());
  for (long t = 0; t < n; ++t) {
    const weather::WeatherRecord& from = w.records[static_cast<std::size_t>(((t + records) % n + n) % n)];
    out.records[static_cast<std::size_t>(t)].direct_normal_w_m2 = from.direct_normal_w_m2;
    out.records[static_cast<std::size_t>(t)].diffuse_horizontal_w_m2 = from.diffuse_horizontal_w_m2;
  }
  return out;
}

/// A cloudless year made from the sun at each record's mid-hour plus `shift_h`: direct normal
/// 900 W/m2 x sin(altitude) and diffuse horizontal 100 W/m2 x sin(altitude) while the sun
/// is up, symmetric about transit. Record t carries the light of the instant shift_h after its
/// stamp, so the light's centre (the transit) falls on the records stamped shift_h before the
/// transit: offset_h = -shift_h.
weather::HourlyWeather clear_year(const weather::HourlyWeather& w, const SolarSite& site, double shift_h) {
  weather::HourlyWeather out = w;
  const weather::SiteClock clock = weather::SiteClock::for_weather(w);
  const auto steps = clock.steps(w.records);
  for (std::size_t t = 0; t < steps.size(); ++t) {
    const weather::UtcTime utc = clock.utc(steps[t]);
    const SolarPosition sun = solar_position_utc(site, utc.year, utc.month, utc.day, utc.hour + shift_h);
    const double s = std::sin(sun.true_altitude_rad);
    out.records[t].direct_normal_w_m2 = s > 0 ? 900.0 * s : 0.0;
    out.records[t].diffuse_horizontal_w_m2 = s > 0 ? 100.0 * s : 0.0;
  }
  return out;
}

}  // namespace

TEST(RadiationTiming, ASunlitYearMovedByAKnownTimeIsMeasuredOffByThatTime) {
  const weather::HourlyWeather epw = weather::read_hourly_weather(OaklandEpw);
  const SolarSite site = solar_site_of(epw);
  for (const double shift_h : {-2.0, -1.0, -0.5, 0.0, 0.25, 1.0}) {
    const RadiationTiming timing = radiation_timing(clear_year(epw, site, shift_h), site);
    ASSERT_TRUE(timing.measured) << shift_h;
    EXPECT_EQ(timing.days, 73u);  // a fifth of 365 days
    // The hourly sampling of a profile that starts and ends at the horizon: within 0.03 h.
    EXPECT_NEAR(timing.offset_h, -shift_h, 0.03) << "records " << shift_h << " h behind the light";
  }
}

TEST(RadiationTiming, OaklandIsOnItsClockAndMovedByAnHourIsNot) {
  const weather::HourlyWeather epw = weather::read_hourly_weather(OaklandEpw);
  const SolarSite site = solar_site_of(epw);
  const RadiationTiming own = radiation_timing(epw, site);
  ASSERT_TRUE(own.measured);
  EXPECT_LT(std::abs(own.offset_h), 0.2);

  const RadiationTiming early = radiation_timing(moved(epw, 1), site);
  const RadiationTiming late = radiation_timing(moved(epw, -1), site);
  EXPECT_NEAR(early.offset_h, own.offset_h - 1.0, 0.1);
  EXPECT_NEAR(late.offset_h, own.offset_h + 1.0, 0.1);
}

TEST(RadiationTiming, TooFewSunnyDaysGiveNoMeasure) {
  weather::HourlyWeather epw = weather::read_hourly_weather(OaklandEpw);
  const SolarSite site = solar_site_of(epw);
  // Direct light on 37 days only: a fifth of them (7) is below RadiationTimingMinimumDays.
  for (std::size_t t = 0; t < epw.records.size(); ++t)
    if (t / 24 % 10 != 0) epw.records[t].direct_normal_w_m2 = 0.0;
  const RadiationTiming timing = radiation_timing(epw, site);
  EXPECT_FALSE(timing.measured);
  SolarSite other = site;
  other.time_zone_h = 1;
  EXPECT_THROW(radiation_timing(epw, other), std::invalid_argument);
}
