// examples_accuracy_bench: is every example project within its accuracy target? Each project
// of projects/ runs as a daylight-factor study twice: at the accuracy target (default 1 %
// relative standard error of DF at the 95th-percentile sensor, simulation.accuracy) and at a
// target sqrt(10) times tighter, which traces about 10 times the photons, with 10 times the
// direct component's shadow rays and final-gather rays (without them a project whose rounds
// stop on the direct component's floor would stop the reference there too, after its pilot)
// and another seed (the reference). Per
// sensor the relative difference e = (DF - DF_ref) / DF_ref measures the run's whole error:
// its noise, and the change of the density estimate's bias with the photon count, which the
// reported standard error does not contain. The target is met if the RMS of e over the
// sensors is at most sqrt(target^2 + r^2), r the RMS over the sensors of the reference's own
// reported relative standard error: when every sensor's standard error is at most the target,
// the noise of both runs gives an RMS of e at most that, so a larger RMS is bias or an
// understated standard error. (r is about target / sqrt(10) where the reference meets its
// tighter target; a reference stopped early, e.g. a gathered grid on the gather ray limit,
// states its larger error, which the bound then contains.) On a grid of few sensors the RMS
// is itself noisy (3 sensors at the target exceed the bound with a probability of about 0.4,
// P(chi-square(3) > 3) = 0.39), so there the verdict is one draw. Also printed:
// the 95th percentile of |e|, and the share of sensors whose difference lies within 2 combined
// standard errors (95 % if the reported errors are honest and the bias is small). A grid
// estimated by final gather that ends above the target ("not reachable by photons": the
// rounds trace no photons for it) fails whatever e; a grid that stopped above the target on a
// budget or the direct component's floor is also tested against its reported 95th percentile
// ("within its reported p95"). Exit status 1 when a grid fails or a project errs.
//
// The DF-only study traces no sun; the target governs the sky sources only (docs/photon-
// tracing.md, "Accuracy target"). Every grid of the project's base case is compared (one row
// each, with the grid's status: a grid estimated by final gather above the target is "not
// reachable by photons", which the rounds do not chase). Variants are not run (the bench
// measures the estimator on each scene once; a variant is another scene of the same kind):
// the bench says so for each project that has them; a project without sensors (render only)
// is skipped with its reason. Wall and process CPU seconds (user + sys, all threads) are
// printed: with 2 shared cores wall times vary with the load, CPU times much less.
// Usage: examples_accuracy_bench [target_percent|default [project_name...]]; `default` (or no
// argument): each project's own simulation.accuracy target, else the default target (the
// final preset, 1 %) that applies to a project that gives no photon counts.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/results_model.h"
#include "df_only_run.h"

using namespace dayphoton;
namespace fs = std::filesystem;

