// `dayphoton run PROJECT.yaml...`: the daylight study of each project (study/study_runner.h),
// with progress on the terminal (a redrawn bar) or plain lines when the output is not one,
// and a table of where the time went. Several projects run one after the other, each into
// its own output folder (or into --output/<project name> when --output is given for more
// than one project). Under mpirun with at least as many cases (every project's base and
// variants) as ranks, the cases of all the projects are units dealt out to the ranks by
// their estimated cost first (study/case_units.h, docs/cluster.md "Projects as units").
#include <unistd.h>

#include <exception>
#include <filesystem>
#include <memory>
#include <iostream>
#include <ostream>
#include <string>
#include <vector>

#include <tbb/global_control.h>

#include "commands.h"
#include "dayphoton/project/path_name.h"
#include "dayphoton/project/project.h"
#include "dayphoton/report/report_html.h"
#include "dayphoton/study/case_cost.h"
#include "dayphoton/study/case_units.h"
#include "dayphoton/study/distributed_executor.h"
#include "dayphoton/study/placement_check.h"
#include "dayphoton/study/study_runner.h"

namespace dayphoton::app {
namespace {

/// The output folder of each project: --output itself for one project; for several,
/// --output/<name of the project file's folder>, a name that must pass the path-name rule and
/// differ from the others' (else two projects would write into one folder). Empty strings
/// without --output (each project's outputs.folder).
std::vector<std::string> output_folders(const RunOptions& options) {
  namespace fs = std::filesystem;
  const std::size_t n = options.project_paths.size();
  if (options.output_dir.empty()) return std::vector<std::string>(n);
  if (n == 1) return {options.output_dir};
  std::vector<std::string> folders, folds;
  for (const std::string& path : options.project_paths) {
    const std::string name = fs::absolute(path).lexically_normal().parent_path().filename().string();
    const std::string problem = project::path_name_problem(name);
    if (!problem.empty())
      throw UsageError("with --output and several projects, each writes to --output/<name of its folder>, but the "
                       "folder of '" + path + "' is named '" + project::printable_name(name) +
                       "', which is not a portable folder name: " + problem + " (" + project::PathNameRule +
                       "); run that project on its own");
    const std::string fold = project::path_name_fold(name);
    for (std::size_t i = 0; i < folds.size(); ++i)
      if (folds[i] == fold)
        throw UsageError("with --output and several projects, each writes to --output/<name of its folder>: '" +
                         options.project_paths[i] + "' and '" + path + "' would both write to " +
                         (fs::path(options.output_dir) / name).string() + "; run them one at a time");
    folds.push_back(fold);
    folders.push_back((fs::path(options.output_dir) / name).string());
  }
  return folders;
}

}  // namespace

int run_run(const RunOptions& options, std::ostream& out, std::ostream& err) {
  std::unique_ptr<tbb::global_control> threads;
  if (options.threads > 0)
    threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                    static_cast<std::size_t>(options.threads));
  // Under mpirun the ranks check the same inputs alike: they agree on a failure, which rank 0
  // alone prints (commands.h agree_on_failure), instead of every rank printing it.
  dist::Communicator* const ranks = options.ranks && options.ranks->size() > 1 ? options.ranks : nullptr;
  auto checked = [ranks, &err](const std::exception_ptr& failure) {
    if (ranks) agree_on_failure(*ranks, failure, err);
    if (failure) std::rethrow_exception(failure);
  };
  // Load every project first: a typo in the last one should not wait for the first to run.
  // With --output, outputs.folder is not used and may lie anywhere.
  std::vector<std::string> folders;
  std::vector<project::Project> projects;
  std::vector<study::RunInputs> inputs;
  std::exception_ptr failure;
  try {
    folders = output_folders(options);
    project::LoadOptions load;
    load.output_folder_overridden = !options.output_dir.empty();
    for (const std::string& path : options.project_paths) projects.push_back(project::load_project(path, load));
    // Geometry and placement (no port, no sensor, sensors outside every room or in a solid,
    // undecidable ports) of every case, and the weather file and the points in time of every
    // project (run_inputs.h), before anything is written.
    for (const project::Project& proj : projects) study::check_project_placement(proj);
    for (const project::Project& proj : projects) inputs.push_back(study::read_run_inputs(proj));
  } catch (...) {
    failure = std::current_exception();
  }
  checked(failure);

  auto settings_of = [&](std::size_t i) {
    const project::Project& proj = projects[i];
    study::RunSettings settings;
    settings.force = options.force;
    settings.version = DAYPHOTON_VERSION;
    settings.command = "dayphoton run " + proj.path;
    settings.output_dir = folders[i];
    settings.cache_dir = options.cache_dir;
    settings.write_views = report::write_views;  // images and report.html from results.json's model
    // Under mpirun every rank runs the study (distributed_executor.h); the executor's writer
    // flag keeps the ranks other than 0 from writing anything (study_runner.h).
    if (ranks) {
      settings.make_executor = [ranks](const study::ArtifactStore& store, bool force) {
        return study::make_distributed_executor(*ranks, store, force);
      };
    }
    // The weather file and the points in time, read and checked above (the ranks agree again).
    settings.inputs_checked = checked;
    settings.inputs = &inputs[i];
    return settings;
  };
  const study::ProgressStyle style =
      study::Progress::choose_style(&out == &std::cout && isatty(STDOUT_FILENO), options.quiet);
  // Under mpirun, several projects with at least as many cases in all as ranks: every case of
  // every project is a unit (case_units.h), each rank computes its own units' steps alone into
  // its project's cache, rank 0 receives the others'; then each project runs from its cache.
  std::string units_line;
  std::vector<std::unique_ptr<study::ArtifactStore>> stores;  // each project's cache, if units
  if (ranks && projects.size() > 1 && !options.force) {
    std::size_t cases = 0;
    for (const project::Project& proj : projects) cases += 1 + proj.variants.size();
    if (cases >= static_cast<std::size_t>(ranks->size())) {
      std::vector<const study::ArtifactStore*> store_of;
      std::vector<study::CaseUnit> units;
      for (std::size_t p = 0; p < projects.size(); ++p) {
        stores.push_back(std::make_unique<study::ArtifactStore>(study::run_cache_folder(projects[p], settings_of(p))));
        store_of.push_back(stores.back().get());
        const study::RunInputs& in = inputs[p];
        const std::vector<double> costs = study::case_costs_seconds(
            projects[p], study::sun_year_of(projects[p], in.weather ? &*in.weather : nullptr,
                                            in.sun_site ? &*in.sun_site : nullptr));
        for (std::size_t c = 0; c < costs.size(); ++c) units.push_back({p, c, costs[c]});
      }
      const std::unique_ptr<study::CaseUnits> assigned = study::make_case_units(*ranks, store_of, false, units);
      study::Progress progress(out, style);
      for (std::size_t u = 0; u < units.size(); ++u)
        if (assigned->mine(u))
          study::run_case_steps(projects[units[u].project], inputs[units[u].project], units[u].case_index,
                                settings_of(units[u].project), *stores[units[u].project],
                                assigned->executor(units[u].project), progress);
      units_line = assigned->join();
    }
  }
  for (std::size_t i = 0; i < projects.size(); ++i) {
    const project::Project& proj = projects[i];
    study::Progress progress(out, style);
    study::RunSettings settings = settings_of(i);
    settings.cases_as_units = units_line.empty();
    settings.units_line = units_line;
    if (!stores.empty()) settings.store = stores[i].get();  // what the units stored is used by this run
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
