// Test support for the study tests: a whole `run_study` into a fresh folder, quietly.
#pragma once

#include <filesystem>
#include <sstream>

#include "dayphoton/project/project.h"
#include "dayphoton/study/cache_folder.h"
#include "dayphoton/study/progress.h"
#include "dayphoton/study/study_runner.h"

namespace dayphoton::test {

/// Run `project` into `out` after removing the folder and its cache (cache_folder.h), so that
/// nothing of an earlier test run is read back; no progress output.
inline study::RunReport run_in_fresh_folder(const project::Project& project, const std::filesystem::path& out) {
  std::filesystem::remove_all(out);
  std::filesystem::remove_all(study::default_cache_folder(out.string()));
  study::RunSettings settings;
  settings.output_dir = out.string();
  std::ostringstream quiet;
  study::Progress progress(quiet, study::ProgressStyle::Quiet);
  return study::run_study(project, settings, progress);
}

/// The project file `project_file` run as run_in_fresh_folder runs a project, into `out`
/// instead of its own `outputs.folder` (as `dayphoton run -o` does).
inline study::RunReport run_file_in_fresh_folder(const std::filesystem::path& project_file,
                                                 const std::filesystem::path& out) {
  project::LoadOptions options;
  options.output_folder_overridden = true;
  return run_in_fresh_folder(project::load_project(project_file.string(), options), out);
}

}  // namespace dayphoton::test
