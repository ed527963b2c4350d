// A whole (tiny) daylight-factor run writes results.json, and the report and images are made
// from the results folder alone: the folder is copied elsewhere, the project file and the
// original folder are deleted, and `write_images_and_report` on the copy still writes every
// section, with the model read back equal to the one the run wrote and the windows the run
// recorded.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "dayphoton/project/project.h"
#include "dayphoton/report/report_html.h"
#include "dayphoton/study/cache_folder.h"
#include "dayphoton/study/progress.h"
#include "dayphoton/study/results_model.h"
#include "dayphoton/study/study_runner.h"
#include "../temp_folder.h"
#include "run_with_report.h"

using namespace dayphoton;
namespace fs = std::filesystem;

namespace {

const char* const Project =
    "site: {latitude: 51.5, longitude: -0.12, time_zone: 0}\n"
    "study: daylight_factor\n"
    "materials:\n"
    "  walls: {type: lambertian, reflectance: 0.5}\n"
    "  glazing: {type: glass, transmittance: 0.7}\n"
    "geometry:\n"
    "  rooms:\n"
    "    - name: room\n"
    "      size: [3, 4, 3]\n"
    "      materials: {floor: walls, ceiling: walls, walls: walls}\n"
    "      windows: [{name: win, wall: south, width: 2, height: 1.2, sill: 1.0, offset: 0.5, material: glazing}]\n"
    "sensors:\n"
    "  grids: [{name: floor, room: room, height: 0.8, spacing: 0.5}]\n"
    "simulation: {photons_per_bin: 100, seed: 5}\n";

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(ReportFromResults, NeedsNothingButTheResultsFolder) {
  const fs::path root = test::process_temp_dir() / "dayphoton_report_from_results";
  fs::remove_all(root);
  fs::create_directories(root / "project");
  std::ofstream(root / "project" / "project.yaml") << Project;
  const project::Project project = project::load_project((root / "project" / "project.yaml").string());
  const fs::path out = root / "run";
  test::run_with_report(project, out);
  ASSERT_TRUE(fs::exists(out / "results.json"));
  ASSERT_TRUE(fs::exists(out / "report.html"));
  // summary.json lists results.json among the outputs.
  EXPECT_NE(read_text(out / "summary.json").find("results.json"), std::string::npos);
  const study::ResultsModel model = study::read_results_model(out.string());
  ASSERT_EQ(model.cases.size(), 1u);
  ASSERT_EQ(model.cases[0].grids.size(), 1u);
  const study::GridResult& grid = model.cases[0].grids[0];
  EXPECT_EQ(grid.positions_m.size(), 35u);  // 5 x 7 at 0.5 m, the outer points 0.5 m from the walls
  EXPECT_TRUE(grid.lattice.regular);
  EXPECT_EQ(grid.lattice.columns, 5);
  EXPECT_EQ(grid.lattice.rows, 7);
  EXPECT_EQ(model.cases[0].openings.size(), 1u);
  EXPECT_EQ(grid.openings_drawn.size(), 1u);
  ASSERT_TRUE(grid.daylight_factor.has_value());
  EXPECT_GT(grid.daylight_factor->mean_percent, 0.0);
  EXPECT_FALSE(grid.annual.has_value());

  // Elsewhere, without the project and the original folder.
  const fs::path moved = root / "moved";
  fs::copy(out, moved, fs::copy_options::recursive);
  fs::remove_all(root / "project");
  fs::remove_all(out);
  fs::remove_all(study::default_cache_folder(out.string()));
  fs::remove(moved / "report.html");
  EXPECT_TRUE(study::read_results_model(moved.string()) == model);
  const std::vector<std::string> written = report::write_images_and_report(moved.string());
  EXPECT_EQ(written.size(), 2u + 1u);  // daylight_factor.exr/.png, report.html
  const std::string html = read_text(moved / "report.html");
  EXPECT_NE(html.find("id=\"grid-floor-df\""), std::string::npos);
  EXPECT_NE(html.find("class=\"window\""), std::string::npos);
  EXPECT_EQ(html.find("could not read"), std::string::npos);
  fs::remove_all(root);
}

TEST(ReportFromResults, PointInTimeCasesCarryTheirUncertainty) {
  // A CIE overcast case is the daylight factor times its sky's horizontal illuminance, and so
  // is its standard error (study/point_in_time_uncertainty.h): its relative uncertainty is the
  // DF's, stated in summary.json, in results.json and in the report's point-in-time part.
  const fs::path root = test::process_temp_dir() / "dayphoton_report_point_in_time";
  fs::remove_all(root);
  fs::create_directories(root / "project");
  std::ofstream(root / "project" / "project.yaml")
      << Project << "points_in_time: [{name: noon, date: 03-21, time: \"12:00\", sky: cie_overcast}]\n";
  const project::Project project = project::load_project((root / "project" / "project.yaml").string());
  const fs::path out = root / "run";
  test::run_with_report(project, out);
  const study::ResultsModel model = study::read_results_model(out.string());
  const study::GridResult& grid = model.cases.at(0).grids.at(0);
  ASSERT_EQ(grid.points_in_time.size(), 1u);
  const study::PointInTimeSummary& noon = grid.points_in_time[0];
  ASSERT_TRUE(noon.rms_relative_stderr_percent && noon.max_relative_stderr_percent);
  ASSERT_TRUE(grid.daylight_factor.has_value());
  EXPECT_GT(*noon.rms_relative_stderr_percent, 0.0);
  // The illuminance table is float: 1e-6 relative.
  EXPECT_NEAR(*noon.rms_relative_stderr_percent, grid.daylight_factor->rms_relative_stderr_percent,
              1e-5 * grid.daylight_factor->rms_relative_stderr_percent);
  EXPECT_NEAR(*noon.max_relative_stderr_percent, grid.daylight_factor->max_relative_stderr_percent,
              1e-5 * grid.daylight_factor->max_relative_stderr_percent);
  const std::string summary = read_text(out / "summary.json");
  EXPECT_NE(summary.find("\"rms_relative_stderr_percent\""), std::string::npos);
  EXPECT_NE(summary.find("\"sensors_with_light\""), std::string::npos);
  const std::string html = read_text(out / "report.html");
  const std::size_t part = html.find("id=\"grid-floor-pit\"");
  ASSERT_NE(part, std::string::npos);
  EXPECT_NE(html.find("standard error, RMS over sensors (relative)", part), std::string::npos);
  EXPECT_EQ(html.find("not stated", part), std::string::npos);
  fs::remove_all(root);
}
