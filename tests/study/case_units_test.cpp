// Whole cases as units over the ranks (case_units.h): a side-lit room with two variants (three
// cases) run on 2 and 3 in-process ranks (tests/dist/in_process_ranks.h) through the
// distributed executor. Each rank first computes the cases it owns alone; rank 0's results
// folder and cache must be those of a one-process run, byte for byte, and its run.log must
// name the assignment. With fewer cases than ranks there are no units.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include "dayphoton/project/project.h"
#include "dayphoton/study/case_units.h"
#include "in_process_study.h"
#include "side_lit_room.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

const std::string RoomYaml = test::side_lit_room_yaml("[4, 5, 3]", "3", 300) +
                             "outputs: {images: false, report: false}\n"
                             "variants:\n"
                             "  - name: darker\n"
                             "    materials: {walls: {type: lambertian, reflectance: 0.3}}\n"
                             "  - name: tinted\n"
                             "    materials: {glass: {type: glass, transmittance: 0.4}}\n";

using test::files_of;
using test::fresh_dir;

std::string text_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(CaseUnits, OnlyWithAtLeastAsManyCasesAsRanksAndWithoutForce) {
  test::run_ranks_expecting_no_error(3, [&](dist::Communicator& comm) {
    const ArtifactStore store(fresh_dir("case_units_count_rank" + std::to_string(comm.rank())).string());
    if (make_case_units(comm, store, false, 2)) throw std::runtime_error("units for 2 cases over 3 ranks");
    if (make_case_units(comm, store, true, 3)) throw std::runtime_error("units with force");
    const auto units = make_case_units(comm, store, false, 4);
    if (!units) throw std::runtime_error("no units for 4 cases over 3 ranks");
    // Case c on rank 2 - c mod 3: rank 0 owns the fewest (it writes every case afterwards).
    for (std::size_t c = 0; c < 4; ++c)
      if (units->mine(c) != (comm.rank() == 2 - int(c % 3)))
        throw std::runtime_error("case " + std::to_string(c) + " on the wrong rank");
    units->join();  // nothing computed: nothing sent
  });
}

TEST(CaseUnits, VariantsAsUnitsGiveTheOneProcessResultsAndCache) {
  const project::Project project = project::load_project_from_string(RoomYaml, "room.yaml");
  ASSERT_EQ(project.variants.size(), 2u);
  const fs::path alone = fresh_dir("case_units_alone"), alone_cache = fresh_dir("case_units_alone_cache");
  test::run_study_quietly(project, alone, alone_cache);
  const std::map<std::string, std::string> results = test::result_files(alone);
  const std::map<std::string, std::string> cache = files_of(alone_cache);
  ASSERT_GE(results.size(), 9u);  // three cases' sensors, daylight factors, ...
  ASSERT_GT(cache.size(), 146u);
  for (int ranks : {2, 3}) {
    SCOPED_TRACE(std::to_string(ranks) + " ranks");
    const std::string tag = "case_units_" + std::to_string(ranks);
    const fs::path out = fresh_dir(tag + "_out"), cached = fresh_dir(tag + "_cache");
    test::run_ranks_expecting_no_error(
        ranks, [&](dist::Communicator& comm) { test::run_study_quietly(project, out, cached, &comm); });
    EXPECT_EQ(test::result_files(out), results);
    EXPECT_EQ(files_of(cached), cache);
    const std::string log = text_of(out / "run.log");
    EXPECT_NE(log.find("cases as units over " + std::to_string(ranks) + " ranks: rank 0 case"), std::string::npos)
        << log;
    // Every step of the three cases' runs came from the cache the units filled.
    const std::string cached_line = "photons: traced 0 of 146 sources (not needed: every grid's coefficients are cached)";
    std::size_t cached_cases = 0;
    for (std::size_t at = log.find(cached_line); at != std::string::npos; at = log.find(cached_line, at + 1))
      ++cached_cases;
    EXPECT_EQ(cached_cases, 3u) << log;
  }
}

}  // namespace
}  // namespace dayphoton::study
