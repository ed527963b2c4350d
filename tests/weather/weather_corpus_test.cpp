// The weather-file variants of tests/data/weather (README.md there says what each file
// exercises): each accepted variant reads with exactly its documented warnings, each broken
// used field gives its located error, and EPW and .wea files give the same hourly series
// (docs/weather.md, "Real-world files").
#include "dayphoton/weather/hourly_weather.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "dayphoton/weather/epw_reader.h"
#include "dayphoton/weather/wea.h"
#include "epw_test_support.h"

namespace dayphoton::weather {
namespace {

std::string corpus(const std::string& name) { return std::string(DAYPHOTON_TEST_DATA_DIR) + "/weather/" + name; }

/// The first line ("file:line:col: severity: message") of each diagnostic, the corpus folder
/// removed from the file name.
std::vector<std::string> first_lines(const std::vector<Diagnostic>& diagnostics) {
  std::vector<std::string> out;
  const std::string folder = std::string(DAYPHOTON_TEST_DATA_DIR) + "/weather/";
  for (const Diagnostic& d : diagnostics) {
    std::string f = d.format();
    f = f.substr(0, f.find('\n'));
    if (f.rfind(folder, 0) == 0) f.erase(0, folder.size());
    out.push_back(f);
  }
  return out;
}

/// The diagnostics of a read that must fail.
template <class Read>
std::vector<std::string> errors_of(Read read) {
  try {
    read();
  } catch (const InputError& e) {
    return first_lines(e.diagnostics());
  }
  ADD_FAILURE() << "expected an InputError";
  return {};
}

// ---- EPW header variants ---------------------------------------------------------------

TEST(WeatherCorpus, CleanFileHasNoWarnings) {
  const EpwFile epw = read_epw(corpus("clean.epw"));
  EXPECT_EQ(epw.records.size(), 48u);
  EXPECT_TRUE(epw.warnings.empty());
  EXPECT_EQ(epw.ignored_value_count, 0u);
}

TEST(WeatherCorpus, DataPeriodDatesWrittenYearFirst) {
  const EpwFile epw = read_epw(corpus("dates_year_first.epw"));
  EXPECT_EQ(epw.header.data_period.start_month, 1);
  EXPECT_EQ(epw.header.data_period.start_day, 1);
  EXPECT_EQ(epw.header.data_period.end_month, 1);
  EXPECT_EQ(epw.header.data_period.end_day, 2);
  EXPECT_EQ(epw.records.size(), 48u);
  EXPECT_TRUE(epw.warnings.empty());
}

TEST(WeatherCorpus, DataPeriodDatesWithTrailingYear) {
  const EpwFile epw = read_epw(corpus("dates_with_year.epw"));
  EXPECT_EQ(epw.records.size(), 48u);
  EXPECT_TRUE(epw.warnings.empty());
}

TEST(WeatherCorpus, BadDataPeriodDateIsStillALocatedError) {
  test::SyntheticEpw e;
  e.lines[7] = "DATA PERIODS,1,1,Data,Sunday,2015/13/1,12/31";
  EXPECT_EQ(test::error_lines(e),
            std::vector<std::string>{"t.epw:8:6: error: field 6 (start date): expected a date M/D, M/D/YYYY "
                                     "or YYYY/M/D, found '2015/13/1'"});
}

TEST(WeatherCorpus, ByteOrderMarkIsNotPartOfTheFirstLine) {
  const EpwFile epw = read_epw(corpus("utf8_bom.epw"));
  EXPECT_EQ(epw.header.location.city, "Testville");
  EXPECT_EQ(epw.records.size(), 48u);
  EXPECT_TRUE(epw.warnings.empty());
  const HourlyWeather wea = read_hourly_weather(corpus("utf8_bom.wea"));
  EXPECT_EQ(wea.site.city, "Testville");
  EXPECT_EQ(wea.records.size(), 48u);
}

TEST(WeatherCorpus, LocationLineWithAnEleventhField) {
  const EpwFile epw = read_epw(corpus("location_11_fields.epw"));
  EXPECT_DOUBLE_EQ(epw.header.location.latitude_deg, 37.72);
  EXPECT_DOUBLE_EQ(epw.header.location.elevation_m, 2.0);
  EXPECT_EQ(first_lines(epw.warnings),
            std::vector<std::string>{"location_11_fields.epw:1:11: warning: LOCATION line has 11 fields, expected 10; "
                                     "the fields after field 10 (elevation) are ignored"});
}

TEST(WeatherCorpus, EmptyLeapYearField) {
  const EpwFile epw = read_epw(corpus("leap_flag_empty.epw"));
  EXPECT_FALSE(epw.header.leap_year_observed);
  EXPECT_EQ(first_lines(epw.warnings),
            std::vector<std::string>{"leap_flag_empty.epw:5:2: warning: field 2 (LeapYear observed) is empty; the "
                                     "calendar follows the records (366 days if they hold February 29)"});
}

TEST(WeatherCorpus, EmptyLeapYearFieldWithALeapDay) {
  const EpwFile epw = read_epw(corpus("leap_day_flag_empty.epw"));
  EXPECT_TRUE(epw.leap_day_present);
  EXPECT_EQ(epw.records.size(), 72u);
  EXPECT_EQ(epw.warnings.size(), 1u);  // the empty field; no second warning about "No"
}

TEST(WeatherCorpus, DeclaredLeapDay) {
  const EpwFile epw = read_epw(corpus("leap_day_declared.epw"));
  EXPECT_TRUE(epw.leap_day_present);
  EXPECT_EQ(epw.records.size(), 72u);
  EXPECT_TRUE(epw.warnings.empty());
}

TEST(WeatherCorpus, UndeclaredLeapDayIsKeptWithOneWarning) {
  const EpwFile epw = read_epw(corpus("leap_day_undeclared.epw"));
  EXPECT_TRUE(epw.leap_day_present);
  EXPECT_EQ(epw.records.size(), 72u);
  EXPECT_EQ(epw.warnings.size(), 1u);
}

TEST(WeatherCorpus, FullLeapYearOf8784RecordsGivesAn8784HourSeries) {
  const EpwFile epw = test::SyntheticEpw(false, true).read();
  const HourlyWeather w = hourly_weather_from_epw(epw);
  EXPECT_EQ(w.records.size(), 8784u);
  EXPECT_TRUE(w.leap_day_present);
}

// ---- fields dayphoton does not use ------------------------------------------------------

TEST(WeatherCorpus, BadValuesInUnusedFieldsAreCountedWarnings) {
  const EpwFile epw = read_epw(corpus("unused_fields_junk.epw"));
  EXPECT_EQ(epw.records.size(), 48u);
  EXPECT_EQ(epw.ignored_value_count, 14u);
  const std::vector<std::string> w = first_lines(epw.warnings);
  ASSERT_EQ(w.size(), MaxLocatedIgnoredValues + 1);
  EXPECT_EQ(w[0], "unused_fields_junk.epw:9:27: warning: field 27 (present weather observation): 'x' is not a "
                  "number; dayphoton does not use this field, the value is ignored");
  EXPECT_EQ(w[1], "unused_fields_junk.epw:10:27: warning: field 27 (present weather observation): 12 is outside "
                  "[0, 9]; dayphoton does not use this field, the value is ignored");
  EXPECT_EQ(w.back(), "unused_fields_junk.epw: warning: 14 values in fields dayphoton does not use were ignored "
                      "(field 9 (relative humidity): 1, field 21 (wind direction): 1, field 25 (visibility): 1, "
                      "field 27 (present weather observation): 10, field 33 (albedo): 1); the first 10 are "
                      "located above");
  // The ignored values read as missing.
  EXPECT_FALSE(epw.records[12].relative_humidity_percent.has_value());
  EXPECT_TRUE(epw.records[11].relative_humidity_percent.has_value());
}

TEST(WeatherCorpus, LadybugStyleFileIsAccepted) {
  // An 11-field LOCATION line, an empty LeapYear field, year-first data period dates and
  // empty present-weather fields, together.
  const EpwFile epw = read_epw(corpus("ladybug_style.epw"));
  EXPECT_EQ(epw.records.size(), 48u);
  EXPECT_EQ(epw.warnings.size(), 2u);
  EXPECT_EQ(epw.ignored_value_count, 0u);
}

// ---- fields the sky uses ----------------------------------------------------------------

TEST(WeatherCorpus, BrokenUsedFieldsAreLocatedErrors) {
  EXPECT_EQ(errors_of([] { read_epw(corpus("used_fields_broken.epw")); }),
            (std::vector<std::string>{
                "used_fields_broken.epw:20:16: error: field 16 (diffuse horizontal radiation): 'abc' is not a number",
                "used_fields_broken.epw:21:15: error: field 15 (direct normal radiation): -3 W/m^2 is negative "
                "[0, 1500]",
                "used_fields_broken.epw:22:8: error: field 8 (dew point temperature): 'dew' is not a number"}));
}

TEST(WeatherCorpus, ShortGapsOfIrradianceAreInterpolated) {
  const EpwFile epw = read_epw(corpus("missing_short_gaps.epw"));
  EXPECT_TRUE(epw.warnings.empty());  // missing values are not problems of the file
  const HourlyWeather w = hourly_weather_from_epw(epw);
  EXPECT_EQ(w.filled_values, 3u);
  // Jan 1 hours 10 and 11 between hour 9 (190 W/m^2) and hour 12 (220 W/m^2).
  EXPECT_DOUBLE_EQ(*w.records[9].direct_normal_w_m2, 200.0);
  EXPECT_DOUBLE_EQ(*w.records[10].direct_normal_w_m2, 210.0);
  // Jan 2 hour 12 between hours 11 (61) and 13 (63).
  EXPECT_DOUBLE_EQ(*w.records[35].diffuse_horizontal_w_m2, 62.0);
  EXPECT_EQ(first_lines(w.warnings),
            (std::vector<std::string>{
                "missing_short_gaps.epw:18:15: warning: field 15 (direct normal radiation) is missing; "
                "interpolated to 200 W/m^2 (a gap of 2 hours)",
                "missing_short_gaps.epw:19:15: warning: field 15 (direct normal radiation) is missing; "
                "interpolated to 210 W/m^2 (a gap of 2 hours)",
                "missing_short_gaps.epw:44:16: warning: field 16 (diffuse horizontal radiation) is missing; "
                "interpolated to 62 W/m^2 (a gap of 1 hour)"}));
}

TEST(WeatherCorpus, GapAtTheStartHoldsTheNeighbour) {
  const HourlyWeather w = hourly_weather_from_epw(read_epw(corpus("missing_at_start.epw")));
  EXPECT_EQ(w.filled_values, 1u);
  EXPECT_DOUBLE_EQ(*w.records[0].diffuse_horizontal_w_m2, 0.0);
}

TEST(WeatherCorpus, LongGapOfIrradianceIsALocatedError) {
  const EpwFile epw = read_epw(corpus("missing_long_gap.epw"));
  EXPECT_EQ(errors_of([&] { hourly_weather_from_epw(epw); }),
            std::vector<std::string>{
                "missing_long_gap.epw:18:15: error: field 15 (direct normal radiation) is missing for 3 consecutive "
                "hours (1/1 hour 10 to 1/1 hour 12); at most 2 are interpolated: fill the gap with a weather "
                "tool, or use another file"});
}

TEST(WeatherCorpus, FilledValuesBeyondTheLocatedOnesAreCounted) {
  test::SyntheticEpw e;
  // 30 isolated missing DNI values: March 1..30 at hour 10.
  for (int d = 1; d <= 30; ++d) e.set_field(test::SyntheticEpw::line_of(3, d, 10), 15, "9999");
  const HourlyWeather w = hourly_weather_from_epw(e.read());
  EXPECT_EQ(w.filled_values, 30u);
  ASSERT_EQ(w.warnings.size(), MaxLocatedFilledValues + 1);
  EXPECT_EQ(first_lines({w.warnings.back()}),
            std::vector<std::string>{"t.epw: warning: 30 missing irradiance values were interpolated; the first "
                                     "10 are located above"});
}

// ---- .wea ------------------------------------------------------------------------------

TEST(WeatherCorpus, WeaFileGivesASeriesWithItsHeaderSite) {
  const HourlyWeather w = read_hourly_weather(corpus("hourly.wea"));
  EXPECT_EQ(w.format, WeatherFormat::Wea);
  EXPECT_EQ(w.records.size(), 48u);
  EXPECT_EQ(w.site.city, "Testville");
  EXPECT_EQ(w.site.country, "USA");
  EXPECT_DOUBLE_EQ(w.site.latitude_deg, 37.72);
  EXPECT_DOUBLE_EQ(w.site.longitude_east_deg, -122.22);
  EXPECT_DOUBLE_EQ(w.site.time_zone_h, -8.0);
  EXPECT_DOUBLE_EQ(w.site.elevation_m, 2.0);
  EXPECT_FALSE(w.leap_day_present);
  EXPECT_EQ(w.records[9].hour, 10);
  EXPECT_EQ(w.records[9].source_line, 16);
  EXPECT_DOUBLE_EQ(*w.records[9].direct_normal_w_m2, 200.0);
  EXPECT_DOUBLE_EQ(*w.records[9].diffuse_horizontal_w_m2, 60.0);
}

TEST(WeatherCorpus, WeaAndEpwOfTheSameDataGiveTheSameSeries) {
  const HourlyWeather a = read_hourly_weather(corpus("clean.epw"));
  const HourlyWeather b = read_hourly_weather(corpus("hourly.wea"));
  ASSERT_EQ(a.records.size(), b.records.size());
  for (std::size_t i = 0; i < a.records.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(a.records[i].month, b.records[i].month);
    EXPECT_EQ(a.records[i].day, b.records[i].day);
    EXPECT_EQ(a.records[i].hour, b.records[i].hour);
    EXPECT_EQ(a.records[i].direct_normal_w_m2, b.records[i].direct_normal_w_m2);
    EXPECT_EQ(a.records[i].diffuse_horizontal_w_m2, b.records[i].diffuse_horizontal_w_m2);
  }
  EXPECT_DOUBLE_EQ(a.site.longitude_east_deg, b.site.longitude_east_deg);
  EXPECT_DOUBLE_EQ(a.site.time_zone_h, b.site.time_zone_h);
}

TEST(WeatherCorpus, WeaLeapDay) {
  const HourlyWeather w = read_hourly_weather(corpus("hourly_leap_day.wea"));
  EXPECT_TRUE(w.leap_day_present);
  EXPECT_EQ(w.records.size(), 72u);
}

TEST(WeatherCorpus, WeaBadValueIsALocatedError) {
  EXPECT_EQ(errors_of([] { read_hourly_weather(corpus("bad_value.wea")); }),
            std::vector<std::string>{"bad_value.wea:37:11: error: direct: '12x' is not a number"});
}

TEST(WeatherCorpus, WeaMissingHourIsALocatedError) {
  EXPECT_EQ(errors_of([] { read_hourly_weather(corpus("missing_hour.wea")); }),
            std::vector<std::string>{"missing_hour.wea:27:5: error: missing record(s): expected 1/1 hour 21 "
                                     "(20.500), found 1/1 hour 22 (21.500)"});
}

TEST(WeatherCorpus, WeaTimeStampsMustBeMidHours) {
  const std::vector<std::string> e = errors_of([] { read_hourly_weather(corpus("integer_hours.wea")); });
  ASSERT_FALSE(e.empty());
  EXPECT_EQ(e[0], "integer_hours.wea:7:5: error: hour 0.000 is not a mid-hour time stamp h - 0.5 (0.5, 1.5, .., "
                  "23.5) of hourly data");
}

TEST(WeatherCorpus, WeaIlluminanceUnitsAreRefusedAsAnnualWeather) {
  EXPECT_EQ(errors_of([] { read_hourly_weather(corpus("units_illuminance.wea")); }),
            std::vector<std::string>{"units_illuminance.wea:6:25: error: weather_data_file_units 3: the annual sky "
                                     "needs direct normal and diffuse horizontal irradiance (units 1)"});
}

// Seeded random corruptions of the .wea and EPW corpus texts through the reader and the
// series: a series or an InputError, never a crash or another exception.
TEST(WeatherCorpus, FuzzedCorruptionsOfTheSeriesNeverCrash) {
  std::mt19937 rng(11u);
  const std::string alphabet = "0123456789 .,-+/\n\tabc_\xff";
  for (const std::string name : {"hourly.wea", "missing_short_gaps.epw"}) {
    std::ifstream file(corpus(name), std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    ASSERT_FALSE(text.empty()) << name;
    int failures = 0;
    for (int iteration = 0; iteration < 200; ++iteration) {
      std::string t = text;
      for (int k = 0; k < 3; ++k) {
        const std::size_t pos = rng() % t.size();
        switch (rng() % 3) {
          case 0: t[pos] = alphabet[rng() % alphabet.size()]; break;
          case 1: t.erase(pos, 1 + rng() % 20); break;
          case 2: t.insert(pos, 1, alphabet[rng() % alphabet.size()]); break;
        }
        if (t.empty()) t = "x";
      }
      std::istringstream in(t);
      try {
        if (name == "hourly.wea")
          hourly_weather_from_wea(read_wea(in, "fuzz.wea"));
        else
          hourly_weather_from_epw(read_epw(in, "fuzz.epw"));
      } catch (const InputError& e) {
        ++failures;
        for (const Diagnostic& d : e.diagnostics()) EXPECT_FALSE(d.message.empty());
      }
    }
    EXPECT_GT(failures, 50) << name;  // most corruptions are caught, not silently accepted
  }
}

TEST(WeatherCorpus, ExtensionChoosesTheReader) {
  EXPECT_TRUE(is_wea_path("a/b.wea"));
  EXPECT_TRUE(is_wea_path("B.WEA"));
  EXPECT_FALSE(is_wea_path("b.epw"));
  EXPECT_FALSE(is_wea_path("wea"));
  EXPECT_EQ(read_hourly_weather(corpus("clean.epw")).format, WeatherFormat::Epw);
}

}  // namespace
}  // namespace dayphoton::weather
