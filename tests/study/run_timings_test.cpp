// timings.json (study/run_timings.h): the run's step times written from typed data and read
// back through the one typed reader, which names the key of a bad field; a folder without the
// file (an older run) has no timings rather than an error; cached steps carry no time; the
// progress records CPU time per step.
#include "dayphoton/study/run_timings.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "dayphoton/core/diagnostics.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

std::string temp_dir(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("dayphoton_run_timings_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(p);
  fs::create_directories(p);
  return p.string();
}

RunTimings example() {
  RunTimings t;
  t.steps = {{"sky matrix", "hours", 0, 0, 0, true},
             {"photons", "sources", 146, 12.345678901234, 23.5, false},
             {"tinted: coefficients workplane", "sensors", 165, 0.004, 0.0079, false}};
  t.total_wall_s = 20.25;
  t.total_cpu_s = 31.125;
  t.threads = 2;
  return t;
}

std::string error_of(const std::string& text) {
  try {
    parse_run_timings(text, "dir/timings.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(RunTimings, RoundTripsExactly) {
  const std::string dir = temp_dir("round_trip");
  const RunTimings t = example();
  EXPECT_EQ(write_run_timings(t, dir), (fs::path(dir) / "timings.json").string());
  const std::optional<RunTimings> back = read_run_timings(dir);
  ASSERT_TRUE(back);
  EXPECT_EQ(*back, t);  // doubles to their last bit (JSON numbers are written round-trip exact)
  fs::remove_all(dir);
}

TEST(RunTimings, AFolderWithoutTheFileHasNoTimings) {
  const std::string dir = temp_dir("absent");
  EXPECT_FALSE(read_run_timings(dir));
  fs::remove_all(dir);
}

TEST(RunTimings, BadFieldsNameTheirKey) {
  EXPECT_NE(error_of("[1]").find("timings.json is not a JSON object"), std::string::npos);
  EXPECT_NE(error_of(R"({"schema_version": 7, "threads": 1, "total_wall_s": 1, "total_cpu_s": 1, "steps": []})")
                .find("schema version 7"),
            std::string::npos);
  const std::string head = R"({"schema_version": 1, "threads": 2, "total_wall_s": 1, "total_cpu_s": 1, "steps": [)";
  const std::string good = R"({"name": "a", "cached": false, "wall_s": 1, "cpu_s": 1, "work": 3, "unit": "u"})";
  EXPECT_EQ(error_of(head + good + "]}"), "");
  EXPECT_NE(error_of(head + good + R"(, {"name": "b", "cached": false, "wall_s": -1, "cpu_s": 1, "work": 3, "unit": "u"}]})")
                .find("'steps[1].wall_s' is not a number of seconds >= 0"),
            std::string::npos);
  EXPECT_NE(error_of(head + R"({"name": "b", "cached": "yes", "wall_s": 1, "cpu_s": 1, "work": 3, "unit": "u"}]})")
                .find("'steps[0].cached' is not true or false"),
            std::string::npos);
  EXPECT_NE(error_of(head + R"({"name": "b", "cached": true, "wall_s": 1, "cpu_s": 1, "unit": "u"}]})")
                .find("'steps[0].work' is missing"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"schema_version": 1, "threads": 2, "total_cpu_s": 1, "steps": []})").find("'total_wall_s' is missing"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"schema_version": 1, "threads": 2, "total_wall_s": 1, "total_cpu_s": 1, "steps": {}})")
                .find("'steps' is not an array"),
            std::string::npos);
}

TEST(RunTimings, CachedStepsCarryNoTimeAndTheProgressRecordsCpuTime) {
  std::ostringstream quiet;
  Progress progress(quiet, ProgressStyle::Quiet);
  progress.cached("sky matrix");
  progress.start("busy", 10, "loops");
  // Busy for at least 20 ms of CPU time on this thread.
  const double cpu0 = Progress::process_cpu_seconds();
  volatile double sink = 0;
  while (Progress::process_cpu_seconds() - cpu0 < 0.02)
    for (int i = 0; i < 10000; ++i) sink = sink + std::sqrt(double(i));
  progress.advance(10);
  progress.end();
  const RunTimings t = run_timings_of(progress.steps(), 1.5, 0.5, 3);
  ASSERT_EQ(t.steps.size(), 2u);
  EXPECT_TRUE(t.steps[0].cached);
  EXPECT_EQ(t.steps[0].wall_s, 0);
  EXPECT_EQ(t.steps[0].cpu_s, 0);
  EXPECT_EQ(t.steps[0].name, "sky matrix");
  EXPECT_FALSE(t.steps[1].cached);
  EXPECT_EQ(t.steps[1].work, 10u);
  EXPECT_EQ(t.steps[1].unit, "loops");
  EXPECT_GE(t.steps[1].cpu_s, 0.02);
  EXPECT_GT(t.steps[1].wall_s, 0);
  EXPECT_EQ(t.threads, 3u);
  EXPECT_EQ(t.total_wall_s, 1.5);
}

}  // namespace
}  // namespace dayphoton::study
