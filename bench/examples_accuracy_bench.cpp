// examples_accuracy_bench: is every example project within its accuracy target? Each project
// of projects/ runs as a daylight-factor study twice: at the accuracy target (default 1 %
// relative standard error of DF at the 95th-percentile sensor, simulation.accuracy) and at a
// target sqrt(10) times tighter, which traces about 10 times the photons (the reference). Per
// sensor the relative difference e = (DF - DF_ref) / DF_ref measures the run's whole error:
// its noise, and the change of the density estimate's bias with the photon count, which the
// reported standard error does not contain. The target is met if the RMS of e over the
// sensors is at most target * sqrt(1 + 1/10): when every sensor's standard error is at most
// the target, the noise alone gives an RMS of e at most that (the reference's tenth of the
// variance included), so a larger RMS is bias or an understated standard error. Also printed:
// the 95th percentile of |e|, and the share of sensors whose difference lies within 2 combined
// standard errors (95 % if the reported errors are honest and the bias is small).
//
// The DF-only study traces no sun; the target governs the sky sources only (docs/photon-
// tracing.md, "Accuracy target"). Wall times are printed: with 2 cores a 1 % target takes
// minutes per project and the reference ten times that.
// Usage: examples_accuracy_bench [target_percent [project_name...]]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/progress.h"
#include "dayphoton/study/results_model.h"
#include "dayphoton/study/study_runner.h"

using namespace dayphoton;
namespace fs = std::filesystem;

namespace {

constexpr double ReferencePhotonFactor = 10.0;  ///< the reference traces ~10x the photons

struct DfRun {
  std::vector<double> df_percent, stderr_percent;
  double seconds = 0;
  std::uint64_t photons = 0;
  double reached_percent = 0;
  std::string stop_reason;
};

/// One DF-only run of `proj` at `target_percent`; the values of its first grid.
DfRun run_at(project::Project proj, double target_percent, const fs::path& out, const fs::path& cache) {
  proj.study = project::StudyKind::DaylightFactor;
  project::Simulation::Accuracy accuracy;
  if (proj.simulation.accuracy) accuracy = *proj.simulation.accuracy;
  accuracy.preset.clear();
  accuracy.target_df_relative_stderr_percent = target_percent;
  accuracy.max_seconds = 0;
  proj.simulation.accuracy = accuracy;
  proj.outputs.daylight_factor = true;
  proj.outputs.annual_illuminance = proj.outputs.metrics = false;
  proj.outputs.images = proj.outputs.report = proj.outputs.coefficients = false;
  proj.variants.clear();
  fs::remove_all(out);
  std::ostringstream log;
  study::Progress progress(log, study::ProgressStyle::Lines, 1e9);
  study::RunSettings settings;
  settings.output_dir = out.string();
  settings.cache_dir = cache.string();
  settings.force = true;
  const auto t0 = std::chrono::steady_clock::now();
  study::run_study(proj, settings, progress);
  DfRun r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const study::ResultsModel model = study::read_results_model(out.string());
  const study::GridResult& grid = model.cases.at(0).grids.at(0);
  const study::SensorQuantity* df = grid.find_quantity("daylight_factor");
  if (!df) throw std::runtime_error("no daylight factor in " + out.string());
  r.df_percent = study::read_quantity_values(out.string(), grid, *df);
  study::SensorQuantity se = *df;
  se.column = "df_stderr_percent";
  r.stderr_percent = study::read_quantity_values(out.string(), grid, se);
  if (grid.daylight_factor && grid.daylight_factor->accuracy) {
    r.photons = grid.daylight_factor->accuracy->photons;
    r.reached_percent = grid.daylight_factor->accuracy->reached_percent;
    r.stop_reason = grid.daylight_factor->accuracy->stop_reason;
  }
  return r;
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t i = std::min(v.size() - 1, static_cast<std::size_t>(std::ceil(p * double(v.size())) - 1));
  return v[i];
}

}  // namespace

int main(int argc, char** argv) {
  const double target_percent = argc > 1 ? std::stod(argv[1]) : 1.0;
  std::vector<std::string> names;
  for (int i = 2; i < argc; ++i) names.push_back(argv[i]);
  const fs::path projects = fs::path(DAYPHOTON_BENCH_SOURCE_DIR) / "projects";
  if (names.empty())
    for (const fs::directory_entry& e : fs::directory_iterator(projects))
      if (fs::exists(e.path() / "project.yaml")) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  const double bound = target_percent * std::sqrt(1.0 + 1.0 / ReferencePhotonFactor);
  std::printf("target %.2f %% (p95 sensor relative standard error of DF); reference at %.3f %%; "
              "pass: RMS relative difference <= %.2f %%\n",
              target_percent, target_percent / std::sqrt(ReferencePhotonFactor), bound);
  std::printf("%-16s %7s %8s %8s %9s %9s %8s %8s %7s %7s %s\n", "project", "sensors", "run s", "ref s",
              "photons", "ref phot", "rms e %", "p95 e %", "in 2se", "reached", "verdict");
  int failed = 0;
  for (const std::string& name : names) {
    const fs::path out = fs::temp_directory_path() / ("dayphoton_accuracy_bench_" + name);
    const fs::path cache = fs::temp_directory_path() / ("dayphoton_accuracy_bench_cache_" + name);
    try {
      const project::Project proj = project::load_project((projects / name / "project.yaml").string());
      const DfRun run = run_at(proj, target_percent, out / "run", cache);
      const DfRun ref = run_at(proj, target_percent / std::sqrt(ReferencePhotonFactor), out / "ref", cache);
      std::vector<double> e_percent, abs_e;
      std::size_t within = 0, counted = 0;
      for (std::size_t s = 0; s < run.df_percent.size() && s < ref.df_percent.size(); ++s) {
        if (!(ref.df_percent[s] > 0)) continue;
        const double e = (run.df_percent[s] - ref.df_percent[s]) / ref.df_percent[s];
        e_percent.push_back(100.0 * e);
        abs_e.push_back(100.0 * std::abs(e));
        const double se = std::hypot(run.stderr_percent[s], ref.stderr_percent[s]);
        ++counted;
        if (std::abs(run.df_percent[s] - ref.df_percent[s]) <= 2.0 * se) ++within;
      }
      double sum2 = 0;
      for (double e : e_percent) sum2 += e * e;
      const double rms = e_percent.empty() ? 0 : std::sqrt(sum2 / double(e_percent.size()));
      const bool pass = rms <= bound;
      if (!pass) ++failed;
      std::printf("%-16s %7zu %8.1f %8.1f %9llu %9llu %8.2f %8.2f %6.0f%% %6.2f%% %s\n", name.c_str(),
                  run.df_percent.size(), run.seconds, ref.seconds, static_cast<unsigned long long>(run.photons),
                  static_cast<unsigned long long>(ref.photons), rms, percentile(abs_e, 0.95),
                  counted ? 100.0 * double(within) / double(counted) : 0.0, run.reached_percent,
                  pass ? "within target" : ("NOT within target (" + run.stop_reason + ")").c_str());
    } catch (const std::exception& e) {
      ++failed;
      std::printf("%-16s error: %s\n", name.c_str(), e.what());
    }
    std::fflush(stdout);
    fs::remove_all(out);
    fs::remove_all(cache);
  }
  std::printf("%zu projects, %d not within the target\n", names.size(), failed);
  return 0;
}
