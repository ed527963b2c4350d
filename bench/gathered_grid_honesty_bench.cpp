// gathered_grid_honesty_bench: is one grid's reported standard error of DF honest at the
// default accuracy, and its mean unbiased? The project runs as a daylight-factor study at
// its accuracy target (as examples_accuracy_bench runs it: the project's photon counts become
// the rounds' reference count, its other grids kept, so the photons are the ones the whole
// project traces) over `seeds` seeds (1..seeds), and the named grid's DF and reported
// standard error (df_stderr_percent) are collected per sensor. Then a long reference: the
// named grid alone, fixed photon counts (`ref_photon_factor` x the project's photons_per_bin),
// `ref_gather_rays` gather rays and 10x the shadow rays, seeds 1001..1000+ref_seeds, averaged.
//
// Per sensor s (n = seeds runs): S_s, the sample standard deviation of DF over the runs, and
// sigma_s, the mean reported standard error. For normal errors (n - 1) S^2 / sigma^2 ~
// chi^2(n - 1), so R_s = S_s / (c4(n) sigma_s) has mean 1 and standard deviation
// sqrt(1 - c4^2) / c4 (0.166 at n = 20) per sensor; the mean of R_s over the sensors has the
// standard deviation sqrt(mean over s, t of rho_st^2 / (2 (n - 1))) (delta method, rho the
// runs' correlations; tests/study/uncertainty_honesty_test.cpp). Bias: z_s = (mean_s -
// ref_s) / sqrt(S_s^2 / n + se_ref_s^2), se_ref_s being the reference's mean reported
// standard error over sqrt(ref_seeds) (its own spread over the reference seeds is printed
// too). CPU seconds (user + sys, all threads) are printed.
// Usage: gathered_grid_honesty_bench project_name grid_name [seeds [ref_photon_factor
//        [ref_gather_rays [ref_seeds]]]]   (defaults 20, 10, 65536, 3); seeds 0: the
//        references alone (e.g. a reference at the runs' photon count, to see the kernel bias
//        change with the photons).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "dayphoton/project/project.h"
#include "dayphoton/study/results_model.h"
#include "df_only_run.h"

using namespace dayphoton;
namespace fs = std::filesystem;

