// EN 17037 exposure to sunlight through `run_study` (docs/outputs.md): a daylight-factor study
// with `sunlight_exposure` writes each case's rooms to results.json (read back equal),
// summary.json, run.log and report.html's section, and no longer lists the sunlight exposure
// as not assessed; without the section nothing of it is written and the sentence stays.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "dayphoton/project/project.h"
#include "dayphoton/study/results_model.h"
#include "../report/run_with_report.h"
#include "../temp_folder.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

const std::string Project =
    "site: {latitude: 48.1, longitude: 11.6, time_zone: 1}\n"
    "study: daylight_factor\n"
    "materials:\n"
    "  walls: {type: lambertian, reflectance: 0.5}\n"
    "  glazing: {type: glass, transmittance: 0.7}\n"
    "geometry:\n"
    "  rooms:\n"
    "    - name: living\n"
    "      size: [4, 5, 3]\n"
    "      materials: {floor: walls, ceiling: walls, walls: walls}\n"
    "      windows: [{name: south, wall: south, width: 2, height: 1.8, sill: 0.9, material: glazing}]\n"
    "sensors:\n"
    "  grids: [{name: floor, room: living, spacing: 1, inset: 0.5}]\n"
    "simulation: {photons_per_bin: 300, seed: 7}\n"
    "outputs: {images: false, report: true}\n"
    "variants:\n"
    "  - name: screened\n"
    "    add: {polygons: [{name: screen, material: walls, vertices: [[-50, -3, 0], [50, -3, 0], [50, -3, 30], [-50, -3, 30]]}]}\n";
const std::string Sunlight = "sunlight_exposure: {date: 03-21, min_altitude: 10}\n";

std::string text_of(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class SunlightExposureRun : public ::testing::Test {
 protected:
  void SetUp() override {
    m_dir = test::process_temp_dir() /
            ("dayphoton_sunlight_run_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(m_dir);
    fs::create_directories(m_dir);
  }
  void TearDown() override { fs::remove_all(m_dir); }

  fs::path run(const std::string& yaml) {
    std::ofstream(m_dir / "project.yaml") << yaml;
    project::LoadOptions options;
    options.output_folder_overridden = true;
    test::run_with_report(project::load_project((m_dir / "project.yaml").string(), options), m_dir / "out");
    return m_dir / "out";
  }

  fs::path m_dir;
};

TEST_F(SunlightExposureRun, EveryOutputCarriesTheRoomsAndNotAssessedDropsTheSunlight) {
  const fs::path out = run(Project + Sunlight);
  const ResultsModel m = read_results_model(out.string());
  ASSERT_TRUE(m.sunlight_exposure);
  EXPECT_EQ(m.sunlight_exposure->month, 3);
  EXPECT_EQ(m.sunlight_exposure->min_altitude_deg, 10.0);
  ASSERT_EQ(m.cases.size(), 2u);
  ASSERT_EQ(m.cases[0].sunlight_exposure.size(), 1u);
  const RoomSunlight& open = m.cases[0].sunlight_exposure[0];
  EXPECT_EQ(open.room, "living");
  EXPECT_EQ(open.level, "high");  // about 9 h at 48 N with nothing in front
  EXPECT_GT(open.hours, 8.0);
  // The screen 3 m in front, 30 m high, hides the sun all day.
  ASSERT_EQ(m.cases[1].sunlight_exposure.size(), 1u);
  EXPECT_EQ(m.cases[1].sunlight_exposure[0].hours, 0.0);
  EXPECT_EQ(m.cases[1].sunlight_exposure[0].level, "below minimum");
  // results.json holds what the run computed, written from the typed model.
  EXPECT_EQ(parse_results_json(results_json(m), "results.json"), m);
  for (const std::string& s : m.not_assessed) EXPECT_EQ(s.find("exposure to sunlight"), std::string::npos) << s;
  // summary.json, run.log, report.html.
  const nlohmann::json summary = nlohmann::json::parse(text_of(out / "summary.json"));
  ASSERT_TRUE(summary.contains("sunlight_exposure"));
  EXPECT_EQ(summary["sunlight_exposure"]["rooms"][0]["level"], "high");
  EXPECT_EQ(summary["variants"][0]["sunlight_exposure"][0]["level"], "below minimum");
  const std::string log = text_of(out / "run.log");
  EXPECT_NE(log.find("EN 17037 sunlight exposure, room living: "), std::string::npos);
  EXPECT_NE(log.find("screened: EN 17037 sunlight exposure, room living: 0.00 h, below minimum (none)"), std::string::npos);
  const std::string report = text_of(out / "report.html");
  EXPECT_NE(report.find("<section id=\"sunlight\">"), std::string::npos);
}

TEST_F(SunlightExposureRun, WithoutTheSectionNothingIsWrittenAndItStaysNotAssessed) {
  const fs::path out = run(Project);
  const ResultsModel m = read_results_model(out.string());
  EXPECT_FALSE(m.sunlight_exposure);
  for (const CaseResult& c : m.cases) EXPECT_TRUE(c.sunlight_exposure.empty());
  bool listed = false;
  for (const std::string& s : m.not_assessed) listed = listed || s.find("exposure to sunlight") != std::string::npos;
  EXPECT_TRUE(listed);
  EXPECT_FALSE(nlohmann::json::parse(text_of(out / "summary.json")).contains("sunlight_exposure"));
  EXPECT_EQ(text_of(out / "report.html").find("<section id=\"sunlight\">"), std::string::npos);
}

}  // namespace
}  // namespace dayphoton::study
