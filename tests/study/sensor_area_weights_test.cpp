// Sensor areas through the study (AnnualStudySettings::sensor_area_m2, docs/metrics.md
// "Sensor areas"): a Honeybee grid whose mesh faces differ, its shares computed by hand.
// Three sensors on faces of 1, 1 and 0.2 m^2 (a column of 0.2 m cells along the window wall,
// as Honeybee's mesh_grid leaves over a floor that is no multiple of its cell): only the
// narrow cell's sensor is bright. Honeybee's share of it is 0.2 / 2.2 = 9.09 % of the area,
// where counting sensors gives 33.3 % (dayphoton before, with a warning).
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "../temp_folder.h"
#include "dayphoton/metrics/annual_metrics.h"
#include "dayphoton/metrics/occupancy.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/annual_study.h"
#include "dayphoton/study/daylight_factor.h"
#include "dayphoton/study/result_files.h"

namespace dayphoton::study {
namespace {

// A 4 x 5 x 3 m room (faces pointing out), a window in its south wall, and a grid of three
// sensors on a mesh of faces [0.4, 1.4], [1.4, 2.4] and [2.4, 2.6] (x) by [1, 2] (y).
const char* const Model = R"({"type": "Model", "identifier": "m", "rooms": [{"type": "Room", "identifier": "r", "faces": [
{"type": "Face", "identifier": "s", "face_type": "Wall", "boundary_condition": {"type": "Outdoors"},
 "geometry": {"type": "Face3D", "boundary": [[0, 0, 0], [4, 0, 0], [4, 0, 3], [0, 0, 3]]},
 "apertures": [{"type": "Aperture", "identifier": "w", "boundary_condition": {"type": "Outdoors"},
   "geometry": {"type": "Face3D", "boundary": [[1, 0, 1], [3, 0, 1], [3, 0, 2], [1, 0, 2]]}}]},
{"type": "Face", "identifier": "n", "face_type": "Wall", "boundary_condition": {"type": "Outdoors"},
 "geometry": {"type": "Face3D", "boundary": [[4, 5, 0], [0, 5, 0], [0, 5, 3], [4, 5, 3]]}},
{"type": "Face", "identifier": "wst", "face_type": "Wall", "boundary_condition": {"type": "Outdoors"},
 "geometry": {"type": "Face3D", "boundary": [[0, 5, 0], [0, 0, 0], [0, 0, 3], [0, 5, 3]]}},
{"type": "Face", "identifier": "e", "face_type": "Wall", "boundary_condition": {"type": "Outdoors"},
 "geometry": {"type": "Face3D", "boundary": [[4, 0, 0], [4, 5, 0], [4, 5, 3], [4, 0, 3]]}},
{"type": "Face", "identifier": "f", "face_type": "Floor", "boundary_condition": {"type": "Ground"},
 "geometry": {"type": "Face3D", "boundary": [[0, 0, 0], [0, 5, 0], [4, 5, 0], [4, 0, 0]]}},
{"type": "Face", "identifier": "c", "face_type": "RoofCeiling", "boundary_condition": {"type": "Outdoors"},
 "geometry": {"type": "Face3D", "boundary": [[0, 0, 3], [4, 0, 3], [4, 5, 3], [0, 5, 3]]}}]}],
"properties": {"radiance": {"sensor_grids": [{"identifier": "g",
 "sensors": [{"pos": [0.9, 1.5, 0.8], "dir": [0, 0, 1]}, {"pos": [1.9, 1.5, 0.8], "dir": [0, 0, 1]},
             {"pos": [2.5, 1.5, 0.8], "dir": [0, 0, 1]}],
 "mesh": {"type": "Mesh3D", "vertices": [[0.4, 1, 0.8], [1.4, 1, 0.8], [2.4, 1, 0.8], [2.6, 1, 0.8],
                                         [0.4, 2, 0.8], [1.4, 2, 0.8], [2.4, 2, 0.8], [2.6, 2, 0.8]],
          "faces": [[0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6]]}}]}}})";

std::string write(const std::string& name, const std::string& text) {
  const std::string path = (test::process_temp_dir() / name).string();
  std::ofstream(path) << text;
  return path;
}

/// The grid's sensor areas as the project loader gives them.
std::vector<double> honeybee_grid_areas_m2() {
  write("model.hbjson", Model);
  const std::string project = write("p.yaml", "version: 1\nstudy: daylight_factor\n"
                                              "site: {latitude: 37.7, longitude: -122.2, time_zone: -8}\n"
                                              "geometry: {honeybee: model.hbjson}\nsensors: {honeybee_grids: all}\n");
  const SceneDescription scene = project::build_scene_description(project::load_project(project));
  return scene.grids.at(0).area_m2;
}

