// `dayphoton run PROJECT.yaml...`: the daylight study of each project (study/study_runner.h),
// with progress on the terminal (a redrawn bar) or plain lines when the output is not one,
// and a table of where the time went. Several projects run one after the other, each into
// its own output folder (or into --output/<project name> when --output is given for more
// than one project).
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <iostream>
#include <ostream>

#include <tbb/global_control.h>

#include "commands.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/study_runner.h"

namespace dayphoton::app {

int run_run(const RunOptions& options, std::ostream& out, std::ostream& err) {
  (void)err;
  std::unique_ptr<tbb::global_control> threads;
  if (options.threads > 0)
    threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                    static_cast<std::size_t>(options.threads));
  // Load every project first: a typo in the last one should not wait for the first to run.
  std::vector<project::Project> projects;
  for (const std::string& path : options.project_paths) projects.push_back(project::load_project(path));

  const study::ProgressStyle style =
      study::Progress::choose_style(&out == &std::cout && isatty(STDOUT_FILENO), options.quiet);
  for (const project::Project& proj : projects) {
    study::Progress progress(out, style);
    study::RunSettings settings;
    settings.force = options.force;
    settings.version = DAYPHOTON_VERSION;
    settings.command = "dayphoton run " + proj.path;
    if (!options.output_dir.empty()) {
      settings.output_dir =
          projects.size() == 1
              ? options.output_dir
              : (std::filesystem::path(options.output_dir) /
                 std::filesystem::path(proj.path).parent_path().filename()).string();
    }
    const study::RunReport report = study::run_study(proj, settings, progress);
    progress.print_summary();
    if (!options.quiet) {
      out << "results: " << report.output_dir << "\n";
      for (const study::GridReport& g : report.grids)
        out << "  " << g.name << ": " << g.sensors << " sensors in " << g.folder << "\n";
    }
  }
  require_written(out, "standard output");
  return ExitOk;
}

}  // namespace dayphoton::app
