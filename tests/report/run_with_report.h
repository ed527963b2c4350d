// Test support: a whole `run_study`, quietly, that also writes what a person reads of it
// (report.html, and report.pdf where Chromium is installed) as `dayphoton run` does.
#pragma once

#include <filesystem>
#include <sstream>

#include "dayphoton/project/project.h"
#include "dayphoton/report/report_html.h"
#include "dayphoton/study/progress.h"
#include "dayphoton/study/study_runner.h"

namespace dayphoton::test {

/// Run `project` into `out` with the report's views; no progress output.
inline study::RunReport run_with_report(const project::Project& project, const std::filesystem::path& out) {
  study::RunSettings settings;
  settings.output_dir = out.string();
  settings.write_views = report::write_views;
  std::ostringstream quiet;
  study::Progress progress(quiet, study::ProgressStyle::Quiet);
  return study::run_study(project, settings, progress);
}

}  // namespace dayphoton::test