TEST(SensorAreaWeights, AHoneybeeMeshOfUnequalFacesGivesHoneybeesShares) {
  AnnualStudySettings settings;  // DA300, sDA fraction 50 %, ASE 1000 lx over 250 h
  settings.sensor_area_m2 = honeybee_grid_areas_m2();
  ASSERT_EQ(settings.sensor_area_m2.size(), 3u);
  EXPECT_NEAR(settings.sensor_area_m2[2], 0.2, 1e-12);
  // Four steps, all occupied: sensors 0 and 1 at 100 lx, sensor 2 (the 0.2 m^2 face) at 800 lx.
  AnnualStudy study;
  study.illuminance = metrics::IlluminanceTable(std::vector<metrics::TimeStamp>(4), 3);
  for (std::size_t t = 0; t < 4; ++t) {
    study.illuminance.lux(t, 0) = study.illuminance.lux(t, 1) = 100.0f;
    study.illuminance.lux(t, 2) = 800.0f;
  }
  study.sensors =
      metrics::compute_sensor_metrics(study.illuminance, metrics::OccupancySchedule(std::vector<bool>(4, true)));
  study.ase_hours = {0, 0, 300};  // only the narrow cell sees the sun for more than 250 h
  summarize_annual_study(study, settings, true, {1, 2, 3, 4}, "test");
  const double share = 100.0 * 0.2 / 2.2;  // 9.0909 %, where the sensor count gives 33.3 %
  EXPECT_NEAR(study.grid.sda_percent, share, 1e-12);
  EXPECT_NEAR(study.grid.ase_percent, share, 1e-12);
  EXPECT_NEAR(study.grid.mean.da_percent, share, 1e-12);
  EXPECT_NEAR(study.grid.mean.mean_occupied_lux, (100 + 100 + 0.2 * 800) / 2.2, 1e-9);
  // EN 17037 over the two brightest steps: the minimum target (300 lx) only at sensor 2, its
  // minimum target (100 lx) everywhere.
  ASSERT_EQ(study.grid.en17037.size(), 3u);
  EXPECT_NEAR(study.grid.en17037[0].target_area_percent, share, 1e-12);
  EXPECT_NEAR(study.grid.en17037[0].minimum_target_area_percent, 100.0, 1e-12);
  EXPECT_NEAR(study.grid.en17037[1].minimum_target_area_percent, share, 1e-12);

  // Equal weights (no areas) give the count's shares, as before.
  AnnualStudySettings equal;
  summarize_annual_study(study, equal, true, {1, 2, 3, 4}, "test");
  EXPECT_NEAR(study.grid.sda_percent, 100.0 / 3, 1e-12);
  // Areas for another count of sensors: refused.
  equal.sensor_area_m2 = {1.0, 1.0};
  EXPECT_THROW(summarize_annual_study(study, equal, true, {}, ""), std::invalid_argument);
}

// The daylight factor's (and the point-in-time cases') mean, median and area shares over the
// same grid: DF 1, 2 and 4 % on 1, 1 and 0.2 m^2. Mean (1 + 2 + 0.8) / 2.2 = 1.727 %; the
// median is the value where the area sorted by DF reaches 1.1 m^2: 2 %; DF >= 3 % on 9.09 %
// of the area. With every area equal, the unweighted values.
TEST(SensorAreaWeights, DaylightFactorStatisticsAreOfTheArea) {
  const GridStatistics g = grid_statistics({1, 2, 4}, {3}, {1.0, 1.0, 0.2});
  EXPECT_NEAR(g.mean, 3.8 / 2.2, 1e-12);
  EXPECT_EQ(g.median, 2.0);
  EXPECT_EQ(g.min, 1.0);
  EXPECT_EQ(g.max, 4.0);
  EXPECT_NEAR(g.uniformity, 2.2 / 3.8, 1e-12);
  ASSERT_EQ(g.area_at_or_above_percent.size(), 1u);
  EXPECT_NEAR(g.area_at_or_above_percent[0].second, 100.0 * 0.2 / 2.2, 1e-12);
  // Half the area exactly below 2 %: the mean of the two values, as an even count's median.
  EXPECT_EQ(grid_statistics({1, 2, 4}, {}, {1.0, 0.5, 0.5}).median, 1.5);
  const GridStatistics equal = grid_statistics({4, 1, 3, 2}, {2.5}, {0.3, 0.3, 0.3, 0.3});
  const GridStatistics counted = grid_statistics({4, 1, 3, 2}, {2.5});
  EXPECT_DOUBLE_EQ(equal.mean, counted.mean);
  EXPECT_EQ(equal.median, counted.median);
  EXPECT_DOUBLE_EQ(equal.area_at_or_above_percent[0].second, counted.area_at_or_above_percent[0].second);
  EXPECT_THROW(grid_statistics({1, 2}, {}, {1.0}), std::invalid_argument);
}

// sensors.csv carries the areas (`area_m2`, the shortest text of each double) and gives them
// back bit for bit, so `dayphoton annual` weighs as the run did; without areas, no column.
TEST(SensorAreaWeights, SensorsCsvCarriesTheAreasBitForBit) {
  const std::vector<SensorPoint> sensors = {{{0.9, 1.5, 0.8}, {0, 0, 1}}, {{2.5, 1.5, 0.8}, {0, 0, 1}}};
  const std::vector<double> area_m2 = {1.0 / 3.0, 0.1 * 0.35};
  const std::string path = (test::process_temp_dir() / "sensors.csv").string();
  write_sensors_csv(sensors, area_m2, path);
  std::ifstream in(path);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "index,x,y,z,nx,ny,nz,area_m2");
  std::vector<double> back;
  EXPECT_EQ(read_sensors_csv(path, &back).size(), 2u);
  EXPECT_EQ(back, area_m2);
  write_sensors_csv(sensors, {}, path);
  EXPECT_EQ(read_sensors_csv(path, &back).size(), 2u);
  EXPECT_TRUE(back.empty());
}

}  // namespace
}  // namespace dayphoton::study
