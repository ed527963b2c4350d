// EPW reader: the real files (projects/office, tests/data/weather) read cleanly, and a table of corrupted
// texts each gives its exact located message (file:line:field) or the documented handling
// (docs/weather.md). A seeded fuzz loop checks that no corruption crashes the reader.
#include "dayphoton/weather/epw_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include "epw_test_support.h"

namespace dayphoton::weather {
namespace {

using test::error_lines;
using test::SyntheticEpw;

const std::string OaklandEpw = std::string(DAYPHOTON_SOURCE_DIR) + "/projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw";
const std::string MannheimEpw = std::string(DAYPHOTON_TEST_DATA_DIR) + "/weather/DEU_Mannheim.epw";

bool exists(const std::string& path) { return std::ifstream(path).good(); }

// ---- real files -------------------------------------------------------------------------

TEST(EpwReader, OaklandReadsCleanly) {
  const std::string path = OaklandEpw;
  ASSERT_TRUE(exists(path)) << "missing " << path;
  const EpwFile epw = read_epw(path);
  EXPECT_TRUE(epw.warnings.empty());
  ASSERT_EQ(epw.records.size(), 8760u);
  EXPECT_FALSE(epw.leap_day_present);
  // LOCATION,Oakland Metropolitan Arpt,CA,USA,TMY3,724930,37.72,-122.22,-8.0,2.0
  const EpwLocation& loc = epw.header.location;
  EXPECT_EQ(loc.city, "Oakland Metropolitan Arpt");
  EXPECT_EQ(loc.state, "CA");
  EXPECT_EQ(loc.country, "USA");
  EXPECT_EQ(loc.source, "TMY3");
  EXPECT_EQ(loc.wmo, "724930");
  EXPECT_EQ(loc.latitude_deg, 37.72);
  EXPECT_EQ(loc.longitude_east_deg, -122.22);
  EXPECT_EQ(loc.time_zone_h, -8.0);
  EXPECT_EQ(loc.elevation_m, 2.0);
  EXPECT_FALSE(epw.header.leap_year_observed);
  EXPECT_EQ(epw.header.data_period.records_per_hour, 1);
  EXPECT_EQ(epw.header.data_period.start_weekday, "Sunday");
  EXPECT_EQ(epw.header.data_period.end_month, 12);
  EXPECT_EQ(epw.header.data_period.end_day, 31);
  // First record: 1999,1,1,1,0,...,9.0,7.0,87,102000,0,0,305,0,0,0,...
  const WeatherRecord& r0 = epw.records.front();
  EXPECT_EQ(r0.year, 1999);
  EXPECT_EQ(r0.month, 1);
  EXPECT_EQ(r0.day, 1);
  EXPECT_EQ(r0.hour, 1);
  EXPECT_EQ(r0.minute, 0);
  EXPECT_EQ(r0.source_line, 9);
  EXPECT_EQ(r0.dry_bulb_c, 9.0);
  EXPECT_EQ(r0.dew_point_c, 7.0);
  EXPECT_EQ(r0.pressure_pa, 102000.0);
  EXPECT_EQ(r0.horizontal_infrared_w_m2, 305.0);
  EXPECT_EQ(r0.direct_normal_w_m2, 0.0);
  // Last record: 2004,12,31,24,... ; liquid precipitation depth 999 = missing.
  const WeatherRecord& rn = epw.records.back();
  EXPECT_EQ(rn.month, 12);
  EXPECT_EQ(rn.day, 31);
  EXPECT_EQ(rn.hour, 24);
  EXPECT_EQ(rn.source_line, 8768);
  EXPECT_FALSE(rn.liquid_precipitation_depth_mm.has_value());
  // No DNI/DHI is missing in this file, and its largest values (awk over the file).
  double max_dni = 0, max_dhi = 0, max_zenith = 0;
  for (const WeatherRecord& r : epw.records) {
    ASSERT_TRUE(r.direct_normal_w_m2 && r.diffuse_horizontal_w_m2) << "line " << r.source_line;
    max_dni = std::max(max_dni, *r.direct_normal_w_m2);
    max_dhi = std::max(max_dhi, *r.diffuse_horizontal_w_m2);
    if (r.zenith_luminance_cd_m2) max_zenith = std::max(max_zenith, *r.zenith_luminance_cd_m2);
  }
  EXPECT_EQ(max_dni, 951.0);
  EXPECT_EQ(max_dhi, 436.0);
  EXPECT_EQ(max_zenith, 33180.0);  // zenith luminance above 9999 is data, not "missing"
}

TEST(EpwReader, MannheimReadsCleanly) {
  const std::string path = MannheimEpw;
  ASSERT_TRUE(exists(path)) << "missing " << path;
  const EpwFile epw = read_epw(path);
  EXPECT_TRUE(epw.warnings.empty());
  ASSERT_EQ(epw.records.size(), 8760u);
  // LOCATION,Mannheim,BW,DEU,BBSR,107290,49.52000,8.55000,1.0,96.0
  const EpwLocation& loc = epw.header.location;
  EXPECT_EQ(loc.city, "Mannheim");
  EXPECT_EQ(loc.state, "BW");
  EXPECT_EQ(loc.country, "DEU");
  EXPECT_EQ(loc.source, "BBSR");
  EXPECT_EQ(loc.wmo, "107290");
  EXPECT_EQ(loc.latitude_deg, 49.52);
  EXPECT_EQ(loc.longitude_east_deg, 8.55);
  EXPECT_EQ(loc.time_zone_h, 1.0);
  EXPECT_EQ(loc.elevation_m, 96.0);
  EXPECT_EQ(epw.header.data_period.start_weekday, "Monday");
  EXPECT_EQ(epw.records.front().year, 2005);
}

// ---- the synthetic file and documented handling ---------------------------------------------

TEST(EpwReader, SyntheticFileIsValid) {
  const SyntheticEpw epw;
  const EpwFile f = epw.read();
  EXPECT_EQ(f.records.size(), 8760u);
  EXPECT_TRUE(f.warnings.empty());
  EXPECT_EQ(f.records[8].direct_normal_w_m2, 190.0);  // hour 9: 100 + 10 * 9
  EXPECT_EQ(f.records[8].diffuse_horizontal_w_m2, 59.0);
}

TEST(EpwReader, MissingValueCodesBecomeNullopt) {
  SyntheticEpw epw;
  const int line = SyntheticEpw::line_of(6, 21, 12);
  epw.set_field(line, 7, "99.9");       // dry bulb
  epw.set_field(line, 8, "99.9");       // dew point
  epw.set_field(line, 9, "999");        // relative humidity
  epw.set_field(line, 10, "999999");    // pressure
  epw.set_field(line, 14, "9999");      // GHI
  epw.set_field(line, 15, "9999");      // DNI
  epw.set_field(line, 16, "9999");      // DHI
  epw.set_field(line, 17, "999999");    // global illuminance
  epw.set_field(line, 18, "999900");    // direct illuminance: >= 999900 is missing
  epw.set_field(line, 19, "");          // empty field: missing
  epw.set_field(line, 20, "9999");      // zenith luminance: exactly 9999 is missing
  epw.set_field(line, 23, "99");        // total sky cover
  const EpwFile f = epw.read();
  ASSERT_EQ(f.records.size(), 8760u);
  const WeatherRecord& r = f.records[static_cast<std::size_t>(line - 9)];
  ASSERT_EQ(r.source_line, line);
  EXPECT_FALSE(r.dry_bulb_c);
  EXPECT_FALSE(r.dew_point_c);
  EXPECT_FALSE(r.relative_humidity_percent);
  EXPECT_FALSE(r.pressure_pa);
  EXPECT_FALSE(r.global_horizontal_w_m2);
  EXPECT_FALSE(r.direct_normal_w_m2);
  EXPECT_FALSE(r.diffuse_horizontal_w_m2);
  EXPECT_FALSE(r.global_horizontal_lux);
  EXPECT_FALSE(r.direct_normal_lux);
  EXPECT_FALSE(r.diffuse_horizontal_lux);
  EXPECT_FALSE(r.zenith_luminance_cd_m2);
  EXPECT_FALSE(r.total_sky_cover_tenths);
  EXPECT_EQ(r.opaque_sky_cover_tenths, 4.0);  // untouched neighbours stay
  // Consumers locate what they need but find missing:
  EXPECT_EQ(epw_field_location(f, r, epw_field::DirectNormalRadiation).to_string(),
            "t.epw:" + std::to_string(line) + ":15");
  EXPECT_STREQ(epw_field_name(15), "direct normal radiation");
  EXPECT_STREQ(epw_field_name(0), "unknown field");
  EXPECT_STREQ(epw_field_name(36), "unknown field");
}

TEST(EpwReader, MinuteSixtyAndZeroAreBothAccepted) {
  SyntheticEpw epw;
  for (std::size_t i = 8; i < epw.lines.size(); i += 2) epw.set_field(static_cast<int>(i) + 1, 5, "60");
  const EpwFile f = epw.read();
  EXPECT_EQ(f.records.size(), 8760u);
  EXPECT_EQ(f.records[0].minute, 60);
  EXPECT_EQ(f.records[1].minute, 0);
}

TEST(EpwReader, LeapYearWith8784Records) {
  const SyntheticEpw epw(/*leap_flag=*/true, /*leap_records=*/true);
  const EpwFile f = epw.read();
  ASSERT_EQ(f.records.size(), 8784u);
  EXPECT_TRUE(f.leap_day_present);
  EXPECT_TRUE(f.warnings.empty());
  EXPECT_EQ(f.records[59 * 24 - 24].month, 2);  // day 59 = Feb 28, day 60 = Feb 29
  EXPECT_EQ(f.records[59 * 24].day, 29);
  EXPECT_EQ(f.records[60 * 24].month, 3);
}

TEST(EpwReader, UndeclaredLeapDayIsKeptWithAWarning) {
  const SyntheticEpw epw(/*leap_flag=*/false, /*leap_records=*/true);
  const EpwFile f = epw.read();
  ASSERT_EQ(f.records.size(), 8784u);
  EXPECT_TRUE(f.leap_day_present);
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_EQ(f.warnings[0].format(),
            "t.epw:1425:3: warning: February 29 present although the HOLIDAYS/DAYLIGHT SAVINGS "
            "line says LeapYear observed = No; the leap day is kept (366-day year)\n");
}

TEST(EpwReader, PartialDataPeriodIsAcceptedWhenDeclared) {
  SyntheticEpw epw;
  epw.lines[7] = "DATA PERIODS,1,1,Data,Sunday, 1/ 1, 1/31";
  epw.lines.resize(8 + 31 * 24);
  EXPECT_EQ(epw.read().records.size(), 744u);
}

// ---- corrupted texts: exact located messages ------------------------------------------------

struct Corruption {
  const char* name;
  void (*apply)(SyntheticEpw&);
  std::vector<std::string> expected;  ///< first line of every diagnostic, in order
};

std::vector<Corruption> corruptions() {
  return {
      {"empty file", [](SyntheticEpw& e) { e.lines.clear(); },
       {"t.epw:1: error: empty file: expected the 'LOCATION' line (an EPW file has 8 header lines)"}},
      {"header only partly there", [](SyntheticEpw& e) { e.lines.resize(3); },
       {"t.epw:4: error: file ends in the header: expected the 'GROUND TEMPERATURES' line (an "
        "EPW file has 8 header lines)"}},
      {"misspelled header keyword",
       [](SyntheticEpw& e) { e.lines[2] = "TYPICAL/EXTREM PERIODS,0"; },
       {"t.epw:3:1: error: header line 3 should start with 'TYPICAL/EXTREME PERIODS', found "
        "'TYPICAL/EXTREM PERIODS'"}},
      {"header line missing", [](SyntheticEpw& e) { e.lines.erase(e.lines.begin() + 6); },
       {"t.epw:7:1: error: header line 7 should start with 'COMMENTS 2', found 'DATA PERIODS'"}},
      {"no header at all", [](SyntheticEpw& e) { e.lines.erase(e.lines.begin(), e.lines.begin() + 8); },
       {"t.epw:1:1: error: header line 1 should start with 'LOCATION', found '1999' (a header "
        "line is missing)"}},
      {"short LOCATION line",
       [](SyntheticEpw& e) { e.lines[0] = "LOCATION,Oakland,CA,USA,TMY3,724930,37.72,-122.22"; },
       {"t.epw:1:9: error: LOCATION line has 8 fields, expected 10 (field 9 (time zone) is "
        "missing)"}},
      {"letters in latitude",
       [](SyntheticEpw& e) { e.lines[0] = "LOCATION,Oakland,CA,USA,TMY3,724930,37.7a,-122.22,-8.0,2.0"; },
       {"t.epw:1:7: error: field 7 (latitude): '37.7a' is not a number"}},
      {"time zone out of range",
       [](SyntheticEpw& e) { e.lines[0] = "LOCATION,Oakland,CA,USA,TMY3,724930,37.72,-122.22,-120,2.0"; },
       {"t.epw:1:9: error: field 9 (time zone): -120 is outside [-12, 14] hours (east positive)"}},
      {"bad leap flag", [](SyntheticEpw& e) { e.lines[4] = "HOLIDAYS/DAYLIGHT SAVINGS,Maybe,0,0,0"; },
       {"t.epw:5:2: error: field 2 (LeapYear observed): expected 'Yes' or 'No', found 'Maybe'"}},
      {"sub-hourly data period",
       [](SyntheticEpw& e) { e.lines[7] = "DATA PERIODS,1,4,Data,Sunday, 1/ 1,12/31"; },
       {"t.epw:8:3: error: field 3 (records per hour): only hourly data (1 record per hour) is "
        "supported, found '4'"}},
      {"truncated file",
       [](SyntheticEpw& e) {
         e.lines.resize(8 + 100);
         e.lines.back().resize(30);  // cut mid-record, as an interrupted download would
       },
       {"t.epw:108:7: error: record has 6 fields, expected 35 (field 7 (dry bulb "
        "temperature) is missing)",
        "t.epw:109: error: file ends before the end of the data period: expected 8760 hourly "
        "records (1/1 hour 1 to 12/31 hour 24), found 99; next expected 1/5 hour 5"}},
      {"wrong field count (one short)",
       [](SyntheticEpw& e) {
         std::string& l = e.lines[18];
         l.erase(l.rfind(','));
       },
       {"t.epw:19:35: error: record has 34 fields, expected 35 (field 35 (liquid precipitation "
        "quantity) is missing)"}},
      {"wrong field count (one extra)", [](SyntheticEpw& e) { e.lines[18] += ",0"; },
       {"t.epw:19:36: error: record has 36 fields, expected 35"}},
      {"letters in DNI",
       [](SyntheticEpw& e) { e.set_field(SyntheticEpw::line_of(3, 2, 10), 15, "12a"); },
       {"t.epw:1458:15: error: field 15 (direct normal radiation): '12a' is not a number"}},
      {"letters in month", [](SyntheticEpw& e) { e.set_field(20, 2, "Jan"); },
       {"t.epw:20:2: error: field 2 (month): 'Jan' is not an integer"}},
      {"day 30 in February",
       [](SyntheticEpw& e) { e.set_field(SyntheticEpw::line_of(2, 28, 5), 3, "30"); },
       {"t.epw:1405:3: error: field 3 (day): 30 is outside 1..29 (days of month 2)"}},
      {"hour 0", [](SyntheticEpw& e) { e.set_field(9, 4, "0"); },
       {"t.epw:9:4: error: field 4 (hour): 0 is outside 1..24 (EPW hour h covers (h-1, h])"}},
      {"minute 30 in hourly data", [](SyntheticEpw& e) { e.set_field(12, 5, "30"); },
       {"t.epw:12:5: error: field 5 (minute): '30' is not valid for hourly data (expected 0 or 60)"}},
      {"negative diffuse irradiance",
       [](SyntheticEpw& e) { e.set_field(SyntheticEpw::line_of(7, 4, 12), 16, "-5"); },
       {"t.epw:4436:16: error: field 16 (diffuse horizontal radiation): -5 W/m^2 is negative "
        "[0, 1500]"}},
      {"direct normal above the physical limit",
       [](SyntheticEpw& e) { e.set_field(SyntheticEpw::line_of(7, 4, 13), 15, "1600"); },
       {"t.epw:4437:15: error: field 15 (direct normal radiation): 1600 W/m^2 is outside the "
        "physical range [0, 1500]"}},
      {"dew point below -70 degC", [](SyntheticEpw& e) { e.set_field(30, 8, "-80"); },
       {"t.epw:30:8: error: field 8 (dew point temperature): -80 degC is outside the physical range "
        "[-70, 70]"}},
      {"two records swapped", [](SyntheticEpw& e) { std::swap(e.lines[100], e.lines[101]); },
       {"t.epw:101:2: error: missing record(s): expected 1/4 hour 21, found 1/4 hour 22",
        "t.epw:102:2: error: record 1/4 hour 21 is out of order: expected 1/4 hour 23 after "
        "1/4 hour 22 on line 101"}},
      {"duplicate hour", [](SyntheticEpw& e) { e.lines[101] = e.lines[100]; },
       {"t.epw:102:2: error: duplicate record 1/4 hour 21 (already on line 101)",
        "t.epw:103:2: error: missing record(s): expected 1/4 hour 22, found 1/4 hour 23"}},
      {"a day missing (8736 records)",
       [](SyntheticEpw& e) {
         const auto first = e.lines.begin() + SyntheticEpw::line_of(5, 10, 1) - 1;
         e.lines.erase(first, first + 24);
       },
       {"t.epw:3105:2: error: missing record(s): expected 5/10 hour 1, found 5/11 hour 1"}},
      {"declared leap year without Feb 29",
       [](SyntheticEpw& e) { e.lines[4] = "HOLIDAYS/DAYLIGHT SAVINGS,Yes,0,0,0"; },
       {"t.epw:1425:2: error: missing record(s): expected 2/29 hour 1, found 3/1 hour 1 (the "
        "header says LeapYear observed = Yes, so February 29 must be present)"}},
      {"extra record after 12/31 hour 24",
       [](SyntheticEpw& e) { e.lines.push_back(SyntheticEpw::record(1, 1, 1)); },
       {"t.epw:8769:2: error: record 1/1 hour 1 is after the end of the data period (12/31 "
        "hour 24)"}},
      {"blank line between records", [](SyntheticEpw& e) { e.lines.insert(e.lines.begin() + 20, ""); },
       {"t.epw:21: error: blank line between records"}},
  };
}

TEST(EpwReader, CorruptedTextsGiveLocatedMessages) {
  for (const Corruption& c : corruptions()) {
    SCOPED_TRACE(c.name);
    SyntheticEpw epw;
    c.apply(epw);
    EXPECT_EQ(error_lines(epw), c.expected);
  }
}

TEST(EpwReader, TrailingBlankLinesAreIgnored) {
  SyntheticEpw epw;
  epw.lines.push_back("");
  epw.lines.push_back("  ");
  EXPECT_EQ(epw.read().records.size(), 8760u);
}

TEST(EpwReader, InputErrorTextIsCompilerStyle) {
  SyntheticEpw epw;
  epw.set_field(40, 16, "-1");
  try {
    epw.read();
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "t.epw:40:16: error: field 16 (diffuse horizontal radiation): -1 W/m^2 is negative "
              "[0, 1500]\n1 error generated.\n");
  }
}

TEST(EpwReader, ErrorsAreCappedButCounted) {
  SyntheticEpw epw;
  for (std::size_t i = 8; i < epw.lines.size(); ++i) epw.set_field(static_cast<int>(i) + 1, 16, "bright");
  try {
    epw.read(/*max_errors=*/10);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.diagnostics().size(), 10u);
    const std::string what = e.what();
    EXPECT_NE(what.find("note: 8750 more error(s) not shown"), std::string::npos);
    EXPECT_NE(what.find("8760 errors generated."), std::string::npos);
  }
}

