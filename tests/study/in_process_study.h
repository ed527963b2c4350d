// Test support for the study tests that run a whole `run_study` on in-process ranks
// (tests/dist/in_process_ranks.h) and compare it with one process: fresh folders, a quiet run
// alone or on one rank through the distributed executor, every rank's exception as a test
// failure, and the files of a results folder or cache as bytes.
#pragma once

#include <gtest/gtest.h>

#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <iterator>
#include <map>
#include <sstream>
#include <string>

#include "../dist/in_process_ranks.h"
#include "../temp_folder.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/distributed_executor.h"
#include "dayphoton/study/progress.h"
#include "dayphoton/study/study_runner.h"

namespace dayphoton::test {

/// Sensors per block of a grid step in these tests: smaller than the run's (plan_policy.h), so
/// that the small test grids are shared over the ranks by several blocks.
constexpr std::size_t TestSensorBlockSize = 8;

/// Every file below `dir` (relative path -> bytes), but those named in `left_out`.
inline std::map<std::string, std::string> files_of(const std::filesystem::path& dir,
                                                   std::initializer_list<std::string> left_out = {}) {
  std::map<std::string, std::string> files;
  for (const std::filesystem::directory_entry& e : std::filesystem::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const std::string name = e.path().filename().string();
    bool skip = false;
    for (const std::string& l : left_out) skip = skip || name == l;
    if (skip) continue;
    std::ifstream in(e.path(), std::ios::binary);
    files[std::filesystem::relative(e.path(), dir).generic_string()] =
        std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return files;
}

/// The files of a results folder that must be the same bytes for any rank count: all but the
/// run's history (run.log, timings.json) and summary.json (it names the folder).
inline std::map<std::string, std::string> result_files(const std::filesystem::path& dir) {
  return files_of(dir, {"run.log", "timings.json", "summary.json"});
}

/// `run_study` of `project` into `out` with the cache `cache`, quietly: by one process, or with
/// `comm` as that rank of a distributed run (every rank calls it, as under mpirun).
inline study::RunReport run_study_quietly(const project::Project& project, const std::filesystem::path& out,
                                          const std::filesystem::path& cache, dist::Communicator* comm = nullptr) {
  study::RunSettings settings;
  settings.output_dir = out.string();
  settings.cache_dir = cache.string();
  if (comm)
    settings.make_executor = [comm](const study::ArtifactStore& store, bool force) {
      return study::make_distributed_executor(*comm, store, force, TestSensorBlockSize);
    };
  std::ostringstream quiet;
  study::Progress progress(quiet, study::ProgressStyle::Quiet);
  return study::run_study(project, settings, progress);
}

/// `body` on `ranks` in-process ranks; an exception of any rank is a test failure.
inline void run_ranks_expecting_no_error(int ranks, const std::function<void(dist::Communicator&)>& body) {
  const std::vector<std::exception_ptr> errors = dist::test::run_ranks(ranks, body);
  for (std::size_t r = 0; r < errors.size(); ++r)
    if (errors[r]) {
      try {
        std::rethrow_exception(errors[r]);
      } catch (const std::exception& x) {
        ADD_FAILURE() << "rank " << r << ": " << x.what();
      }
    }
}

}  // namespace dayphoton::test
