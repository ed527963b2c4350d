// Per-grid CSV files (study/result_files.h): headers, rows, number formats, the sensors.csv
// round trip `dayphoton annual` relies on, and located errors on a bad sensors file.
#include "dayphoton/study/result_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "dayphoton/core/diagnostics.h"
#include "../temp_folder.h"

using namespace dayphoton;
using namespace dayphoton::study;
namespace fs = std::filesystem;

namespace {

std::string temp_path(const std::string& name) {
  return (test::process_temp_dir() / ("dayphoton_result_files_test_" + name)).string();
}

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

const std::vector<SensorPoint> Sensors = {{{0.5, 1.25, 0.8}, {0, 0, 1}}, {{-2.0, 3.123456789, 0.8}, {0, 0.6, 0.8}}};

}  // namespace

TEST(ResultFiles, SensorsCsvRoundTrips) {
  const std::string path = temp_path("sensors.csv");
  write_sensors_csv(Sensors, {}, path);
  const auto lines = lines_of(path);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "index,x,y,z,nx,ny,nz");
  EXPECT_EQ(lines[1], "0,0.5,1.25,0.8,0,0,1");
  EXPECT_EQ(lines[2], "1,-2,3.123457,0.8,0,0.6,0.8");
  const auto back = read_sensors_csv(path);
  fs::remove(path);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_DOUBLE_EQ(back[0].position.y, 1.25);
  EXPECT_DOUBLE_EQ(back[1].position.y, 3.123457);
  EXPECT_DOUBLE_EQ(back[1].normal.z, 0.8);
}

TEST(ResultFiles, BadSensorsCsvIsALocatedError) {
  const std::string path = temp_path("bad_sensors.csv");
  auto expect_error_at = [&](const std::string& text, const std::string& where) {
    std::ofstream(path) << text;
    try {
      read_sensors_csv(path);
      ADD_FAILURE() << "no error for " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path + where), std::string::npos) << e.what();
    }
  };
  expect_error_at("index,x,y,z\n0,1,2,3\n", ":1:1");
  expect_error_at("index,x,y,z,nx,ny,nz\n0,1,2,3,0,0,1\n1,1,two,3,0,0,1\n", ":3:3");
  expect_error_at("index,x,y,z,nx,ny,nz\n0,1,2,3,0,0\n", ":2");
  expect_error_at("index,x,y,z,nx,ny,nz\n1,1,2,3,0,0,1\n", ":2:1");
  fs::remove(path);
  EXPECT_THROW(read_sensors_csv(path), InputError);
}

TEST(ResultFiles, DaylightFactorCsv) {
  const std::string path = temp_path("df.csv");
  write_daylight_factor_csv(Sensors, {2.71828, 0.0}, path);
  const auto lines = lines_of(path);
  fs::remove(path);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "index,x,y,z,df_percent");
  EXPECT_EQ(lines[1], "0,0.5,1.25,0.8,2.7183");
  EXPECT_EQ(lines[2], "1,-2,3.123457,0.8,0.0000");
  EXPECT_THROW(write_daylight_factor_csv(Sensors, {1.0}, path), std::invalid_argument);
  // With the standard errors: a sixth column, df_stderr_percent (docs/outputs.md).
  write_daylight_factor_csv(Sensors, {2.71828, 0.0}, path, {0.012345, 0.0});
  const auto with_stderr = lines_of(path);
  fs::remove(path);
  ASSERT_EQ(with_stderr.size(), 3u);
  EXPECT_EQ(with_stderr[0], "index,x,y,z,df_percent,df_stderr_percent");
  EXPECT_EQ(with_stderr[1], "0,0.5,1.25,0.8,2.7183,0.0123");
  EXPECT_THROW(write_daylight_factor_csv(Sensors, {1.0, 2.0}, path, {1.0}), std::invalid_argument);
}

TEST(ResultFiles, MetricsCsvHeaderFollowsTheSettings) {
  metrics::SensorMetrics m;
  m.da_percent = 73.5123;
  m.cda_percent = 80;
  m.da_max_percent = 1.25;
  m.udi_below_percent = 9;
  m.udi_original_percent = 74;
  m.udi_above_original_percent = 17;
  m.udi_supplementary_percent = 10;
  m.udi_autonomous_percent = 70;
  m.udi_above_revised_percent = 11;
  m.mean_occupied_lux = 1984.04;
  const std::string path = temp_path("metrics.csv");
  write_metrics_csv(Sensors, {m, metrics::SensorMetrics{}}, metrics::MetricSettings{}, {}, path);
  auto lines = lines_of(path);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0],
            "index,x,y,z,da300_percent,cda300_percent,damax_percent,udi_below100_percent,udi100_2000_percent,"
            "udi_above2000_percent,udi_supplementary100_300_percent,udi_autonomous300_3000_percent,"
            "udi_above3000_percent,mean_occupied_lux");
  EXPECT_EQ(lines[1], "0,0.5,1.25,0.8,73.512,80.000,1.250,9.000,74.000,17.000,10.000,70.000,11.000,1984.0");

  metrics::MetricSettings other;
  other.da_threshold_lux = 250.5;
  other.udi_upper_revised_lux = 2500;
  write_metrics_csv(Sensors, {m, m}, other, {250, 251}, path);
  lines = lines_of(path);
  fs::remove(path);
  EXPECT_EQ(lines[0],
            "index,x,y,z,da250.5_percent,cda250.5_percent,damax_percent,udi_below100_percent,udi100_2000_percent,"
            "udi_above2000_percent,udi_supplementary100_250.5_percent,udi_autonomous250.5_2500_percent,"
            "udi_above2500_percent,mean_occupied_lux,ase_hours");
  EXPECT_EQ(lines[2].substr(lines[2].rfind(',')), ",251");
  EXPECT_EQ(metrics_csv_columns(other, true).size(), 15u);
  EXPECT_THROW(write_metrics_csv(Sensors, {m}, other, {}, path), std::invalid_argument);
  EXPECT_THROW(write_metrics_csv(Sensors, {m, m}, other, {1}, path), std::invalid_argument);
}
