// simulation.accuracy (docs/project-format.md, "accuracy"): presets map to their targets,
// the target defaults to 1 %, and the keys that would also set photon counts are located errors.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dayphoton/project/project.h"
#include "located_errors.h"

namespace dayphoton::project {
namespace {

const std::string FakePath = std::string(DAYPHOTON_SOURCE_DIR) + "/projects/office/snippet.yaml";
const std::string Head =
    "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"
    "outputs: {annual_illuminance: false, metrics: false}\n"
    "materials: {}\n"
    "geometry: {}\n"
    "simulation:\n";

std::vector<std::string> errors_of(const std::string& text) {
  return test::located_errors([&] { load_project_from_string(text, FakePath); }, FakePath);
}

TEST(AccuracyKeys, PresetsAndDefaults) {
  const struct {
    const char* yaml;
    double target;
  } cases[] = {{"  accuracy: {preset: draft}\n", 5.0},
               {"  accuracy: {preset: standard}\n", 2.0},
               {"  accuracy: {preset: final}\n", 1.0},
               {"  accuracy: {}\n", 1.0},
               {"  accuracy: {target_df_relative_stderr_percent: 0.5, max_photons: 1000000, max_seconds: 60}\n", 0.5}};
  for (const auto& c : cases) {
    const Project p = load_project_from_string(Head + c.yaml, FakePath);
    ASSERT_TRUE(p.simulation.accuracy.has_value()) << c.yaml;
    EXPECT_DOUBLE_EQ(p.simulation.accuracy->target_df_relative_stderr_percent, c.target) << c.yaml;
  }
  const Project budgets = load_project_from_string(Head + cases[4].yaml, FakePath);
  EXPECT_EQ(budgets.simulation.accuracy->max_photons, 1000000);
  EXPECT_DOUBLE_EQ(budgets.simulation.accuracy->max_seconds, 60.0);
  for (const auto& c : cases) EXPECT_FALSE(load_project_from_string(Head + c.yaml, FakePath).simulation.accuracy->defaulted);
  // No photon count and no accuracy: the default target (the final preset); an explicit count
  // (sky or caustic) keeps the count control.
  const Project defaulted = load_project_from_string(Head + "  seed: 1\n", FakePath);
  ASSERT_TRUE(defaulted.simulation.accuracy.has_value());
  EXPECT_TRUE(defaulted.simulation.accuracy->defaulted);
  EXPECT_EQ(defaulted.simulation.accuracy->preset, "final");
  EXPECT_DOUBLE_EQ(defaulted.simulation.accuracy->target_df_relative_stderr_percent, 1.0);
  EXPECT_FALSE(load_project_from_string(Head + "  photons_per_bin: 1000\n", FakePath).simulation.accuracy.has_value());
  EXPECT_FALSE(
      load_project_from_string(Head + "  caustic_photons_per_bin: 1000\n", FakePath).simulation.accuracy.has_value());
}

TEST(AccuracyKeys, ConflictsAreLocatedErrors) {
  EXPECT_EQ(errors_of(Head + "  photons_per_bin: 1000\n  accuracy: {preset: draft}\n"),
            std::vector<std::string>{"6:20: 'photons_per_bin' and 'accuracy' exclude each other: the accuracy "
                                     "target chooses the photons of every sky bin (remove one of them)"});
  EXPECT_EQ(errors_of(Head + "  accuracy: {preset: draft, target_df_relative_stderr_percent: 3}\n"),
            std::vector<std::string>{"6:22: give either 'preset' or 'target_df_relative_stderr_percent' in "
                                     "'accuracy', not both"});
  EXPECT_EQ(errors_of(Head + "  accuracy: {preset: quick}\n").size(), 1u);
  EXPECT_EQ(errors_of(Head + "  accuracy: {target_df_relative_stderr_percent: 0}\n").size(), 1u);
  EXPECT_EQ(errors_of(Head + "  accuracy: {max_photons: 2000}\nlimits: {photons: 1000}\n").size(), 2u);
}

}  // namespace
}  // namespace dayphoton::project
