// The results model (study/results_model.h): results.json round-trips every field (write ->
// read -> equal), a missing or mistyped field is an error naming its key, another schema
// version and a folder without results.json are errors that say to run again, and the
// builder draws on a wall grid's elevation only the windows of that wall.
#include "dayphoton/study/results_model.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/results_model_builder.h"
#include "../temp_folder.h"

using namespace dayphoton;
using namespace dayphoton::study;
namespace fs = std::filesystem;

namespace {

/// A model with every field set to a value other than its default.
ResultsModel full_model() {
  ResultsModel m;
  m.project_name = "project.yaml";
  m.project_file = "projects/office/project.yaml";
  m.dayphoton_version = "0.1.0";
  m.compiler = "13.2";
  m.study = "annual";
  m.site_name = "Oakland \"caf\xc3\xa9\"";
  m.latitude_deg = 37.72;
  m.longitude_deg = -122.22;
  m.time_zone_h = -8;
  m.elevation_m = 2.5;
  m.sun_from_weather = true;
  m.sun_site = std::array<double, 4>{37.7, -122.2, -8, 1.25};
  m.sun_sentence = "the sun is computed for ...";
  m.station_distance_km = 0.125;
  m.below_horizon_hours = 7;
  m.below_horizon_their_sun = "left out";
  m.weather_file = "w.epw";
  m.basis = "reinhart";
  m.reinhart_mf = 2;
  m.ground_reflectance = 0.15;
  m.settings = {{"photons per bin", "20000"}, {"sun", "bins"}};
  m.notes = {"one", "two"};
  m.title = "Riverside \"school\"";
  m.not_assessed = {"glare", "view out"};
  CaseResult c;
  c.kind = "variant";
  c.name = "tinted";
  c.folder = "variants/tinted";
  c.changes = {"glazing tinted"};
  c.openings = {{{0, 0, 1}, {1, 0, 1}, {1, 0, 2}}};
  c.systems = {{{0, -1, 2}, {1, -1, 2}, {1, -0.5, 2}}};
  c.materials = {{"walls", "plastic", 0.5, std::nullopt, 0.05, 88.5}, {"glazing", "glass", std::nullopt, 0.6, 0, 6}};
  c.rooms = {{"office", 6, 8, 3, 48, 6, 18, 1.5,
              {{"south", "south", 4, 1.5, 0.9, 6, "glazing", 0.8, 0.9}, {"top", "roof", 1, 1.5, 0.25, 1.5, "glazing", 1, 1}}}};
  c.opening_area_m2 = 7.5;
  c.blinds_in_place = {"venetian"};
  GridResult g;
  g.name = "workplane";
  g.folder = "variants/tinted/workplane";
  g.positions_m = {{0.25, 0.25, 0.8}, {0.75, 0.25, 0.8}, {0.25, 0.75, 0.8}};
  g.area_m2 = {0.25, 0.25, 0.1};  // a grid whose sensors stand for unequal areas
  g.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  g.orientation = GridOrientation::Tilted;
  g.plan = false;
  g.lattice.regular = true;
  g.lattice.columns = 2;
  g.lattice.rows = 2;
  g.lattice.spacing_m = 0.5;
  g.lattice.origin_m = {0.25, 0.75, 0.8};
  g.lattice.column_step_m = {0.5, 0, 0};
  g.lattice.row_step_m = {0, -0.5, 0};
  g.lattice.column_of = {0, 1, 0};
  g.lattice.row_of = {1, 1, 0};
  g.outline = {{0, 0, 0.8}, {1, 0, 0.8}, {1, 1, 0.8}};
  g.openings_drawn = {0};
  g.dropped_outside_rooms = 3;
  g.dropped_inside_solid = 1;
  g.quantities = {{"da300", "metrics.csv", "da300_percent", "da", "daylight autonomy (300 lx)", "%",
                   QuantityScale::Percent, "daylight autonomy"},
                  {"daylight_factor", "daylight_factor.csv", "df_percent", "daylight_factor", "daylight factor", "%",
                   QuantityScale::DaylightFactor, "daylight factor"}};
  g.daylight_factor = DaylightFactorSummary{1.5, 1.25, 0.1, 3.3, 0.0667, {{2.0, 33.3}, {1.0, 66.7}}, 4.5, 9.25, 3, std::nullopt};
  g.daylight_factor->accuracy =
      DaylightFactorSummary::AccuracyReached{2.0, 2.4, 3, 4100000, "photon budget", "above target", 4096, 2,
                                             "gather ray limit", 64};
  g.sun_accuracy = SunAccuracyReached{2.0, 1.75, 9.5, 2, 3200000, "target met", "met", 1024, 1, "target met"};
  g.dropped_on_cut_surface = 8;
  g.dropped_enclosed = 2;
  g.daylight_factor->accuracy->near_cut_sensors = 12;
  g.daylight_factor->accuracy->near_cut_gather_rays = 1024;
  g.daylight_factor->accuracy->near_cut_largest_percent = 1.25;
  g.daylight_factor->accuracy->near_cut_gather_rounds = 2;
  g.daylight_factor->accuracy->near_cut_stop_reason = "gather ray limit";
  g.sun_accuracy->near_cut_sensors = 9;
  g.sun_accuracy->near_cut_gather_rays = 1024;
  g.sun_accuracy->near_cut_largest_percent = 1.5;
  AnnualSummary a;
  a.sensors = 3;
  a.time_steps = 8760;
  a.occupied_hours = 3650;
  a.da_threshold_lux = 250.5;
  a.udi_lower_lux = 99;
  a.udi_upper_original_lux = 2001;
  a.udi_upper_revised_lux = 3001;
  a.sda_time_fraction = 0.4;
  a.ase_threshold_lux = 999;
  a.ase_hours = 249;
  a.occupancy.kind = "weekly";
  a.occupancy.start_h = a.occupancy.end_h = 0;
  a.occupancy.description = "weekdays 8-18";
  a.occupancy.week[0] = {{8, 12}, {13, 17.5}};
  a.occupancy.week[4] = {{9, 12}};
  a.occupancy.holiday_hours = {{10, 11}};
  a.occupancy.holidays = {{12, 24, 1, 2}, {8, 1, 8, 15}};
  a.occupancy.january_1 = "Sunday";
  a.occupancy.daylight_saving = "eu";
  a.occupancy.hourly = "0110";
  a.occupancy.hourly_source = "schedule.csv";
  a.da_percent = 1.1;
  a.cda_percent = 2.2;
  a.da_max_percent = 3.3;
  a.udi_below_percent = 4.4;
  a.udi_achieved_percent = 5.5;
  a.udi_above_original_percent = 6.6;
  a.udi_supplementary_percent = 7.7;
  a.udi_autonomous_percent = 8.8;
  a.udi_above_revised_percent = 9.9;
  a.mean_occupied_lux = 432.1;
  a.sda_percent = 66.7;
  a.sda_sensors = 2;
  a.ase_percent = 12.5;
  a.en17037_daylight_hours = 4380;
  a.en17037_daylight_hours_source = "diffuse";
  a.en17037_openings = "horizontal";
  a.en17037_target_area_required_percent = 95;
  a.en17037 = {{"minimum", 300, 100, 80, 100, true}, {"medium", 500, 300, 40, 80, false}};
  a.sky = "Perez";
  a.da_verdicts_within_2_sigma = 1;
  a.da_verdicts_within_2_sigma_area_percent = 16.7;
  g.annual = a;
  g.points_in_time = {{"noon", "cie_overcast", 500, 450, 100, 900, 0.2, 1.25, 3.5, std::nullopt},
                      {"older_run", "weather", 800, 700, 90, 2000, 0.1, std::nullopt, std::nullopt, std::nullopt}};
  g.has_illuminance_table = true;
  g.spacing_m = 0.5;
  g.verdicts = {{"IES LM-83-12", "sDA300/50%", ">= 55 %", 66.7, "%", "pass", ""},
                {"EN 17037 daylight provision", "level", "minimum, medium or high", std::nullopt, "", "not assessed",
                 "the grid is tilted"}};
  c.grids = {g};
  CaseResult base;
  base.kind = "base";
  m.cases = {base, c};
  return m;
}


std::string error_of(const std::string& text) {
  try {
    parse_results_json(text, "r/results.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ResultsModel, RoundTripsEveryField) {
  const ResultsModel m = full_model();
  const std::string dir = test::empty_dir("results_model_round_trip");
  const std::string path = write_results_model(m, dir);
  EXPECT_EQ(path, (fs::path(dir) / "results.json").string());
  const ResultsModel back = read_results_model(dir);
  EXPECT_TRUE(back == m);
  EXPECT_EQ(results_json(back), results_json(m));  // and the text is stable
  // Each field matters to the comparison: a changed value is seen.
  ResultsModel changed = back;
  changed.cases[1].grids[0].annual->ase_percent.reset();
  EXPECT_FALSE(changed == m);
  changed = back;
  changed.cases[1].grids[0].lattice.row_of[2] = 1;
  EXPECT_FALSE(changed == m);
  changed = back;
  changed.cases[1].materials[1].transmittance = 0.61;
  EXPECT_FALSE(changed == m);
  changed = back;
  changed.cases[1].rooms[0].windows[0].frame_factor = 0.7;
  EXPECT_FALSE(changed == m);
  changed = back;
  changed.cases[1].grids[0].verdicts[0].outcome = "fail";
  EXPECT_FALSE(changed == m);
  changed = back;
  changed.cases[1].grids[0].daylight_factor->accuracy->status = "met";
  EXPECT_FALSE(changed == m);
  changed = back;
  changed.cases[1].grids[0].daylight_factor->accuracy->gather_stop_reason = "round limit";
  EXPECT_FALSE(changed == m);
  changed = back;
  changed.cases[1].grids[0].daylight_factor->accuracy->gather_rays = 1024;
  EXPECT_FALSE(changed == m);
  changed = back;
  changed.cases[1].grids[0].daylight_factor->accuracy->direct_samples_per_bin = 256;
  EXPECT_FALSE(changed == m);
  changed = back;
  changed.cases[1].grids[0].sun_accuracy->hourly_percent = 9.4;
  EXPECT_FALSE(changed == m);
  changed = back;
  changed.cases[1].grids[0].sun_accuracy->gather_rays = 4096;
  EXPECT_FALSE(changed == m);
  changed = back;
  changed.cases[1].grids[0].sun_accuracy->gather_stop_reason = "gather ray limit";
  EXPECT_FALSE(changed == m);
  changed = back;
  changed.cases[1].grids[0].sun_accuracy->status = "above target";
  EXPECT_FALSE(changed == m);
  changed = back;
  changed.cases[1].grids[0].daylight_factor->accuracy->near_cut_largest_percent = 1.5;
  EXPECT_FALSE(changed == m);
  changed = back;
  changed.cases[1].grids[0].sun_accuracy->near_cut_sensors = 8;
  EXPECT_FALSE(changed == m);
  changed = back;
  changed.cases[1].grids[0].daylight_factor->accuracy->near_cut_stop_reason = "target met";
  EXPECT_FALSE(changed == m);
  changed = back;
  changed.cases[1].grids[0].dropped_on_cut_surface = 0;
  EXPECT_FALSE(changed == m);
  changed = back;
  changed.cases[1].grids[0].dropped_enclosed = 0;
  EXPECT_FALSE(changed == m);
  changed = back;
  changed.cases[1].blinds_in_place.clear();  // and then not written at all
  EXPECT_FALSE(changed == m);
  EXPECT_EQ(results_json(changed).find("blinds_in_place"), std::string::npos);
  EXPECT_TRUE(parse_results_json(results_json(changed), "r/results.json") == changed);
  changed = back;
  changed.not_assessed.pop_back();
  EXPECT_FALSE(changed == m);
  EXPECT_NEAR(back.cases[1].rooms[0].window_to_wall_ratio(), 6.0 / 18, 1e-12);
  EXPECT_NEAR(back.cases[1].rooms[0].window_to_floor_ratio(), 7.5 / 48, 1e-12);
  // The empty optional fields round-trip too.
  ResultsModel bare;
  CaseResult bare_case;
  bare_case.kind = "base";
  bare.cases.push_back(bare_case);
  EXPECT_TRUE(parse_results_json(results_json(bare), "x") == bare);
}

TEST(ResultsModel, BadFieldsAreErrorsNamingTheKey) {
  const std::string text = results_json(full_model());
  EXPECT_NE(error_of(std::regex_replace(text, std::regex("\"sda_percent\": 66.7"), "\"sda_percent\": \"66.7\""))
                .find("'cases[tinted].grids[workplane].annual.sda_percent' is not a number"),
            std::string::npos);
  EXPECT_NE(error_of(std::regex_replace(text, std::regex(",\\s*\"weather_file\": \"w.epw\""), ""))
                .find("'weather_file' is missing"),
            std::string::npos);
  const std::string version = error_of(std::regex_replace(text, std::regex("\"schema_version\": 4"), "\"schema_version\": 3"));
  EXPECT_NE(version.find("schema version 3"), std::string::npos) << version;
  const std::string version5 = error_of(std::regex_replace(text, std::regex("\"schema_version\": 4"), "\"schema_version\": 5"));
  EXPECT_NE(version5.find("schema version 5"), std::string::npos) << version5;
  // The accuracy statuses are known words, and every field of the sun's accuracy is required.
  EXPECT_NE(error_of(std::regex_replace(text, std::regex("\"status\": \"above target\""), "\"status\": \"above\""))
                .find("daylight_factor.accuracy.status' is not met, above target or not reachable by photons"),
            std::string::npos);
  // The sky's shadow-ray count is required (schema 4) and at least 1.
  EXPECT_NE(error_of(std::regex_replace(text, std::regex("\"direct_samples_per_bin\": 64,\\s*"), ""))
                .find("'cases[tinted].grids[workplane].daylight_factor.accuracy.direct_samples_per_bin' is missing"),
            std::string::npos);
  EXPECT_NE(error_of(std::regex_replace(text, std::regex("\"direct_samples_per_bin\": 64"), "\"direct_samples_per_bin\": 0"))
                .find("daylight_factor.accuracy.direct_samples_per_bin' is not at least 1"),
            std::string::npos);
  EXPECT_NE(error_of(std::regex_replace(text, std::regex("\"hourly_percent\": 9.5,\\s*"), ""))
                .find("'cases[tinted].grids[workplane].sun_accuracy.hourly_percent' is missing"),
            std::string::npos);
  EXPECT_NE(version.find("run the study again"), std::string::npos) << version;
  EXPECT_NE(error_of("[1, 2").find("not a JSON object"), std::string::npos);
  // The occupancy's definition is checked as it is read.
  EXPECT_NE(error_of(std::regex_replace(text, std::regex("\"daylight_saving\": \"eu\""), "\"daylight_saving\": \"uk\""))
                .find("annual.occupancy.daylight_saving' is not none, eu or us"),
            std::string::npos);
  EXPECT_NE(error_of(std::regex_replace(text, std::regex("\"hourly\": \"0110\""), "\"hourly\": \"01x0\""))
                .find("annual.occupancy.hourly' holds a character other than 0 and 1"),
            std::string::npos);
  EXPECT_NE(error_of(std::regex_replace(text, std::regex("\"january_1\": \"Sunday\""), "\"january_1\": \"Sun day\""))
                .find("annual.occupancy.january_1' is not a weekday"),
            std::string::npos);
  // A value file named with a folder part would lead out of the grid's folder.
  EXPECT_NE(error_of(std::regex_replace(text, std::regex("\"file\": \"metrics.csv\""), "\"file\": \"../metrics.csv\""))
                .find("not a plain file name"),
            std::string::npos);
  // Verdicts: a known outcome, a value exactly when assessed; materials: fractions in [0, 1].
  EXPECT_NE(error_of(std::regex_replace(text, std::regex("\"outcome\": \"pass\""), "\"outcome\": \"ok\""))
                .find("is not pass, fail or not assessed"),
            std::string::npos);
  EXPECT_NE(error_of(std::regex_replace(text, std::regex("\"value\": 66.7"), "\"value\": null"))
                .find("is missing for an assessed criterion"),
            std::string::npos);
  EXPECT_NE(error_of(std::regex_replace(text, std::regex("\"transmittance\": 0.6"), "\"transmittance\": 1.6"))
                .find("outside [0, 1]"),
            std::string::npos);
  EXPECT_NE(error_of(std::regex_replace(text, std::regex(",\\s*\"title\": [^\\n]*"), "")).find("'project.title' is missing"),
            std::string::npos);
  // A sensor's cell outside the lattice.
  EXPECT_NE(error_of(std::regex_replace(text, std::regex("\"row\": 1"), "\"row\": 5")).find("outside the lattice"),
            std::string::npos);
}

TEST(ResultsModel, AFolderWithoutResultsJsonSaysToRunAgain) {
  const std::string dir = test::empty_dir("results_model_old_run");
  std::ofstream(dir + "/summary.json") << "{}";
  try {
    read_results_model(dir);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("written by an older dayphoton; run the study again"), std::string::npos)
        << e.what();
  }
}

// A wall grid's picture is an elevation in the wall's plane: the south window of the office
// must not be drawn on the back (north) wall's picture, while the work plane's plan shows it.
TEST(ResultsModelBuilder, ElevationsGetOnlyTheWindowsOfTheirWall) {
  const project::Project project =
      project::load_project(std::string(DAYPHOTON_SOURCE_DIR) + "/projects/wall_sensors/project.yaml");
  const SceneDescription scene = project::build_scene_description(project);
  CaseResult c = results_case("base", "", "", {});
  set_plan_geometry(c, scene);
  ASSERT_FALSE(c.openings.empty());
  bool wall = false, plane = false;
  for (const SensorGrid& g : scene.grids) {
    const GridResult r = results_grid(g, g.name, c, 0, 0);
    if (g.name == "back_wall") {
      wall = true;
      EXPECT_EQ(r.orientation, GridOrientation::Vertical);
      EXPECT_FALSE(r.plan);
      EXPECT_TRUE(r.openings_drawn.empty());
      EXPECT_TRUE(r.lattice.regular);
    } else if (g.name == "workplane") {
      plane = true;
      EXPECT_EQ(r.orientation, GridOrientation::Horizontal);
      EXPECT_TRUE(r.plan);
      EXPECT_EQ(r.openings_drawn.size(), c.openings.size());
    }
  }
  EXPECT_TRUE(wall && plane);
}

// The one typed reader of value tables: the column the model names, for the grid's sensors.
TEST(ResultsModel, ValuesAreReadFromTheColumnTheModelNames) {
  const std::string dir = test::empty_dir("results_model_values");
  fs::create_directories(dir + "/grid");
  std::ofstream(dir + "/grid/metrics.csv") << "index,x,y,z,da300_percent,other\n0,0,0,0.8,10.5,1\n1,1,0,0.8,20.25,2\n";
  GridResult g;
  g.name = "grid";
  g.folder = "grid";
  g.positions_m = {{0, 0, 0.8}, {1, 0, 0.8}};
  SensorQuantity q{"da300", "metrics.csv", "da300_percent", "da", "daylight autonomy (300 lx)", "%",
                   QuantityScale::Percent, "daylight autonomy"};
  EXPECT_EQ(read_quantity_values(dir, g, q), (std::vector<double>{10.5, 20.25}));
  q.column = "da250_percent";  // a column the table does not have
  try {
    read_quantity_values(dir, g, q);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no column 'da250_percent'"), std::string::npos) << e.what();
  }
  q.column = "da300_percent";
  g.positions_m.push_back({2, 0, 0.8});  // the model has 3 sensors, the table 2 rows
  try {
    read_quantity_values(dir, g, q);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("2 rows for the 3 sensors"), std::string::npos) << e.what();
  }
}
