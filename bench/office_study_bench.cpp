// office_study_bench: the whole annual study of the reference office (projects/office), end
// to end as `dayphoton run --force` does it (photons, coefficients, daylight factor, sky
// matrix, annual illuminance, metrics, files), timed, next to the RADIANCE times recorded in
// ../shared/refdata (2 cores): rfluxmtx sky coefficients 113 s (b_dc_classic), gendaymtx -m 1
// 1.5 s and dctimestep 3.4 s (c_annual). Issue 5's goal: the whole study in at most one tenth
// of rfluxmtx's time for the sky coefficients alone. Also prints the RMS relative standard
// error of DF the run reports. Usage: office_study_bench [threads]
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "dayphoton/project/project.h"
#include "dayphoton/study/study_runner.h"

using namespace dayphoton;

int main(int argc, char** argv) {
  std::unique_ptr<tbb::global_control> limit;
  if (argc > 1)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                  std::stoul(argv[1]));
  const project::Project proj =
      project::load_project(std::string(DAYPHOTON_BENCH_SOURCE_DIR) + "/projects/office/project.yaml");
  const std::string out = (std::filesystem::temp_directory_path() / "dayphoton_office_study_bench").string();
  std::filesystem::remove_all(out);
  std::ostringstream log;
  study::Progress progress(log, study::ProgressStyle::Lines, 1e9);
  study::RunSettings settings;
  settings.output_dir = out;
  settings.force = true;
  const auto t0 = std::chrono::steady_clock::now();
  study::run_study(proj, settings, progress);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("office annual study, %lld photons per bin, bandwidth %d, %u threads: %.2f s wall\n",
              proj.simulation.photons_per_bin, proj.simulation.bandwidth,
              static_cast<unsigned>(tbb::global_control::active_value(
                  tbb::global_control::max_allowed_parallelism)),
              seconds);
  for (const study::Progress::StepTime& s : progress.steps())
    std::printf("  %-28s %8.2f s\n", s.name.c_str(), s.seconds);
  const double rfluxmtx_s = 113.0, radiance_annual_s = 113.0 + 1.5 + 3.4;
  std::printf("RADIANCE (refdata, 2 cores): rfluxmtx sky coefficients %.0f s; with gendaymtx and dctimestep %.0f s\n",
              rfluxmtx_s, radiance_annual_s);
  std::printf("ratio: dayphoton's whole study takes %.3f of rfluxmtx's sky coefficients (goal <= 0.1), "
              "%.1f times faster than RADIANCE's annual workflow\n",
              seconds / rfluxmtx_s, radiance_annual_s / seconds);
  // The uncertainty the run reports (daylight_factor.csv, df_stderr_percent; docs/outputs.md):
  // the RMS over sensors of the relative standard error of DF, and the largest.
  std::ifstream df(out + "/workplane/daylight_factor.csv");
  std::string line;
  std::getline(df, line);  // index,x,y,z,df_percent,df_stderr_percent
  double sum = 0, largest = 0;
  std::size_t n = 0;
  while (std::getline(df, line)) {
    std::vector<double> v;
    std::stringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ',')) v.push_back(std::stod(field));
    if (v.size() != 6 || !(v[4] > 0)) continue;
    const double r = v[5] / v[4];
    sum += r * r;
    largest = std::max(largest, r);
    ++n;
  }
  if (n > 0)
    std::printf("DF uncertainty (reported standard error, %zu sensors): RMS relative %.2f %%, largest %.2f %%\n", n,
                100.0 * std::sqrt(sum / double(n)), 100.0 * largest);
  std::filesystem::remove_all(out);
  return 0;
}
