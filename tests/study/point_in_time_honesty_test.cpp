// The point-in-time standard error is honest (point_in_time_uncertainty.h): over Seeds
// independent runs (simulation.seed 1..Seeds) of a small side-lit room, every sensor's observed
// spread of each case's illuminance agrees with the standard error the runs report beside it
// (point_in_time.csv, `<case>_stderr_lux`): the mean ratio of observed to reported standard
// error within Sigmas standard deviations of 1 (its standard deviation from the runs' own
// correlations between sensors, seed_spread.h) and within the acceptance band 0.8 - 1.25 that
// the daylight factor's honesty tests ask (uncertainty_honesty_test.cpp). Three cases, each
// made of different parts: a weather hour with its sun (the sky over the basis with sub-patches,
// the exact direct sun and the sun bins' indirect sun), the CIE overcast sky (the direct part
// from the continuous sky, the photon part from the DF's continuous sky scaled) and a CIE clear
// sky with a sun (the direct part from its continuous sky, the photon part over the basis).
// Every sensor alone, too: none whose spread is more than twice its reported error (the
// penumbra of the sun patch, where the direct sun's shadow rays are noisy, would be).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "seed_spread.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/progress.h"
#include "dayphoton/study/study_runner.h"
#include "../temp_folder.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

constexpr int Seeds = 20;
constexpr double Sigmas = 4.0;
constexpr double TargetLow = 0.8, TargetHigh = 1.25;
/// No sensor's ratio above this: for normal errors (n - 1) R^2 c4^2 ~ chi^2(n - 1), and
/// P(chi^2(19) > 19 x 4 x 0.987^2 = 74) is 2e-8, so 960 honest sensors pass it but for
/// one chance in 50 000. A sensor whose error is left out shows it (the exact direct sun's
/// penumbra, an edge of the sun patch, reads about 5 without its shadow rays' variance).
constexpr double MaxSensorRatio = 2.0;
const char* const Cases[] = {"weather_sun", "overcast", "clear"};

/// The office's weather file (Oakland) cut to the one day of the weather case, 12-21 (its DATA
/// PERIODS line says so): the annual sky the case is taken from, and its sub-patch deltas,
/// which a run makes from the weather and does not cache, are then a day's, not a year's.
void write_one_day_weather(const fs::path& to) {
  std::ifstream in(std::string(DAYPHOTON_SOURCE_DIR) + "/projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw");
  ASSERT_TRUE(in);
  std::ofstream out(to);
  std::string line;
  for (int header = 0; header < 8 && std::getline(in, line); ++header)
    out << (line.rfind("DATA PERIODS", 0) == 0 ? "DATA PERIODS,1,1,Data,Monday,12/21,12/21" : line) << '\n';
  while (std::getline(in, line)) {
    const std::size_t year_end = line.find(',');  // year, month, day, hour, ...
    if (year_end != std::string::npos && line.compare(year_end + 1, 6, "12,21,") == 0) out << line << '\n';
  }
}

