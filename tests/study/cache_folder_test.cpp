// The cache folder beside the output folder, the used list and pruning (study/cache_folder.h).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "dayphoton/study/artifact_store.h"
#include "dayphoton/study/cache_folder.h"
#include "../temp_folder.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

using test::empty_dir;

TEST(CacheFolder, IsAHiddenSiblingOfTheOutputFolder) {
  EXPECT_EQ(default_cache_folder("projects/office/results"), "projects/office/.results-cache");
  EXPECT_EQ(default_cache_folder("projects/office/results/"), "projects/office/.results-cache");
  EXPECT_EQ(default_cache_folder("results"), ".results-cache");
  EXPECT_EQ(default_cache_folder("a/x/../out"), "a/.out-cache");
  // "." is the current folder: its sibling, by its absolute name.
  EXPECT_EQ(default_cache_folder("."),
            (fs::current_path().parent_path() / ("." + fs::current_path().filename().string() + "-cache")).string());
  EXPECT_EQ(legacy_cache_folder("out"), "out/.cache");
}

TEST(CacheFolder, PruningKeepsWhatTheLastCompleteRunUsed) {
  const fs::path dir = empty_dir("cache_folder_prune");
  const ArtifactStore old_run((dir / "cache").string());
  old_run.write("photons", "aaaa", std::string(1000, 'a'));
  old_run.write("photons", "bbbb", std::string(500, 'b'));
  // Without a list, what is reusable is unknown: an error, and nothing goes.
  EXPECT_THROW(prune_cache((dir / "cache").string(), false), std::runtime_error);
  // The next run reads one artefact and writes another; its list names those two.
  const ArtifactStore run((dir / "cache").string());
  ASSERT_TRUE(run.read("photons", "bbbb"));
  EXPECT_FALSE(run.read("photons", "zzzz"));  // a miss is not a use
  run.write("coefficients", "cccc", "c");
  write_used_list(run);
  EXPECT_EQ(run.used_files(), (std::vector<std::string>{"coefficients-cccc.bin", "photons-bbbb.bin"}));

  const CachePruning dry = prune_cache((dir / "cache").string(), true);
  EXPECT_EQ(dry.removed_files, 1u);
  EXPECT_EQ(dry.kept_files, 2u);
  EXPECT_TRUE(fs::exists(old_run.path_for("photons", "aaaa")));
  const CachePruning done = prune_cache((dir / "cache").string(), false);
  EXPECT_EQ(done.removed_files, 1u);
  EXPECT_GT(done.removed_bytes, 1000u);  // the frame and the payload
  EXPECT_FALSE(fs::exists(old_run.path_for("photons", "aaaa")));
  EXPECT_TRUE(run.read("photons", "bbbb"));
  EXPECT_TRUE(run.read("coefficients", "cccc"));
}

TEST(CacheFolder, AnEarlierVersionsCacheMovesBesideTheOutputFolder) {
  const fs::path dir = empty_dir("cache_folder_legacy");
  const fs::path out = dir / "results";
  const ArtifactStore legacy(legacy_cache_folder(out.string()));
  legacy.write("photons", "aaaa", "payload");
  const std::string cache = default_cache_folder(out.string());
  EXPECT_TRUE(adopt_legacy_cache(out.string(), cache));
  EXPECT_FALSE(fs::exists(out / ".cache"));
  EXPECT_EQ(ArtifactStore(cache).read("photons", "aaaa"), std::optional<std::string>("payload"));
  // Once moved (or when the new folder exists), nothing moves again.
  fs::create_directories(out / ".cache");
  EXPECT_FALSE(adopt_legacy_cache(out.string(), cache));
  EXPECT_TRUE(fs::exists(out / ".cache"));
}

}  // namespace
}  // namespace dayphoton::study
