// The writer flag of run_study (study_runner.h): a process whose executor does not write
// results (the ranks other than 0 of an MPI run) writes nothing at all, not even a folder,
// while it takes part in every step. Two in-process ranks (tests/dist/in_process_ranks.h)
// run a small study, each told its own output and cache folder: rank 1's never appear, and
// rank 0's files are those of a one-process run.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

#include "dayphoton/project/project.h"
#include "in_process_study.h"
#include "side_lit_room.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

// The side-lit room with a point-in-time case, whose files are made after a collective step.
const std::string RoomYaml = test::side_lit_room_yaml("[4, 5, 3]", "3", 300) +
                             "points_in_time:\n"
                             "  - {name: noon, date: 03-21, time: \"12:00\", sky: cie_overcast}\n"
                             "outputs: {images: false, report: false}\n";

using test::fresh_dir;

TEST(WriterFlag, OnlyTheWritingRankWritesAndItsFilesAreTheOneProcessRuns) {
  const project::Project project = project::load_project_from_string(RoomYaml, "room.yaml");
  ASSERT_FALSE(project.points_in_time.empty());
  const fs::path alone = fresh_dir("writer_flag_alone"), alone_cache = fresh_dir("writer_flag_alone_cache");
  test::run_study_quietly(project, alone, alone_cache);
  const fs::path out[2] = {fresh_dir("writer_flag_rank0"), fresh_dir("writer_flag_rank1")};
  const fs::path cache[2] = {fresh_dir("writer_flag_rank0_cache"), fresh_dir("writer_flag_rank1_cache")};
  test::run_ranks_expecting_no_error(2, [&](dist::Communicator& comm) {
    test::run_study_quietly(project, out[comm.rank()], cache[comm.rank()], &comm);
  });
  EXPECT_FALSE(fs::exists(out[1])) << "rank 1 made its output folder";
  EXPECT_FALSE(fs::exists(cache[1])) << "rank 1 made its cache folder";
  EXPECT_TRUE(fs::exists(out[0] / "summary.json"));
  EXPECT_TRUE(fs::exists(out[0] / "run.log"));
  EXPECT_TRUE(fs::exists(out[0] / "workplane" / "point_in_time.csv"));
  const std::map<std::string, std::string> expected = test::result_files(alone);
  EXPECT_GE(expected.size(), 4u);
  EXPECT_EQ(test::result_files(out[0]), expected);
}

}  // namespace
}  // namespace dayphoton::study