namespace {

constexpr double ReferencePhotonFactor = 10.0;  ///< the reference traces ~10x the photons
/// The reference's seed is the project's plus this: its photons are independent of the run's.
/// (With the same seed the reference's attempts would extend the run's own, and the
/// difference would lack the run's share of the noise.)
constexpr unsigned long long ReferenceSeedOffset = 1000;

/// One grid of a DF-only run.
struct GridRun {
  std::string name;
  std::vector<double> df_percent, stderr_percent;
  double reached_percent = 0;
  std::string status;
};

struct DfRun {
  std::vector<GridRun> grids;  ///< of the base case
  double seconds = 0, cpu_seconds = 0;
  std::uint64_t photons = 0;
  std::size_t rounds = 0;
  std::string stop_reason;
};

/// One DF-only run of `proj` (base case) at `target_percent`; the values of every grid.
DfRun run_at(project::Project proj, double target_percent, int factor, const fs::path& out,
             const fs::path& cache) {
  if (factor > 1) {
    proj.simulation.direct_samples_per_bin *= factor;
    proj.simulation.gather_rays *= factor;
    proj.simulation.seed += ReferenceSeedOffset;
  }
  bench::set_accuracy_target(proj, target_percent);
  const bench::DfOnlyRun run = bench::run_df_only(proj, out, cache);
  DfRun r;
  r.seconds = run.seconds;
  r.cpu_seconds = run.cpu_seconds;
  for (const study::GridResult& grid : run.model.cases.at(0).grids) {
    bench::GridDf values = bench::read_grid_df(out, grid);
    GridRun gr;
    gr.name = grid.name;
    gr.df_percent = std::move(values.df_percent);
    gr.stderr_percent = std::move(values.stderr_percent);
    if (grid.daylight_factor && grid.daylight_factor->accuracy) {
      const auto& acc = *grid.daylight_factor->accuracy;
      r.photons = acc.photons;
      r.rounds = acc.rounds;
      r.stop_reason = acc.stop_reason;
      gr.reached_percent = acc.reached_percent;
      gr.status = acc.status;
    }
    r.grids.push_back(std::move(gr));
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
  const bool own_target = argc < 2 || std::string(argv[1]) == "default";
  const double given_target = own_target ? 0.0 : std::stod(argv[1]);
  std::vector<std::string> names;
  for (int i = 2; i < argc; ++i) names.push_back(argv[i]);
  const fs::path projects = fs::path(DAYPHOTON_BENCH_SOURCE_DIR) / "projects";
  if (names.empty())
    for (const fs::directory_entry& e : fs::directory_iterator(projects))
      if (fs::exists(e.path() / "project.yaml")) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  std::printf("per grid of each project's base case: the run at the target (p95 sensor relative standard error of "
              "DF) against a run at a target sqrt(%.0f) tighter; pass: RMS relative difference <= sqrt(target^2 + "
              "ref se^2), ref se the RMS of the reference's own relative standard error\n",
              ReferencePhotonFactor);
  std::printf("%-16s %-12s %7s %7s %8s %8s %8s %8s %9s %9s %7s %7s %8s %8s %7s %7s %s\n", "project", "grid",
              "sensors", "target", "run s", "run cpu", "ref s", "ref cpu", "photons", "ref phot", "reached", "ref se",
              "rms e %", "p95 e %", "in 2se", "bound", "verdict (status; stop)");
  int failed = 0, compared = 0;
  for (const std::string& name : names) {
    const fs::path out = fs::temp_directory_path() / ("dayphoton_accuracy_bench_" + name);
    const fs::path cache = fs::temp_directory_path() / ("dayphoton_accuracy_bench_cache_" + name);
    try {
      const project::Project proj = project::load_project((projects / name / "project.yaml").string());
      if (!proj.variants.empty()) {
        std::string list;
        for (const project::VariantSpec& v : proj.variants) list += (list.empty() ? "" : ", ") + v.name;
        std::printf("%-16s base case only; variants not run (%s): the bench measures each scene kind once\n",
                    name.c_str(), list.c_str());
      }
      const double target_percent =
          own_target ? (proj.simulation.accuracy ? proj.simulation.accuracy->target_df_relative_stderr_percent
                                                 : project::Simulation::Accuracy{}.target_df_relative_stderr_percent)
                     : given_target;
      const DfRun run = run_at(proj, target_percent, 1, out / "run", cache);
      if (run.grids.empty()) {
        std::printf("%-16s skipped: the base case has no sensor grid (a render-only project has no DF to compare)\n",
                    name.c_str());
        fs::remove_all(out);
        fs::remove_all(cache);
        continue;
      }
      const DfRun ref = run_at(proj, target_percent / std::sqrt(ReferencePhotonFactor), int(ReferencePhotonFactor),
                               out / "ref", cache);
      for (std::size_t g = 0; g < run.grids.size() && g < ref.grids.size(); ++g) {
        const GridRun& a = run.grids[g];
        const GridRun& b = ref.grids[g];
        std::vector<double> e_percent, abs_e;
        std::size_t within = 0;
        double ref_relative_variance = 0;  // sum over the sensors of the reference's (se / DF)^2, %^2
        for (std::size_t s = 0; s < a.df_percent.size() && s < b.df_percent.size(); ++s) {
          if (!(b.df_percent[s] > 0)) continue;
          const double e = (a.df_percent[s] - b.df_percent[s]) / b.df_percent[s];
          e_percent.push_back(100.0 * e);
          abs_e.push_back(100.0 * std::abs(e));
          const double se = std::hypot(a.stderr_percent[s], b.stderr_percent[s]);
          if (std::abs(a.df_percent[s] - b.df_percent[s]) <= 2.0 * se) ++within;
          const double ref_relative_percent = 100.0 * b.stderr_percent[s] / b.df_percent[s];
          ref_relative_variance += ref_relative_percent * ref_relative_percent;
        }
        double sum2 = 0;
        for (double e : e_percent) sum2 += e * e;
        const double rms = e_percent.empty() ? 0 : std::sqrt(sum2 / double(e_percent.size()));
        // The reference's own noise, as it reports it: the RMS of its relative standard error.
        const double ref_se_percent = e_percent.empty() ? 0 : std::sqrt(ref_relative_variance / double(e_percent.size()));
        const double bound = std::hypot(target_percent, ref_se_percent);
        // A gathered grid the rounds do not chase: its error is partly the gather rays' and
        // partly the photons' of the pilot, which the reference does not multiply (it traces no
        // more photons for such a grid); a grid above the target this way fails, whatever e.
        const bool gathered_above = a.status == "not reachable by photons";
        const bool pass = rms <= bound && !gathered_above;
        ++compared;
        if (!pass) ++failed;
        // Beside the verdict: is the run within the accuracy it reports (its reached p95, when a
        // budget or a floor stopped it above the target)?
        const double reported_bound = std::hypot(std::max(target_percent, a.reached_percent), ref_se_percent);
        const std::string verdict = std::string(pass ? "within target" : "NOT within target") +
                                    (gathered_above ? ": gathered grid above the target" : "") +
                                    (pass || a.reached_percent <= target_percent ? ""
                                     : rms <= reported_bound ? ", within its reported p95"
                                                             : ", NOT within its reported p95") +
                                    " (" + a.status +
                                    "; " + run.stop_reason + " after " + std::to_string(run.rounds) +
                                    " rounds; ref " + ref.stop_reason + ")";
        std::printf("%-16s %-12s %7zu %6.2f%% %8.1f %8.1f %8.1f %8.1f %9llu %9llu %6.2f%% %6.2f%% %8.2f %8.2f %6.0f%% "
                    "%6.2f%% %s\n",
                    name.c_str(), a.name.c_str(), a.df_percent.size(), target_percent, run.seconds, run.cpu_seconds,
                    ref.seconds, ref.cpu_seconds, static_cast<unsigned long long>(run.photons),
                    static_cast<unsigned long long>(ref.photons), a.reached_percent, ref_se_percent, rms,
                    percentile(abs_e, 0.95),
                    e_percent.empty() ? 0.0 : 100.0 * double(within) / double(e_percent.size()), bound,
                    verdict.c_str());
      }
    } catch (const std::exception& e) {
      ++failed;
      std::printf("%-16s error: %s\n", name.c_str(), e.what());
    }
    std::fflush(stdout);
    fs::remove_all(out);
    fs::remove_all(cache);
  }
  std::printf("%zu projects, %d grids compared, %d not within the target or in error\n", names.size(), compared,
              failed);
  return failed == 0 ? 0 : 1;
}
