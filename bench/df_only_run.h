// Bench support: a project run as a daylight-factor study of its base case alone, quietly, and
// the values of its grids read back from results.json (examples_accuracy_bench and
// gathered_grid_honesty_bench); the process's CPU seconds and the load average (the Perez
// benches too).
#pragma once

#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "dayphoton/project/project.h"
#include "dayphoton/study/progress.h"
#include "dayphoton/study/results_model.h"
#include "dayphoton/study/study_runner.h"

namespace dayphoton::bench {

/// The machine's one-minute load average as /proc/loadavg prints it ("unknown" without it):
/// wall times on shared cores mean little without it.
inline std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one;
  in >> one;
  return in ? one : std::string("unknown");
}

/// CPU seconds (user + sys) of this process so far, all threads.
inline double process_cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

/// `proj` with the accuracy target `target_percent` (relative standard error of DF at the
/// 95th-percentile sensor) in place of its preset's, and no time budget; its other accuracy
/// settings kept (the project's photon counts stay the rounds' reference count).
inline void set_accuracy_target(project::Project& proj, double target_percent) {
  project::Simulation::Accuracy accuracy;
  if (proj.simulation.accuracy) accuracy = *proj.simulation.accuracy;
  accuracy.preset.clear();
  accuracy.target_df_relative_stderr_percent = target_percent;
  accuracy.max_seconds = 0;
  proj.simulation.accuracy = accuracy;
}

/// A DF-only run: its results and its wall and CPU seconds (the study alone).
struct DfOnlyRun {
  study::ResultsModel model;
  double seconds = 0, cpu_seconds = 0;
};

/// `proj` as a daylight-factor study of its base case (no variants, annual results, images,
/// report or coefficients), run quietly into `output_dir` (removed first) with the cache
/// `cache_dir`.
inline DfOnlyRun run_df_only(project::Project proj, const std::filesystem::path& output_dir,
                             const std::filesystem::path& cache_dir) {
  proj.study = project::StudyKind::DaylightFactor;
  proj.outputs.daylight_factor = true;
  proj.outputs.annual_illuminance = proj.outputs.metrics = false;
  proj.outputs.images = proj.outputs.report = proj.outputs.coefficients = false;
  proj.variants.clear();
  std::filesystem::remove_all(output_dir);
  std::ostringstream log;
  study::Progress progress(log, study::ProgressStyle::Quiet);
  study::RunSettings settings;
  settings.output_dir = output_dir.string();
  settings.cache_dir = cache_dir.string();
  settings.force = true;
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = process_cpu_seconds();
  study::run_study(proj, settings, progress);
  DfOnlyRun r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.cpu_seconds = process_cpu_seconds() - cpu0;
  r.model = study::read_results_model(settings.output_dir);
  return r;
}

/// One grid's DF and its reported standard error per sensor, %.
struct GridDf {
  std::vector<double> df_percent, stderr_percent;
};

/// The DF values of `grid` of the results in `output_dir`.
inline GridDf read_grid_df(const std::filesystem::path& output_dir, const study::GridResult& grid) {
  const study::SensorQuantity* df = grid.find_quantity("daylight_factor");
  if (!df) throw std::runtime_error("no daylight factor for grid " + grid.name + " in " + output_dir.string());
  GridDf v;
  v.df_percent = study::read_quantity_values(output_dir.string(), grid, *df);
  study::SensorQuantity se = *df;
  se.column = "df_stderr_percent";
  v.stderr_percent = study::read_quantity_values(output_dir.string(), grid, se);
  return v;
}

}  // namespace dayphoton::bench
