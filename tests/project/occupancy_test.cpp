// `metrics.occupancy` (project/src/occupancy_reader.cpp, occupancy_csv.cpp; docs/metrics.md
// "Occupancy schedules"): a school week with holidays and daylight saving time loads into
// exactly those values (a day's own key over weekdays/weekends over every_day); a CSV
// schedule loads its values; every bad value is a located error at the key in the project
// or at the line and column in the CSV.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/project/project.h"
#include "located_errors.h"

namespace dayphoton::project {
namespace {

namespace fs = std::filesystem;

// Lines 1-6: a daylight-factor project; snippets start at line 7.
const std::string Base =
    "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"
    "outputs: {annual_illuminance: false, metrics: false}\n"
    "materials:\n"
    "  glazing: {type: glass, transmittance: 0.6}\n"
    "  walls: {type: lambertian, reflectance: 0.5}\n"
    "geometry: {}\n";

/// A folder with the project's CSV files, removed at the end of the test.
struct Folder {
  fs::path dir = fs::temp_directory_path() / ("dayphoton_occupancy_" + std::to_string(::getpid()));
  Folder() { fs::create_directories(dir); }
  ~Folder() { fs::remove_all(dir); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  }
  std::string project() const { return (dir / "project.yaml").string(); }
};

/// A project file "written" in a folder that does not exist, so relative paths resolve there.
const fs::path FakeFolder = fs::temp_directory_path() / "dayphoton_occupancy_no_such_folder";
const std::string FakeProject = (FakeFolder / "project.yaml").string();

std::vector<std::string> errors_of(const std::string& text, const std::string& path = FakeProject) {
  return test::located_errors([&] { load_project_from_string(Base + text, path); });
}

using Windows = OccupancySpec::Windows;

}  // namespace

TEST(Occupancy, SchoolWeekLoads) {
  const Project p = load_project_from_string(Base +
                                                 "metrics:\n"
                                                 "  occupancy:\n"
                                                 "    every_day: [9, 12]\n"
                                                 "    weekdays: [[8, 12], [13, 15.5]]\n"
                                                 "    wednesday: [8, 12]\n"
                                                 "    sunday: closed\n"
                                                 "    holidays: [12-21..01-03, 05-01]\n"
                                                 "    holiday_hours: [10, 11]\n"
                                                 "    january_1: monday\n"
                                                 "    daylight_saving: eu\n",
                                             FakeProject);
  const OccupancySpec& o = p.metrics.occupancy;
  ASSERT_TRUE(o.given);
  EXPECT_EQ(o.location.line, 9);
  const Windows lessons = {{8, 12}, {13, 15.5}};
  EXPECT_EQ(o.week[0], lessons);
  EXPECT_EQ(o.week[2], (Windows{{8, 12}}));
  EXPECT_EQ(o.week[4], lessons);
  EXPECT_EQ(o.week[5], (Windows{{9, 12}}));  // Saturday: every_day
  EXPECT_TRUE(o.week[6].empty());            // Sunday: closed
  ASSERT_EQ(o.holidays.size(), 2u);
  EXPECT_EQ(o.holidays[0].from_month, 12);
  EXPECT_EQ(o.holidays[0].from_day, 21);
  EXPECT_EQ(o.holidays[0].to_month, 1);
  EXPECT_EQ(o.holidays[0].to_day, 3);
  EXPECT_EQ(o.holidays[1].from_month, 5);
  EXPECT_EQ(o.holidays[1].to_day, 1);
  EXPECT_EQ(o.holiday_hours, (Windows{{10, 11}}));
  EXPECT_EQ(o.january_1, 0);
  EXPECT_EQ(o.daylight_saving, "eu");
  // Without the key: the daily window, the old keys.
  const Project old = load_project_from_string(Base + "metrics: {occupancy_start: 7}\n", FakeProject);
  EXPECT_FALSE(old.metrics.occupancy.given);
  EXPECT_EQ(old.metrics.occupancy_start_h, 7);
}

TEST(Occupancy, SensorSetsHaveTheirOwn) {
  const Project p = load_project_from_string(
      Base +
          "sensors:\n"
          "  grids: [{name: a, polygon: [[0, 0, 0], [1, 0, 0], [1, 1, 0]], occupancy: {weekends: [10, 16]}}]\n"
          "  points: [{name: b, points: [[0, 0, 1, 0, 0, 1]], occupancy: {every_day: [0, 24]}}]\n",
      FakeProject);
  EXPECT_FALSE(p.metrics.occupancy.given);
  ASSERT_TRUE(p.sensors.grids[0].occupancy.given);
  EXPECT_EQ(p.sensors.grids[0].occupancy.week[6], (Windows{{10, 16}}));
  EXPECT_TRUE(p.sensors.grids[0].occupancy.week[0].empty());
  EXPECT_EQ(p.sensors.points[0].occupancy.week[3], (Windows{{0, 24}}));
  EXPECT_EQ(errors_of("sensors:\n"
                      "  points: [{name: b, points: [[0, 0, 1, 0, 0, 1]], occupancy: {every_day: [0, 25]}}]\n"),
            (std::vector<std::string>{"8:79: 'every_day': hours must be in [0, 24], got 25"}));
}

TEST(Occupancy, EveryBadValueIsLocated) {
  EXPECT_EQ(errors_of("metrics:\n"
                      "  occupancy_start: 7\n"
                      "  occupancy:\n"
                      "    weekdays: [8, 25]\n"
                      "    saturday: [12, 9]\n"
                      "    sunday: shut\n"
                      "    monday: [[8, 12], [11, 14]]\n"
                      "    holidays: [2026-12-25, 02-30, 07-01..08-32]\n"
                      "    january_1: mon\n"
                      "    daylight_saving: au\n"
                      "    tusday: [8, 9]\n"),
            (std::vector<std::string>{
                "8:3: 'occupancy_start' cannot be combined with 'occupancy': write the hours there (every_day: "
                "[start, end])",
                "10:19: 'weekdays': hours must be in [0, 24], got 25",
                "13:23: 'monday': windows must be in time order and must not overlap: [11, 14] starts before the "
                "previous one ends (12)",
                "11:20: 'saturday': the end (9) must be after the start (12)",
                "12:13: 'sunday': expected hours as [start, end], a list of such windows ([[8, 12], [13, 17]]) or "
                "'closed', got 'shut'",
                "14:16: 'holidays': '2026-12-25' is not a date MM-DD (12-25) or a period MM-DD..MM-DD "
                "(07-06..08-31) (the weather file stands for a typical year: write the date without the year, "
                "'12-25')",
                "14:28: 'holidays': '02-30' is not a date MM-DD (12-25) or a period MM-DD..MM-DD (07-06..08-31)",
                "14:35: 'holidays': '07-01..08-32' is not a date MM-DD (12-25) or a period MM-DD..MM-DD "
                "(07-06..08-31)",
                "15:16: unknown value 'mon' for 'january_1': expected one of monday, tuesday, wednesday, thursday, "
                "friday, saturday, sunday",
                "16:22: unknown value 'au' for 'daylight_saving': expected one of none, eu, us (did you mean 'eu'?)",
                "17:5: unknown key 'tusday' in occupancy (did you mean 'tuesday'?)",
            }));
  EXPECT_EQ(errors_of("metrics: {occupancy: {daylight_saving: eu}}\n"),
            (std::vector<std::string>{"7:22: the occupancy gives no hours: write every_day, weekdays, weekends or a "
                                      "day's hours (e.g. weekdays: [8, 17]), or a file"}));
  EXPECT_EQ(errors_of("metrics: {occupancy: {every_day: [8, 18], holiday_hours: [9, 10]}}\n"),
            (std::vector<std::string>{"7:58: 'holiday_hours' without 'holidays': list the holiday dates"}));
  EXPECT_EQ(errors_of("metrics: {occupancy: {file: missing.csv, weekdays: [8, 18]}}\n"),
            (std::vector<std::string>{
                "7:42: 'weekdays' cannot be combined with 'file': the CSV gives every hour",
                "7:29: occupancy schedule 'missing.csv' not found (looked for '" + (FakeFolder / "missing.csv").string() + "')"}));
}

TEST(Occupancy, CsvScheduleLoadsAndItsErrorsNameTheCsvLine) {
  const Folder folder;
  std::string values = "occupied\n";
  for (int i = 0; i < 8760; ++i) values += (i % 24 >= 8 && i % 24 < 16) ? "1\n" : "0\n";
  folder.write("school.csv", values);
  const Project p = load_project_from_string(Base + "metrics: {occupancy: {file: school.csv}}\n", folder.project());
  const OccupancySpec& o = p.metrics.occupancy;
  EXPECT_EQ(o.file, (folder.dir / "school.csv").string());
  ASSERT_EQ(o.hourly.size(), 8760u);
  EXPECT_FALSE(o.hourly[7]);
  EXPECT_TRUE(o.hourly[8]);
  EXPECT_FALSE(o.hourly[16]);

  const std::string bad = folder.write("bad.csv", "hour\n1\n0.5\n1,0\nyes\n\n2\n");
  try {
    load_project_from_string(Base + "metrics: {occupancy: {file: bad.csv}}\n", folder.project());
    FAIL() << "no error";
  } catch (const InputError& e) {
    std::vector<std::string> got;
    for (const Diagnostic& d : e.diagnostics()) {
      EXPECT_EQ(d.location.file, bad);
      got.push_back(std::to_string(d.location.line) + ":" + std::to_string(d.location.column) + ": " + d.message);
    }
    EXPECT_EQ(got, (std::vector<std::string>{
                       "3:1: occupancy must be 0 or 1, found 0.5 (a fraction: the metrics count whole occupied "
                       "hours; round or threshold the schedule first)",
                       "4:2: expected one value per line (1 occupied, 0 not), found 2 fields",
                       "5:1: expected 0 or 1, found 'yes'",
                       "7:1: occupancy must be 0 or 1, found 2",
                   }));
  }
}

}  // namespace dayphoton::project
