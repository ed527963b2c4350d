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

#include "point_in_time_room.h"
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
  test::write_one_day_weather(dir / "one_day.epw");
  std::ofstream(yaml) << test::point_in_time_room(dir / "one_day.epw", "{photons_per_bin: 300, direct_samples_per_bin: 9}");
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