namespace {

struct GridValues {
  std::vector<double> df, se;
  std::string note;  ///< the grid's accuracy: reached p95, status, gather rays, rounds, stop
};

GridValues run_once(const project::Project& proj, const std::string& grid_name, const fs::path& out) {
  fs::remove_all(out);
  const bench::DfOnlyRun run = bench::run_df_only(proj, out / "out", out / "cache");
  for (const study::GridResult& grid : run.model.cases.at(0).grids) {
    if (grid.name != grid_name) continue;
    bench::GridDf values = bench::read_grid_df(out / "out", grid);
    GridValues v;
    v.df = std::move(values.df_percent);
    v.se = std::move(values.stderr_percent);
    if (grid.daylight_factor && grid.daylight_factor->accuracy) {
      const auto& a = *grid.daylight_factor->accuracy;
      char buffer[256];
      std::snprintf(buffer, sizeof buffer, "p95 %.3f %% (%s; %d rays, %zu gather rounds: %s; %llu photons)",
                    a.reached_percent, a.status.c_str(), a.gather_rays, a.gather_rounds,
                    a.gather_stop_reason.c_str(), static_cast<unsigned long long>(a.photons));
      v.note = buffer;
    }
    fs::remove_all(out);
    return v;
  }
  throw std::runtime_error("no grid " + grid_name + " in the base case");
}

double c4(int n) { return std::sqrt(2.0 / (n - 1)) * std::exp(std::lgamma(n / 2.0) - std::lgamma((n - 1) / 2.0)); }

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s project grid [seeds [ref_photon_factor [ref_gather_rays [ref_seeds]]]]\n", argv[0]);
    return 2;
  }
  const std::string name = argv[1], grid = argv[2];
  const int seeds = argc > 3 ? std::stoi(argv[3]) : 20;
  const double ref_factor = argc > 4 ? std::stod(argv[4]) : 10.0;
  const int ref_rays = argc > 5 ? std::stoi(argv[5]) : 65536;
  const int ref_seeds = argc > 6 ? std::stoi(argv[6]) : 3;
  const fs::path tmp = fs::temp_directory_path() / ("dayphoton_gathered_honesty_" + name);
  const project::Project base =
      project::load_project((fs::path(DAYPHOTON_BENCH_SOURCE_DIR) / "projects" / name / "project.yaml").string());

  // The runs at the default accuracy target.
  std::vector<GridValues> runs;
  double cpu0 = bench::process_cpu_seconds();
  for (int seed = 1; seed <= seeds; ++seed) {
    project::Project p = base;
    p.simulation.seed = static_cast<unsigned long long>(seed);
    bench::set_accuracy_target(p, project::Simulation::Accuracy{}.target_df_relative_stderr_percent);
    runs.push_back(run_once(p, grid, tmp));
    std::printf("seed %2d:", seed);
    for (std::size_t s = 0; s < runs.back().df.size(); ++s)
      std::printf(" %.4f (%.4f)", runs.back().df[s], runs.back().se[s]);
    std::printf("  %s\n", runs.back().note.c_str());
    std::fflush(stdout);
  }
  const double run_cpu = bench::process_cpu_seconds() - cpu0;

  // The long reference: the grid alone, fixed photon counts.
  std::vector<GridValues> refs;
  cpu0 = bench::process_cpu_seconds();
  for (int r = 1; r <= ref_seeds; ++r) {
    project::Project p = base;
    p.simulation.accuracy.reset();
    p.simulation.photons_per_bin = static_cast<long long>(std::llround(double(p.simulation.photons_per_bin) * ref_factor));
    p.simulation.gather_rays = ref_rays;
    p.simulation.direct_samples_per_bin *= 10;
    p.simulation.seed = 1000ull + static_cast<unsigned long long>(r);
    std::vector<project::GridSpec> grids;
    for (const auto& g : p.sensors.grids)
      if (g.name == grid) grids.push_back(g);
    p.sensors.grids = grids;
    std::vector<project::PointsSpec> points;
    for (const auto& g : p.sensors.points)
      if (g.name == grid) points.push_back(g);
    p.sensors.points = points;
    refs.push_back(run_once(p, grid, tmp));
    std::printf("reference %d:", r);
    for (std::size_t s = 0; s < refs.back().df.size(); ++s)
      std::printf(" %.4f (%.4f)", refs.back().df[s], refs.back().se[s]);
    std::printf("\n");
    std::fflush(stdout);
  }
  const double ref_cpu = bench::process_cpu_seconds() - cpu0;

  if (seeds < 2 || ref_seeds < 1) {
    std::printf("(fewer than 2 seeds or no reference: no comparison; %.1f + %.1f CPU s)\n", run_cpu, ref_cpu);
    return 0;
  }
  const std::size_t m = runs[0].df.size();
  const int n = seeds;
  std::vector<double> mean(m, 0), sd(m, 0), sigma(m, 0), ref(m, 0), ref_se(m, 0), ref_sd(m, 0);
  for (std::size_t s = 0; s < m; ++s) {
    for (const GridValues& v : runs) mean[s] += v.df[s] / n, sigma[s] += v.se[s] / n;
    for (const GridValues& v : runs) sd[s] += (v.df[s] - mean[s]) * (v.df[s] - mean[s]);
    sd[s] = std::sqrt(sd[s] / (n - 1));
    for (const GridValues& v : refs) ref[s] += v.df[s] / ref_seeds, ref_se[s] += v.se[s] / ref_seeds;
    for (const GridValues& v : refs) ref_sd[s] += (v.df[s] - ref[s]) * (v.df[s] - ref[s]);
    ref_sd[s] = ref_seeds > 1 ? std::sqrt(ref_sd[s] / (ref_seeds - 1)) : 0.0;
    ref_se[s] /= std::sqrt(double(ref_seeds));
  }
  const double k = c4(n);
  std::printf("%s %s: %d seeds at the default target (%.1f CPU s), reference %d seeds x %.0f photons, %d rays "
              "(%.1f CPU s)\n",
              name.c_str(), grid.c_str(), n, run_cpu, ref_seeds, ref_factor, ref_rays, ref_cpu);
  std::printf("%6s %9s %9s %9s %7s %9s %9s %9s %8s %8s\n", "sensor", "mean DF", "sd DF", "mean se", "ratio",
              "ref DF", "ref se", "ref sd", "bias %", "z bias");
  double mean_ratio = 0;
  for (std::size_t s = 0; s < m; ++s) {
    const double ratio = sd[s] / (k * sigma[s]);
    mean_ratio += ratio / double(m);
    const double z = (mean[s] - ref[s]) / std::sqrt(sd[s] * sd[s] / n + ref_se[s] * ref_se[s]);
    std::printf("%6zu %9.4f %9.4f %9.4f %7.3f %9.4f %9.4f %9.4f %+8.3f %+8.2f\n", s, mean[s], sd[s], sigma[s], ratio,
                ref[s], ref_se[s], ref_sd[s], 100.0 * (mean[s] / ref[s] - 1.0), z);
  }
  double rho2 = 0;
  for (std::size_t s = 0; s < m; ++s)
    for (std::size_t t = 0; t < m; ++t) {
      double cov = 0;
      for (const GridValues& v : runs) cov += (v.df[s] - mean[s]) * (v.df[t] - mean[t]);
      const double rho = cov / ((n - 1) * sd[s] * sd[t]);
      rho2 += rho * rho;
    }
  rho2 /= double(m) * double(m);
  std::printf("mean ratio %.3f, its sd %.3f (mean rho^2 %.3f); one sensor's ratio sd %.3f\n", mean_ratio,
              std::sqrt(rho2 / (2.0 * (n - 1))), rho2, std::sqrt(1 - k * k) / k);
  return 0;
}
