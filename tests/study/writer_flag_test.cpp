// The writer flag of run_study (study_runner.h): a process whose executor does not write
// results (the ranks other than 0 of an MPI run) writes nothing at all, not even a folder,
// while it takes part in every step. Two in-process ranks (tests/dist/in_process_ranks.h)
// run a small study, each told its own output and cache folder: rank 1's never appear, and
// rank 0's files are those of a one-process run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>

#include "../dist/in_process_ranks.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/distributed_executor.h"
#include "dayphoton/study/progress.h"
#include "dayphoton/study/study_runner.h"
#include "side_lit_room.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

// The side-lit room with a point-in-time case, whose files are made after a collective step.
const std::string RoomYaml = test::side_lit_room_yaml("[4, 5, 3]", "3", 300) +
                             "points_in_time:\n"
                             "  - {name: noon, date: 03-21, time: \"12:00\", sky: cie_overcast}\n"
                             "outputs: {images: false, report: false}\n";

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / name;
  fs::remove_all(dir);
  return dir;
}

/// Every file below `dir` (relative path -> bytes) but the run's history (run.log, timings.json)
/// and summary.json (it names the folder).
std::map<std::string, std::string> result_files(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const std::string name = e.path().filename().string();
    if (name == "run.log" || name == "timings.json" || name == "summary.json") continue;
    std::ifstream in(e.path(), std::ios::binary);
    files[fs::relative(e.path(), dir).generic_string()] =
        std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return files;
}

TEST(WriterFlag, OnlyTheWritingRankWritesAndItsFilesAreTheOneProcessRuns) {
  const project::Project project = project::load_project_from_string(RoomYaml, "room.yaml");
  ASSERT_FALSE(project.points_in_time.empty());
  const fs::path alone = fresh_dir("writer_flag_alone"), alone_cache = fresh_dir("writer_flag_alone_cache");
  {
    RunSettings settings;
    settings.output_dir = alone.string();
    settings.cache_dir = alone_cache.string();
    std::ostringstream quiet;
    Progress progress(quiet, ProgressStyle::Quiet);
    run_study(project, settings, progress);
  }
  const fs::path out[2] = {fresh_dir("writer_flag_rank0"), fresh_dir("writer_flag_rank1")};
  const fs::path cache[2] = {fresh_dir("writer_flag_rank0_cache"), fresh_dir("writer_flag_rank1_cache")};
  const auto errors = dist::test::run_ranks(2, [&](dist::Communicator& comm) {
    RunSettings settings;
    settings.output_dir = out[comm.rank()].string();
    settings.cache_dir = cache[comm.rank()].string();
    settings.make_executor = [&comm](const ArtifactStore& store, bool force) {
      return make_distributed_executor(comm, store, force, 8);
    };
    std::ostringstream quiet;
    Progress progress(quiet, ProgressStyle::Quiet);
    run_study(project, settings, progress);
  });
  for (const std::exception_ptr& e : errors)
    if (e) {
      try {
        std::rethrow_exception(e);
      } catch (const std::exception& x) {
        ADD_FAILURE() << x.what();
      }
    }
  EXPECT_FALSE(fs::exists(out[1])) << "rank 1 made its output folder";
  EXPECT_FALSE(fs::exists(cache[1])) << "rank 1 made its cache folder";
  EXPECT_TRUE(fs::exists(out[0] / "summary.json"));
  EXPECT_TRUE(fs::exists(out[0] / "run.log"));
  EXPECT_TRUE(fs::exists(out[0] / "workplane" / "point_in_time.csv"));
  const std::map<std::string, std::string> expected = result_files(alone);
  EXPECT_GE(expected.size(), 4u);
  EXPECT_EQ(result_files(out[0]), expected);
}

}  // namespace
}  // namespace dayphoton::study
