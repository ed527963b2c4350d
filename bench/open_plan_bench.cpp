// open_plan_bench: the scale bench. The whole annual study (`dayphoton run --force`: photons,
// sky and sun coefficients, daylight factor, annual illuminance with the exact hourly sun,
// metrics, files) of bench/scenes/open_plan: a 50 m x 50 m open-plan floor with windows on two
// facades and columns, 10,000 work-plane sensors at 0.5 m. Prints the wall time, each step's
// time, the peak resident memory, the size of the results and of the cache, and the DF
// uncertainty the run reports, so that cost per sensor can be read off.
// Usage: open_plan_bench [threads [photons_per_bin]] (default: the project's 40,000 photons per
// bin, which reach the 2 % DF uncertainty goal; docs/photon-tracing.md "Scale").
#include <sys/resource.h>
#include <tbb/global_control.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "dayphoton/project/project.h"
#include "dayphoton/study/study_runner.h"

using namespace dayphoton;
namespace fs = std::filesystem;

namespace {

std::uintmax_t folder_bytes(const fs::path& folder) {
  std::uintmax_t total = 0;
  if (!fs::exists(folder)) return 0;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(folder))
    if (e.is_regular_file()) total += e.file_size();
  return total;
}

double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

/// CPU seconds of the process so far, user + system.
double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

/// The 1-minute load average (/proc/loadavg): wall times mean little on a loaded machine.
std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one;
  in >> one;
  return in ? one : std::string("unknown");
}

}  // namespace

int main(int argc, char** argv) {
  std::unique_ptr<tbb::global_control> limit;
  if (argc > 1)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                  std::stoul(argv[1]));
  project::Project proj = project::load_project(std::string(DAYPHOTON_BENCH_SOURCE_DIR) +
                                                "/bench/scenes/open_plan/project.yaml");
  if (argc > 2) proj.simulation.photons_per_bin = std::stoll(argv[2]);
  const fs::path out = fs::temp_directory_path() / "dayphoton_open_plan_bench";
  const fs::path cache = fs::temp_directory_path() / "dayphoton_open_plan_bench_cache";
  fs::remove_all(out);
  fs::remove_all(cache);
  std::ostringstream log;
  study::Progress progress(log, study::ProgressStyle::Lines, 1e9);
  study::RunSettings settings;
  settings.output_dir = out.string();
  settings.cache_dir = cache.string();
  settings.force = true;
  const std::string load_at_start = load_average();
  const auto t0 = std::chrono::steady_clock::now();
  const study::RunReport report = study::run_study(proj, settings, progress);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::size_t sensors = 0;
  for (const study::GridReport& g : report.grids) sensors += g.sensors;
  const unsigned threads = static_cast<unsigned>(
      tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
  std::printf("open-plan floor 50 m x 50 m, %zu sensors, %lld photons per bin, %u threads\n", sensors,
              proj.simulation.photons_per_bin, threads);
  std::printf("whole annual study: %.1f s wall, %.2f ms wall per sensor; %.1f s CPU (user + system), %.2f ms "
              "CPU per sensor; load average %s at the start, %s at the end\n",
              seconds, 1000.0 * seconds / double(sensors > 0 ? sensors : 1), cpu_seconds(),
              1000.0 * cpu_seconds() / double(sensors > 0 ? sensors : 1), load_at_start.c_str(), load_average().c_str());
  // Each step's wall and CPU seconds (all threads), and what the run did after its last step
  // (the results model, hashing the outputs for the manifest, summary.json).
  double step_wall = 0, step_cpu = 0;
  std::printf("  %-30s %8s %8s %6s\n", "step", "wall s", "CPU s", "CPU/wall");
  for (const study::Progress::StepTime& s : progress.steps()) {
    std::printf("  %-30s %8.2f %8.2f %6.2f\n", s.name.c_str(), s.seconds, s.cpu_seconds,
                s.seconds > 0 ? s.cpu_seconds / s.seconds : 0.0);
    step_wall += s.seconds;
    step_cpu += s.cpu_seconds;
  }
  std::printf("  %-30s %8.2f %8.2f\n", "outside the steps", seconds - step_wall, cpu_seconds() - step_cpu);
  const double results_mib = double(folder_bytes(out)) / (1024.0 * 1024.0);
  const double cache_mib = double(folder_bytes(cache)) / (1024.0 * 1024.0);
  std::printf("peak RSS %.0f MiB; results %.1f MiB (%.1f KiB per sensor); cache %.1f MiB\n", peak_rss_mib(),
              results_mib, 1024.0 * results_mib / double(sensors > 0 ? sensors : 1), cache_mib);
  // The uncertainty the run reports per grid (summary.json "uncertainty", docs/outputs.md).
  std::ifstream summary_file(out / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summary_file);
  for (const nlohmann::json& grid : summary.at("grids")) {
    if (!grid.contains("uncertainty")) continue;
    const nlohmann::json& u = grid.at("uncertainty");
    std::printf("grid %s: DF relative standard error RMS %.2f %%, largest %.2f %%\n",
                grid.at("name").get<std::string>().c_str(),
                u.value("df_rms_relative_stderr_percent", -1.0), u.value("df_max_relative_stderr_percent", -1.0));
  }
  std::printf("goal (2 cores): <= 60 s wall and <= 1 GiB RSS at DF RMS uncertainty <= 2 %%\n");
  fs::remove_all(out);
  fs::remove_all(cache);
  return 0;
}
