// .wea: EPW -> .wea must reproduce RADIANCE epw2wea's output for Oakland
// (refdata/results/c_annual/oakland.wea, every line equal as printed), write/read round trip,
// west-positive sign conventions, and located read errors (file:line:column).
#include "dayphoton/weather/wea.h"

#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

#include "epw_test_support.h"

namespace dayphoton::weather {
namespace {

using test::SyntheticEpw;

std::vector<std::string> lines_of(std::istream& in) {
  std::vector<std::string> out;
  std::string l;
  while (std::getline(in, l)) {
    if (!l.empty() && l.back() == '\r') l.pop_back();
    out.push_back(l);
  }
  return out;
}

TEST(Wea, OaklandEpwConvertsToTheRadianceReferenceWea) {
  const std::string epw_path = std::string(DAYPHOTON_SOURCE_DIR) + "/projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw";
  const std::string wea_path = std::string(DAYPHOTON_TEST_DATA_DIR) + "/radiance/oakland.wea";
  std::ifstream ref(wea_path);
  ASSERT_TRUE(std::ifstream(epw_path) && ref) << "missing " << epw_path << " or " << wea_path;

  const WeaFile wea = epw_to_wea(read_epw(epw_path));
  std::ostringstream out;
  write_wea(out, wea);
  std::istringstream ours_in(out.str());
  const std::vector<std::string> ours = lines_of(ours_in);
  const std::vector<std::string> theirs = lines_of(ref);
  ASSERT_EQ(theirs.size(), 6u + 8760u);
  ASSERT_EQ(ours.size(), theirs.size());
  int differing = 0;
  for (std::size_t i = 0; i < ours.size(); ++i) {
    if (ours[i] != theirs[i] && ++differing <= 5)
      ADD_FAILURE() << "line " << i + 1 << ": ours '" << ours[i] << "' vs RADIANCE '" << theirs[i] << "'";
  }
  EXPECT_EQ(differing, 0);
  // Header in RADIANCE's west-positive convention.
  EXPECT_EQ(wea.header.place, "Oakland Metropolitan Arpt_USA");
  EXPECT_EQ(wea.header.longitude_west_deg, 122.22);
  EXPECT_EQ(wea.header.time_zone_west_deg, 120.0);

  // Reading the reference file gives the same values as the conversion.
  const WeaFile read_back = read_wea(wea_path);
  ASSERT_EQ(read_back.records.size(), wea.records.size());
  for (std::size_t i = 0; i < wea.records.size(); ++i) {
    ASSERT_EQ(read_back.records[i].hour_lst, wea.records[i].hour_lst) << i;
    ASSERT_EQ(read_back.records[i].direct, wea.records[i].direct) << i;
    ASSERT_EQ(read_back.records[i].diffuse, wea.records[i].diffuse) << i;
  }
  EXPECT_EQ(read_back.header.latitude_deg, 37.72);
  EXPECT_EQ(read_back.header.site_elevation_m, 2.0);
}

TEST(Wea, EastOfGreenwichBecomesNegativeWest) {
  SyntheticEpw epw;
  epw.lines[0] = "LOCATION,Mannheim,BW,DEU,BBSR,107290,49.52000,8.55000,1.0,96.0";
  const WeaFile wea = epw_to_wea(epw.read());
  std::ostringstream out;
  write_wea(out, wea);
  EXPECT_EQ(out.str().substr(0, out.str().find("1 1 0.500")),
            "place Mannheim_DEU\nlatitude 49.52\nlongitude -8.55\ntime_zone -15\n"
            "site_elevation 96.0\nweather_data_file_units 1\n");
}

TEST(Wea, HalfHourTimeZonesAreKept) {
  SyntheticEpw epw;
  epw.lines[0] = "LOCATION,Delhi,DL,IND,ISHRAE,421820,28.58,77.2,5.5,216.0";
  const WeaFile wea = epw_to_wea(epw.read());
  EXPECT_EQ(wea.header.time_zone_west_deg, -82.5);  // epw2wea's atoi would give -75
  std::ostringstream out;
  write_wea(out, wea);
  EXPECT_NE(out.str().find("\ntime_zone -82.5\n"), std::string::npos);
}

TEST(Wea, MidpointHoursAndValues) {
  const WeaFile wea = epw_to_wea(SyntheticEpw().read());
  ASSERT_EQ(wea.records.size(), 8760u);
  EXPECT_EQ(wea.records[0].hour_lst, 0.5);
  EXPECT_EQ(wea.records[11].hour_lst, 11.5);
  EXPECT_EQ(wea.records[11].direct, 220.0);  // synthetic: 100 + 10 * 12
  EXPECT_EQ(wea.records[11].diffuse, 62.0);
  EXPECT_EQ(wea.records[8759].hour_lst, 23.5);
}

TEST(Wea, MissingDniIsReportedAtTheEpwField) {
  SyntheticEpw epw;
  epw.set_field(300, 15, "9999");
  epw.set_field(301, 16, "9999");
  try {
    epw_to_wea(epw.read());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.diagnostics().size(), 2u);
    EXPECT_EQ(e.diagnostics()[0].format(),
              "t.epw:300:15: error: field 15 (direct normal radiation) is missing; a .wea file "
              "needs it\n");
    EXPECT_EQ(e.diagnostics()[1].location.to_string(), "t.epw:301:16");
  }
}

TEST(Wea, WriteReadRoundTrip) {
  WeaFile wea;
  wea.header.place = "Somewhere Nice_XYZ";
  wea.header.latitude_deg = -33.867;
  wea.header.longitude_west_deg = -151.2;
  wea.header.time_zone_west_deg = -150;
  wea.header.site_elevation_m = 39.25;
  wea.header.units = WeaUnits::DirectNormalDiffuseHorizontalIlluminance;
  for (int i = 0; i < 48; ++i)
    wea.records.push_back({12, 30 + i / 24, (i % 24) + 0.5, 1000.0 * (i % 13), 250.0 * (i % 7), 0});
  std::ostringstream first;
  write_wea(first, wea);
  std::istringstream in(first.str());
  const WeaFile back = read_wea(in, "round.wea");
  EXPECT_EQ(back.header.place, wea.header.place);
  EXPECT_EQ(back.header.latitude_deg, wea.header.latitude_deg);
  EXPECT_EQ(back.header.longitude_west_deg, wea.header.longitude_west_deg);
  EXPECT_EQ(back.header.time_zone_west_deg, wea.header.time_zone_west_deg);
  EXPECT_EQ(back.header.site_elevation_m, wea.header.site_elevation_m);
  EXPECT_EQ(back.header.units, wea.header.units);
  ASSERT_EQ(back.records.size(), wea.records.size());
  for (std::size_t i = 0; i < wea.records.size(); ++i) {
    EXPECT_EQ(back.records[i].month, wea.records[i].month);
    EXPECT_EQ(back.records[i].day, wea.records[i].day);
    EXPECT_EQ(back.records[i].hour_lst, wea.records[i].hour_lst);
    EXPECT_EQ(back.records[i].direct, wea.records[i].direct);
    EXPECT_EQ(back.records[i].diffuse, wea.records[i].diffuse);
    EXPECT_EQ(back.records[i].source_line, static_cast<int>(i) + 7);
  }
  std::ostringstream second;
  write_wea(second, back);
  EXPECT_EQ(second.str(), first.str());
}

TEST(Wea, WriteFileAtomically) {
  const std::string path = ::testing::TempDir() + "weather_wea_test.wea";
  const WeaFile wea = epw_to_wea(SyntheticEpw().read());
  write_wea_file(path, wea);
  EXPECT_EQ(read_wea(path).records.size(), 8760u);
  std::remove(path.c_str());
}

std::string header() {
  return "place A_B\nlatitude 37.72\nlongitude 122.22\ntime_zone 120\nsite_elevation 2.0\n"
         "weather_data_file_units 1\n";
}

std::vector<std::string> errors(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  try {
    read_wea(in, "x.wea");
  } catch (const InputError& e) {
    for (const Diagnostic& d : e.diagnostics()) out.push_back(d.format());
  }
  return out;
}

TEST(Wea, ReadErrorsAreLocatedByLineAndColumn) {
  EXPECT_EQ(errors(header() + "1 1 0.500 0 0\n1 1 1.500 12x 3\n"),
            std::vector<std::string>{"x.wea:8:11: error: direct: '12x' is not a number\n"
                                     "    1 1 1.500 12x 3\n"
                                     "              ^\n"});
  EXPECT_EQ(errors(header() + "2 30 0.500 0 0\n"),
            std::vector<std::string>{"x.wea:7:3: error: day: expected 1..29, found '30'\n"
                                     "    2 30 0.500 0 0\n"
                                     "      ^\n"});
  EXPECT_EQ(errors(header() + "1 1 0.500 0 -4\n"),
            std::vector<std::string>{"x.wea:7:13: error: diffuse: -4 W/m^2 is negative [0, 1500]\n"
                                     "    1 1 0.500 0 -4\n"
                                     "                ^\n"});
  EXPECT_EQ(errors(header() + "1 1 25.5 0 0\n"),
            std::vector<std::string>{"x.wea:7:5: error: hour: expected decimal local standard "
                                     "time in [0, 24], found '25.5'\n"
                                     "    1 1 25.5 0 0\n"
                                     "        ^\n"});
  EXPECT_EQ(errors(header() + "1 1 0.500 0\n"),
            std::vector<std::string>{"x.wea:7: error: expected 5 values (month day hour direct "
                                     "diffuse), found 4\n"
                                     "    1 1 0.500 0\n"});
  EXPECT_EQ(errors("place A_B\nlatitude 37.72\nlongitud 122.22\n"),
            std::vector<std::string>{"x.wea:3:1: error: header line 3 should start with "
                                     "'longitude', found 'longitud'\n"
                                     "    longitud 122.22\n"
                                     "    ^\n"});
  EXPECT_EQ(errors("place A_B\nlatitude 95\n"),
            (std::vector<std::string>{"x.wea:2:10: error: latitude: 95 is outside [-90, 90] "
                                      "degrees (north positive)\n"
                                      "    latitude 95\n"
                                      "             ^\n",
                                      "x.wea:3: error: file ends in the header: expected the "
                                      "'longitude' line (a .wea file has 6 header lines)\n"}));
  std::string units4 = header();
  units4.replace(units4.find("units 1"), 7, "units 4");
  EXPECT_EQ(errors(units4).size(), 1u);
  EXPECT_NE(errors(units4)[0].find("x.wea:6:25: error: weather_data_file_units: expected 1, 2 "
                                   "or 3, found '4'"),
            std::string::npos);
}

// Seeded random corruptions of a .wea text: success or InputError, never a crash.
TEST(Wea, FuzzedCorruptionsNeverCrash) {
  std::ostringstream out;
  write_wea(out, epw_to_wea(SyntheticEpw().read()));
  const std::string text = out.str().substr(0, 20000);
  std::mt19937 rng(7u);
  const std::string alphabet = "0123456789 .-+\n\tabc_\xff";
  int failures = 0;
  for (int iteration = 0; iteration < 200; ++iteration) {
    std::string t = text;
    for (int k = 0; k < 3 && !t.empty(); ++k) {
      const std::size_t pos = rng() % t.size();
      switch (rng() % 3) {
        case 0: t[pos] = alphabet[rng() % alphabet.size()]; break;
        case 1: t.erase(pos, 1 + rng() % 50); break;
        case 2: t.insert(pos, 1, alphabet[rng() % alphabet.size()]); break;
      }
    }
    std::istringstream in(t);
    try {
      read_wea(in, "fuzz.wea");
    } catch (const InputError& e) {
      ++failures;
      for (const Diagnostic& d : e.diagnostics()) EXPECT_GE(d.location.line, 1);
    }
  }
  EXPECT_GT(failures, 100);
}

}  // namespace
}  // namespace dayphoton::weather
