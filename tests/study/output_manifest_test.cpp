// Tests for study/output_manifest.h: begin() marks the folder incomplete and removes summary.json
// and the previous run's outputs (from summary.json's `files`, or from an interrupted run's
// marker), never a path outside the folder or a folder; record() appends to the marker at once;
// entries() gives sizes and SHA-256 in path order; finish() removes the marker.
#include "dayphoton/study/output_manifest.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "dayphoton/core/sha256.h"
#include "../temp_folder.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

/// `name` below this process's own folder, empty but for an empty folder "out" (the output folder).
fs::path root_with_output_folder(const std::string& name) {
  const fs::path dir = test::fresh_dir(name);
  fs::create_directories(dir / "out");
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

TEST(OutputManifest, StaysInsideRejectsEscapes) {
  EXPECT_TRUE(stays_inside("summary.json"));
  EXPECT_TRUE(stays_inside("variants/v/grid/metrics.csv"));
  EXPECT_FALSE(stays_inside(""));
  EXPECT_FALSE(stays_inside("/etc/passwd"));
  EXPECT_FALSE(stays_inside("../outside.txt"));
  EXPECT_FALSE(stays_inside("grid/../../outside.txt"));
  EXPECT_FALSE(stays_inside("./a"));
  EXPECT_FALSE(stays_inside("a/"));
}

TEST(OutputManifest, BeginRemovesThePreviousRunsOutputsOnly) {
  const fs::path root = root_with_output_folder("output_manifest_a");
  const fs::path out = root / "out";
  write(out / "workplane" / "illuminance.csv", "old");
  write(out / "workplane" / "daylight_factor.csv", "old");
  write(out / "gone" / "metrics.csv", "old");
  write(out / "user_notes.txt", "not an output");
  write(root / "outside.txt", "never touched");
  write(out / "summary.json",
        R"({"files": [{"path": "workplane/illuminance.csv"}, {"path": "workplane/daylight_factor.csv"},
                      {"path": "gone/metrics.csv"}, {"path": "../outside.txt"}, {"path": "/etc/hostname"},
                      {"path": "workplane"}]})");
  const OutputManifest m = OutputManifest::begin(out.string(), "pid 1, started now");
  EXPECT_EQ(m.stale_removed(), 3u);
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  EXPECT_TRUE(fs::exists(out / OutputManifest::MarkerName));
  EXPECT_FALSE(fs::exists(out / "workplane" / "illuminance.csv"));
  EXPECT_FALSE(fs::exists(out / "gone"));  // emptied folders go too
  EXPECT_TRUE(fs::exists(out / "user_notes.txt"));
  EXPECT_TRUE(fs::exists(root / "outside.txt"));
  EXPECT_NE(slurp(out / OutputManifest::MarkerName).find("pid 1, started now"), std::string::npos);
  fs::remove_all(root);
}

TEST(OutputManifest, RecordsEntriesAndAnInterruptedRunsFilesAreRemovedNextTime) {
  const fs::path root = root_with_output_folder("output_manifest_b");
  const fs::path out = root / "out";
  {
    OutputManifest m = OutputManifest::begin(out.string(), "first");
    write(out / "b" / "sensors.csv", "sensors");
    write(out / "a.csv", "a");
    m.record((out / "b" / "sensors.csv").string());
    m.record({(out / "a.csv").string(), (out / "a.csv").string()});
    // Appended at once: visible in the marker before the run ends.
    const std::string marker = slurp(out / OutputManifest::MarkerName);
    EXPECT_NE(marker.find("\nb/sensors.csv\n"), std::string::npos) << marker;
    EXPECT_NE(marker.find("\na.csv\n"), std::string::npos) << marker;
    const std::vector<ManifestEntry> e = m.entries();
    ASSERT_EQ(e.size(), 2u);
    EXPECT_EQ(e[0].path, "a.csv");
    EXPECT_EQ(e[0].bytes, 1u);
    EXPECT_EQ(e[0].sha256, sha256_hex("a"));
    EXPECT_EQ(e[1].path, "b/sensors.csv");
    EXPECT_EQ(e[1].sha256, sha256_hex("sensors"));
    EXPECT_THROW(m.record((root / "outside.txt").string()), std::logic_error);
    // The run is "killed" here: no finish().
  }
  const OutputManifest next = OutputManifest::begin(out.string(), "second");
  EXPECT_EQ(next.stale_removed(), 2u);
  EXPECT_FALSE(fs::exists(out / "a.csv"));
  EXPECT_FALSE(fs::exists(out / "b"));
  fs::remove_all(root);
}

TEST(OutputManifest, FinishRemovesTheMarker) {
  const fs::path root = root_with_output_folder("output_manifest_c");
  OutputManifest m = OutputManifest::begin((root / "out").string(), "run");
  m.finish();
  EXPECT_FALSE(fs::exists(root / "out" / OutputManifest::MarkerName));
  fs::remove_all(root);
}

TEST(OutputManifest, ManifestPathsReadsOnlyTheFilesList) {
  EXPECT_EQ(manifest_paths(R"({"files": [{"path": "x"}, {"bytes": 1}, 3, {"path": 4}]})"),
            std::vector<std::string>{"x"});
  EXPECT_TRUE(manifest_paths("not json").empty());
  EXPECT_TRUE(manifest_paths(R"({"timings": []})").empty());
}

}  // namespace
}  // namespace dayphoton::study
