// A variant that removes geometry, end to end through `run_study` (docs/project-format.md
// `variants`, docs/cache.md):
// - the variant "remove the light shelf" writes, byte for byte, the results of the same
//   project written without the shelf (same seed, same scene);
// - its cache keys are those of that project's scene (study/cache_keys.h hashes the scene
//   the variant builds), not the base's: run in the folder of the project without the
//   shelf, the variant reads every photon artefact from the cache, while the base with the
//   shelf traces its own; a removal never reuses the artefacts of the scene it removed from.
// Daylight factors only (no weather file) and few photons, so each run takes seconds.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "dayphoton/project/project.h"
#include "dayphoton/study/cache_keys.h"
#include "dayphoton/study/progress.h"
#include "dayphoton/study/study_runner.h"
#include "../temp_folder.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

const std::string Head =
    "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"
    "materials:\n"
    "  walls: {type: lambertian, reflectance: 0.5}\n"
    "  shelf: {type: metal, reflectance: 0.9, specularity: 0.95}\n"
    "  glazing: {type: glass, transmittance: 0.7}\n"
    "geometry:\n"
    "  rooms:\n"
    "    - name: room\n"
    "      size: [4, 5, 3]\n"
    "      materials: {floor: walls, ceiling: walls, walls: walls}\n"
    "      windows: [{name: win, wall: south, width: 3, height: 1.8, sill: 0.9, material: glazing}]\n";
const std::string Shelf =
    "  systems:\n"
    "    - {type: light_shelf, name: shelf, window: win, side: interior, height: 2.2, depth: 0.6, material: shelf}\n";
const std::string Tail =
    "sensors:\n"
    "  grids: [{name: floor, room: room, spacing: 1, inset: 0.5}]\n"
    "simulation: {photons_per_bin: 300, seed: 7}\n"
    "outputs: {annual_illuminance: false, metrics: false, images: false, report: false}\n";

/// The project with the shelf and a variant without it; the project written without it.
const std::string WithShelf = Head + Shelf + Tail + "variants:\n  - {name: no_shelf, remove: {systems: [shelf]}}\n";
const std::string WithoutShelf = Head + Tail;

class VariantScene : public ::testing::Test {
 protected:
  void SetUp() override {
    m_dir = test::process_temp_dir() /
            ("dayphoton_variant_scene_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(m_dir);
    fs::create_directories(m_dir);
    write("with_shelf.yaml", WithShelf);
    write("without_shelf.yaml", WithoutShelf);
  }
  void TearDown() override { fs::remove_all(m_dir); }

  void write(const std::string& name, const std::string& text) { std::ofstream(m_dir / name) << text; }

  project::Project load(const std::string& name) {
    project::LoadOptions options;
    options.output_folder_overridden = true;
    return project::load_project((m_dir / name).string(), options);
  }

  RunReport run(const std::string& name, const std::string& output) {
    RunSettings settings;
    settings.output_dir = (m_dir / output).string();
    std::ostringstream quiet;
    Progress progress(quiet, ProgressStyle::Quiet);
    return run_study(load(name), settings, progress);
  }

  fs::path m_dir;
};

/// Every file under `folder` (relative path -> bytes).
std::map<std::string, std::string> files_of(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(folder))
    if (e.is_regular_file()) {
      std::ifstream in(e.path(), std::ios::binary);
      std::ostringstream bytes;
      bytes << in.rdbuf();
      files[fs::relative(e.path(), folder).string()] = bytes.str();
    }
  return files;
}

TEST_F(VariantScene, RemovingTheShelfGivesTheResultsOfTheProjectWithoutIt) {
  run("with_shelf.yaml", "a");
  run("without_shelf.yaml", "b");
  const auto variant = files_of(m_dir / "a" / "variants" / "no_shelf" / "floor");
  const auto written = files_of(m_dir / "b" / "floor");
  const auto base = files_of(m_dir / "a" / "floor");
  ASSERT_FALSE(written.empty());
  ASSERT_TRUE(written.count("daylight_factor.csv"));
  EXPECT_EQ(variant, written);
  // summary.json and the run log say what the variant changed.
  const auto summary = files_of(m_dir / "a").at("summary.json");
  EXPECT_NE(summary.find("\"changes\": [\n        \"system shelf removed\"\n      ]"), std::string::npos) << summary;
  EXPECT_NE(files_of(m_dir / "a").at("run.log").find("variant no_shelf: system shelf removed\n"), std::string::npos);
  // The shelf changes the daylight factors (else the comparison above would prove nothing).
  ASSERT_TRUE(base.count("daylight_factor.csv"));
  EXPECT_NE(base.at("daylight_factor.csv"), written.at("daylight_factor.csv"));
}

TEST_F(VariantScene, TheCacheKeysFollowTheSceneTheVariantBuilds) {
  const project::Project with = load("with_shelf.yaml");
  const project::Project without = load("without_shelf.yaml");
  const SceneDescription variant_scene = project::build_scene_description(project::apply_variant(with, with.variants.at(0)));
  const SceneDescription base_scene = project::build_scene_description(with);
  const SceneDescription written_scene = project::build_scene_description(without);
  EXPECT_EQ(scene_key(variant_scene).hex(), scene_key(written_scene).hex());
  EXPECT_NE(scene_key(variant_scene).hex(), scene_key(base_scene).hex());

  // The project without the shelf first; then, in the same folder, the project with the shelf
  // and its variant: the variant finds every photon pass cached, the base traces all of its own.
  const RunReport first = run("without_shelf.yaml", "shared");
  ASSERT_GT(first.sources, 0u);
  EXPECT_EQ(first.sources_traced, first.sources);
  const RunReport second = run("with_shelf.yaml", "shared");
  EXPECT_EQ(second.sources, 2 * first.sources);
  EXPECT_EQ(second.sources_traced, first.sources);  // the base with the shelf
  EXPECT_EQ(second.sources_cached, first.sources);  // the variant without it
}

}  // namespace
}  // namespace dayphoton::study