TEST(EpwReader, UnopenableFileIsARuntimeError) {
  EXPECT_THROW(read_epw("/nonexistent/dir/x.epw"), std::runtime_error);
}

// Seeded random corruptions: the reader must either succeed or throw InputError whose
// diagnostics all point into the file; never crash or throw anything else.
TEST(EpwReader, FuzzedCorruptionsNeverCrash) {
  SyntheticEpw base;  // January only, so 150 iterations stay fast
  base.lines[7] = "DATA PERIODS,1,1,Data,Sunday, 1/ 1, 1/31";
  base.lines.resize(8 + 31 * 24);
  const std::string text = base.text();
  std::mt19937 rng(20240611u);
  const std::string alphabet = "0123456789,.-+eE \r\n\t/abcXYZ\xff";
  int failures = 0, successes = 0;
  for (int iteration = 0; iteration < 150; ++iteration) {
    std::string t = text;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int k = 0; k < edits && !t.empty(); ++k) {
      const std::size_t pos = rng() % t.size();
      switch (rng() % 5) {
        case 0: t[pos] = alphabet[rng() % alphabet.size()]; break;      // replace a byte
        case 1: t.erase(pos, 1 + rng() % 400); break;                   // delete a run
        case 2: t.insert(pos, 1, alphabet[rng() % alphabet.size()]); break;
        case 3: t.resize(pos); break;                                   // truncate
        case 4: t.insert(pos, t.substr(rng() % t.size(), 200)); break;  // duplicate a chunk
      }
    }
    std::istringstream in(t);
    try {
      read_epw(in, "fuzz.epw");
      ++successes;
    } catch (const InputError& e) {
      ++failures;
      ASSERT_FALSE(e.diagnostics().empty());
      for (const Diagnostic& d : e.diagnostics()) {
        EXPECT_EQ(d.location.file, "fuzz.epw");
        EXPECT_GE(d.location.line, 1);
        EXPECT_GE(d.location.column, 0);
        EXPECT_LE(d.location.column, 36);
      }
    }
  }
  // Most random edits must be detected (a few land on free text, e.g. the flags field).
  EXPECT_GT(failures, 100);
  EXPECT_EQ(failures + successes, 150);
}

}  // namespace
}  // namespace dayphoton::weather