/// A 4 x 5 x 3 m room with a south window, in Oakland: at 12-21 11:30 (the weather file's hour
/// 12: 740 W/m^2 direct normal) the sun falls through the window onto the work plane.
std::string room_project(const fs::path& weather) {
  return std::string("site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n") +
         "weather: " + weather.string() + "\n" +
         "materials:\n"
         "  floor: {type: lambertian, reflectance: 0.2}\n"
         "  walls: {type: lambertian, reflectance: 0.5}\n"
         "  ceiling: {type: lambertian, reflectance: 0.7}\n"
         "  glazing: {type: glass, transmittance: 0.6}\n"
         "geometry:\n"
         "  rooms:\n"
         "    - name: room\n"
         "      size: [4, 5, 3]\n"
         "      materials: {floor: floor, ceiling: ceiling, walls: walls}\n"
         "      windows: [{name: win, wall: south, width: 2.4, height: 1.4, sill: 0.9, offset: 0.8, material: glazing}]\n"
         "sensors:\n"
         "  grids: [{name: floor, room: room, height: 0.8, spacing: 0.25, inset: 0.125}]\n"
         "simulation: {photons_per_bin: 300, direct_samples_per_bin: 9}\n"
         "outputs: {daylight_factor: true, annual_illuminance: false, metrics: false, coefficients: false,\n"
         "          images: false, report: false}\n"
         "points_in_time:\n"
         "  - {name: weather_sun, date: 12-21, time: \"11:30\", sky: weather}\n"
         "  - {name: overcast, date: 03-21, time: \"12:00\", sky: cie_overcast, diffuse_horizontal_illuminance: 20000}\n"
         "  - {name: clear, date: 06-21, time: \"10:00\", sky: cie, cie_type: 12, diffuse_horizontal_illuminance: 8000,\n"
         "     direct_normal_illuminance: 70000}\n";
}

/// point_in_time.csv's columns by name.
std::map<std::string, std::vector<double>> read_columns(const fs::path& csv) {
  std::map<std::string, std::vector<double>> columns;
  std::ifstream in(csv);
  EXPECT_TRUE(in) << csv;
  std::string line, field;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream header(line);
  while (std::getline(header, field, ',')) names.push_back(field);
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    for (std::size_t c = 0; std::getline(fields, field, ','); ++c) columns[names.at(c)].push_back(std::stod(field));
  }
  return columns;
}

TEST(PointInTimeHonesty, SpreadOverSeedsMatchesTheReportedStandardErrorOfEveryCase) {
  const fs::path dir = test::process_temp_dir() / "point_in_time_honesty";
  fs::create_directories(dir);
  const fs::path yaml = dir / "project.yaml";
  write_one_day_weather(dir / "one_day.epw");
  std::ofstream(yaml) << room_project(dir / "one_day.epw");
  project::Project p = project::load_project(yaml.string());
  const fs::path cache = dir / "cache";
  fs::remove_all(cache);
  // value[case][run][sensor], stderr alike.
  std::map<std::string, std::vector<std::vector<double>>> value, stderr_lux;
  for (int seed = 1; seed <= Seeds; ++seed) {
    p.simulation.seed = static_cast<std::uint64_t>(seed);
    const fs::path out = dir / std::to_string(seed);
    // One cache for all the runs: the annual sky (which the weather case is taken from) does
    // not depend on the seed and is made once; every photon and ray step does and is traced
    // again.
    fs::remove_all(out);
    RunSettings settings;
    settings.output_dir = out.string();
    settings.cache_dir = cache.string();
    std::ostringstream quiet;
    Progress progress(quiet, ProgressStyle::Quiet);
    run_study(p, settings, progress);
    const auto columns = read_columns(out / "floor" / "point_in_time.csv");
    for (const char* c : Cases) {
      ASSERT_TRUE(columns.count(std::string(c) + "_lux") && columns.count(std::string(c) + "_stderr_lux")) << c;
      value[c].push_back(columns.at(std::string(c) + "_lux"));
      stderr_lux[c].push_back(columns.at(std::string(c) + "_stderr_lux"));
    }
    fs::remove_all(out);
  }
  for (const char* c : Cases) {
    const test::SeedSpread h =
        test::seed_spread(value[c], stderr_lux[c], std::string("point in time ") + c, [](std::size_t) { return true; });
    ASSERT_GT(h.sensors, 0u) << c;
    EXPECT_NEAR(h.mean_ratio, 1.0, Sigmas * h.sd_of_mean) << c;
    EXPECT_GE(h.mean_ratio, TargetLow) << c;
    EXPECT_LE(h.mean_ratio, TargetHigh) << c;
    EXPECT_LE(h.max_ratio, MaxSensorRatio) << c;
  }
}

}  // namespace
}  // namespace dayphoton::study
