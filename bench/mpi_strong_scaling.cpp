// mpi_strong_scaling: the whole `dayphoton run` of a project under one process and under
// `mpirun -np 1, 2, 3` (one thread per rank, fresh caches), measured in one invocation, and
// the cost model of docs/cluster.md predicting those same runs from per-step costs measured
// here.
//
// 1. Measures the run in this process with one thread: every step's CPU seconds as it is
//    computed (an executor that times each step's compute, and keeps its cost estimate,
//    Step::cost), and the rest of the run (loading, scene, annual
//    multiply, metrics, files); then the CPU of a fully cached re-run (what every rank does
//    whatever it computes: the run outside its steps, and decoding every step's bytes).
// 2. Runs `dayphoton run -j 1` alone and under `mpirun -np 1, 2, 3 --bind-to none
//    --oversubscribe`, each into a fresh output folder and cache: wall seconds, the CPU
//    seconds of every rank (this program wraps each rank and reads its rusage), the load
//    average, and checks the results are byte-identical to the one-process run's (run.log,
//    timings.json and summary.json aside).
// 3. Predicts each run from the costs of 1, with the scheme the distributed executor follows
//    (study/distributed_executor.h): every rank does the cached run's work; a batch of photon
//    steps is shared out by dist::assign_jobs on the steps' cost estimates (for sky sources,
//    pilot passes, themselves shared out with equal costs first); a single step (a grid's coefficients, the direct sun, the sky
//    matrix) runs on rank 0 while the others wait asleep. Ranks share this machine's cores
//    (a rank runs at min(1, cores / busy ranks) of a core). Prints predicted against measured
//    CPU per rank and wall, with the error, the speed-ups, and the balance of the photon
//    batches assigned with equal costs, with the estimates and with the true (measured)
//    costs, at 2, 3 and more ranks (the effect of cost-weighted assignment).
//
// Usage: mpi_strong_scaling [photons_per_bin (default 10000) [PROJECT (default projects/office)]]
//   PROJECT's folder is copied (its regular files) and the copy changed: photons_per_bin,
//   no images, no report. Wall times need an idle machine: the load is printed beside them.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <numeric>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "dayphoton/dist/job_assignment.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/step_executor.h"
#include "dayphoton/study/study_runner.h"

using namespace dayphoton;
namespace fs = std::filesystem;

namespace {

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double load_average() {
  double l[1] = {0};
  return getloadavg(l, 1) == 1 ? l[0] : -1;
}

/// One computed step of the measured run.
struct StepCost {
  std::size_t batch = 0;         ///< the run_batch call it came from
  std::string name;              ///< kind and index
  double cpu = 0;                ///< seconds of compute()
  double estimate = 1;           ///< Step::cost() (1 without one)
  double estimate_cpu = 0;       ///< seconds of Step::cost()
  bool has_estimate = false;
};

/// The local executor's work, one step after the other on this thread, timed.
class TimingExecutor final : public study::StepExecutor {
 public:
  TimingExecutor(const study::ArtifactStore& store, bool force, std::vector<StepCost>& log, std::size_t& batches)
      : StepExecutor(store, force), m_log(log), m_batches(batches) {}

  std::vector<char> run_batch(const std::vector<study::Step>& steps, const StepDone& done) override {
    const std::size_t batch = m_batches++;
    std::vector<char> computed(steps.size(), 0);
    for (std::size_t i = 0; i < steps.size(); ++i) {
      if (!lookup(steps[i])) {
        StepCost c;
        c.batch = batch;
        c.name = std::string(study::step_kind_name(steps[i].kind)) + " " + std::to_string(steps[i].index);
        if (steps[i].cost) {
          const double e0 = cpu_seconds();
          c.estimate = steps[i].cost();
          c.estimate_cpu = cpu_seconds() - e0;
          c.has_estimate = true;
        }
        const double t0 = cpu_seconds();
        std::vector<std::string> bytes = steps[i].compute();
        c.cpu = cpu_seconds() - t0;
        store(steps[i], bytes);
        m_log.push_back(c);
        computed[i] = 1;
      }
      if (done) done(i, computed[i] != 0);
    }
    return computed;
  }

 private:
  std::vector<StepCost>& m_log;
  std::size_t& m_batches;
};

/// Runs the study in this process on one thread; returns its CPU seconds.
double run_here(const project::Project& proj, const fs::path& work, bool force, std::vector<StepCost>& log) {
  std::size_t batches = 0;
  std::ostringstream sink;
  study::Progress progress(sink, study::ProgressStyle::Quiet);
  study::RunSettings settings;
  settings.output_dir = (work / "results").string();
  settings.cache_dir = (work / "cache").string();
  settings.force = force;
  settings.make_executor = [&](const study::ArtifactStore& store, bool f) {
    return std::make_unique<TimingExecutor>(store, f, log, batches);
  };
  const double c0 = cpu_seconds();
  study::run_study(proj, settings, progress);
  return cpu_seconds() - c0;
}

/// Wall seconds of the run a ranks' processing-sharing machine of `cores` cores gives loads
/// that start together: each busy rank runs at min(1, cores / busy ranks) of a core.
double shared_makespan(std::vector<double> loads, double cores) {
  loads.erase(std::remove_if(loads.begin(), loads.end(), [](double l) { return l <= 0; }), loads.end());
  std::sort(loads.begin(), loads.end());
  double t = 0, done = 0;
  for (std::size_t i = 0; i < loads.size(); ++i) {
    const double busy = double(loads.size() - i);
    t += (loads[i] - done) / std::min(1.0, cores / busy);
    done = loads[i];
  }
  return t;
}

std::vector<double> loads_of(const std::vector<double>& true_costs, const std::vector<int>& owner, int ranks) {
  std::vector<double> loads(std::size_t(ranks), 0.0);
  for (std::size_t j = 0; j < true_costs.size(); ++j) loads[std::size_t(owner[j])] += true_costs[j];
  return loads;
}

struct Prediction {
  std::vector<double> cpu_of_rank;
  double wall = 0;
};

/// The model of the distributed run (file comment, 3).
Prediction predict(const std::vector<StepCost>& steps, double rest_cpu, double cached_cpu, int ranks, double cores,
                   const std::string& costs, double mpi_start_cpu = 0) {
  Prediction p;
  p.cpu_of_rank.assign(std::size_t(ranks), mpi_start_cpu);
  p.wall = shared_makespan(std::vector<double>(std::size_t(ranks), mpi_start_cpu), cores);
  std::map<std::size_t, std::vector<const StepCost*>> batches;
  for (const StepCost& s : steps) batches[s.batch].push_back(&s);
  if (ranks == 1) {  // one process: nothing sent; the run as measured
    double total = rest_cpu;
    for (const StepCost& s : steps) total += s.cpu;
    p.cpu_of_rank[0] += total;
    p.wall += shared_makespan({total}, cores);
    return p;
  }
  std::vector<double> everyone(std::size_t(ranks), cached_cpu);
  p.wall += shared_makespan(everyone, cores);
  for (double& c : p.cpu_of_rank) c += cached_cpu;
  for (const auto& [id, batch] : batches) {
    std::vector<double> truth, estimate, estimate_cpu;
    bool estimated = true;
    for (const StepCost* s : batch) {
      truth.push_back(s->cpu);
      estimate.push_back(s->estimate);
      estimate_cpu.push_back(s->estimate_cpu);
      estimated = estimated && s->has_estimate;
    }
    if (batch.size() == 1) {  // a single step: rank 0 computes it, the others wait
      p.cpu_of_rank[0] += truth[0];
      p.wall += shared_makespan({truth[0]}, cores);
      continue;
    }
    std::vector<double> by(truth.size(), 1.0);
    if (costs == "estimate" && estimated) {  // the estimates first, shared out with equal costs
      const std::vector<double> el = loads_of(estimate_cpu, dist::assign_jobs(by, ranks).owner_of_job, ranks);
      p.wall += shared_makespan(el, cores);
      for (int r = 0; r < ranks; ++r) p.cpu_of_rank[std::size_t(r)] += el[std::size_t(r)];
      by = estimate;
    } else if (costs == "true") {
      by = truth;
    }
    const std::vector<double> loads = loads_of(truth, dist::assign_jobs(by, ranks).owner_of_job, ranks);
    p.wall += shared_makespan(loads, cores);
    for (int r = 0; r < ranks; ++r) p.cpu_of_rank[std::size_t(r)] += loads[std::size_t(r)];
  }
  return p;
}

/// Balance of the batches of photon steps: sum of CPU over the largest rank's, summed over
/// the batches (ranks = a perfect balance).
double batch_balance(const std::vector<StepCost>& steps, int ranks, const std::string& costs) {
  std::map<std::size_t, std::vector<const StepCost*>> batches;
  for (const StepCost& s : steps) batches[s.batch].push_back(&s);
  double sum = 0, max = 0;
  for (const auto& [id, batch] : batches) {
    if (batch.size() < 2) continue;
    std::vector<double> truth, by;
    for (const StepCost* s : batch) {
      truth.push_back(s->cpu);
      by.push_back(costs == "estimate" ? s->estimate : costs == "true" ? s->cpu : 1.0);
    }
    const std::vector<double> loads = loads_of(truth, dist::assign_jobs(by, ranks).owner_of_job, ranks);
    sum += std::accumulate(loads.begin(), loads.end(), 0.0);
    max += *std::max_element(loads.begin(), loads.end());
  }
  return max > 0 ? sum / max : 0;
}

struct Measured {
  double wall = 0;
  std::vector<double> cpu_of_rank;
  double load_before = 0, load_after = 0;
  int status = -1;
};

/// This program as a rank's wrapper: runs argv[3...], writes its user+system seconds to
/// argv[2].<rank>.
int wrap(int argc, char** argv) {
  const pid_t child = fork();
  if (child == 0) {
    execv(argv[3], argv + 3);
    _exit(127);
  }
  int status = 0;
  rusage u{};
  wait4(child, &status, 0, &u);
  const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
  std::ofstream(std::string(argv[2]) + "." + (rank ? rank : "0"))
      << double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec)
      << "\n";
  (void)argc;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

Measured run_process(const std::vector<std::string>& command, const fs::path& cpu_prefix, int ranks) {
  Measured m;
  m.load_before = load_average();
  std::vector<char*> args;
  for (const std::string& a : command) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t child = fork();
  if (child == 0) {
    setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 0);
    setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 0);
    setenv("OMPI_MCA_btl", "self,vader", 0);
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    execv(args[0], args.data());
    _exit(127);
  }
  int status = 0;
  waitpid(child, &status, 0);
  m.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  m.load_after = load_average();
  m.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  for (int r = 0; r < ranks; ++r) {
    double c = -1;
    std::ifstream(cpu_prefix.string() + "." + std::to_string(r)) >> c;
    m.cpu_of_rank.push_back(c);
  }
  return m;
}

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Files of `b` that differ from `a`'s (run.log and timings.json, which hold its times, and summary.json, which names the run, aside).
int differing_files(const fs::path& a, const fs::path& b) {
  int n = 0;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(a)) {
    if (!e.is_regular_file()) continue;
    const fs::path rel = fs::relative(e.path(), a);
    if (rel == "run.log" || rel == "timings.json" || rel == "summary.json") continue;
    if (!fs::exists(b / rel) || read_file(e.path()) != read_file(b / rel)) ++n;
  }
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 3 && std::string(argv[1]) == "--wrap") return wrap(argc, argv);
  const std::string source_dir = DAYPHOTON_BENCH_SOURCE_DIR;
  const long photons = argc > 1 ? std::stol(argv[1]) : 10000;
  const fs::path project_dir = argc > 2 ? fs::path(argv[2]) : fs::path(source_dir) / "projects/office";
  const std::string dayphoton = DAYPHOTON_EXE;
  const std::string mpirun = DAYPHOTON_MPIEXEC;
  const double cores = double(std::max(1L, sysconf(_SC_NPROCESSORS_ONLN)));

  const fs::path work = fs::temp_directory_path() / ("dayphoton_mpi_strong_scaling_" + std::to_string(getpid()));
  fs::remove_all(work);
  fs::create_directories(work / "project");
  for (const fs::directory_entry& e : fs::directory_iterator(project_dir))
    if (e.is_regular_file()) fs::copy_file(e.path(), work / "project" / e.path().filename());
  const fs::path project_file = work / "project/project.yaml";
  std::string text = read_file(project_file);
  text = std::regex_replace(text, std::regex(R"((\n  photons_per_bin:) *\d+)"), "$1 " + std::to_string(photons));
  text = std::regex_replace(text, std::regex(R"((\n  (images|report):) *true)"), "$1 false");
  std::ofstream(project_file, std::ios::binary) << text;
  const project::Project proj = project::load_project(project_file.string());

  // 1. Per-step costs, one thread.
  std::vector<StepCost> steps, none;
  double total_cpu = 0, cached_cpu = 0;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    total_cpu = run_here(proj, work / "measure", true, steps);
    cached_cpu = run_here(proj, work / "measure", false, none);
  }
  double steps_cpu = 0, estimate_cpu = 0;
  for (const StepCost& s : steps) {
    steps_cpu += s.cpu;
    estimate_cpu += s.estimate_cpu;
  }
  const double rest_cpu = total_cpu - steps_cpu - estimate_cpu;
  std::size_t batch_steps = 0;
  double batch_cpu = 0;
  {
    std::map<std::size_t, int> n;
    for (const StepCost& s : steps) ++n[s.batch];
    for (const StepCost& s : steps)
      if (n[s.batch] > 1) {
        ++batch_steps;
        batch_cpu += s.cpu;
      }
  }
  std::printf("project %s at %ld photons per bin, this machine %.0f cores\n", project_dir.filename().c_str(), photons,
              cores);
  std::printf("measured in one process, one thread: %.2f s CPU: %zu steps computed %.2f s (%zu in batches: %.2f s), "
              "their cost estimates %.2f s, the rest %.2f s; a fully cached re-run %.2f s\n",
              total_cpu, steps.size(), steps_cpu, batch_steps, batch_cpu, estimate_cpu, rest_cpu, cached_cpu);

  {
    std::map<std::size_t, std::vector<const StepCost*>> batches;
    for (const StepCost& s : steps) batches[s.batch].push_back(&s);
    for (auto& [id, batch] : batches) {
      if (batch.size() < 2) continue;
      std::sort(batch.begin(), batch.end(), [](const StepCost* a, const StepCost* b) { return a->cpu > b->cpu; });
      double sum = 0;
      for (const StepCost* s : batch) sum += s->cpu;
      std::printf("  batch of %zu %s...: %.3f s CPU, mean %.4f s; largest:", batch.size(), batch[0]->name.c_str(), sum,
                  sum / double(batch.size()));
      for (std::size_t i = 0; i < std::min<std::size_t>(6, batch.size()); ++i)
        std::printf(" %s %.3f s (estimate %.3g)%s", batch[i]->name.c_str(), batch[i]->cpu, batch[i]->estimate,
                    i + 1 < std::min<std::size_t>(6, batch.size()) ? "," : "\n");
    }
  }
  const bool model_only = argc > 3 && std::string(argv[3]) == "model";

  // 2. The runs, fresh caches, one thread per rank.
  std::printf("\n%-14s %8s %8s %8s  %-26s %-26s %s\n", "run", "wall s", "pred s", "error", "CPU s by rank",
              "predicted", "load before/after, identical");
  const char* self = "/proc/self/exe";
  char self_path[4096] = {0};
  const ssize_t n_self = readlink(self, self_path, sizeof self_path - 1);
  const std::string me = n_self > 0 ? std::string(self_path, std::size_t(n_self)) : std::string(argv[0]);
  double serial_wall = 0, np1_wall = 0;
  // Each rank's CPU for starting and ending MPI (`dayphoton --version` under mpirun -np 2):
  // a measured input of the model.
  double mpi_start_cpu = 0;
  if (!model_only && !mpirun.empty()) {
    const Measured start = run_process({mpirun, "-np", "2", "--bind-to", "none", "--oversubscribe", me, "--wrap",
                                        (work / "start").string(), dayphoton, "--version"},
                                       work / "start", 2);
    mpi_start_cpu = std::max(0.0, 0.5 * (start.cpu_of_rank[0] + start.cpu_of_rank[1]));
    std::printf("%-14s MPI start and end: %.2f s of CPU per rank\n", "", mpi_start_cpu);
  }
  for (int np = 0; np <= 3 && !model_only; ++np) {
    if (np > 0 && mpirun.empty()) break;
    const int ranks = std::max(np, 1);
    const fs::path run = work / (np == 0 ? std::string("alone") : "np" + std::to_string(np));
    std::vector<std::string> command;
    if (np > 0) command = {mpirun, "-np", std::to_string(np), "--bind-to", "none", "--oversubscribe"};
    for (const std::string& a : {me, std::string("--wrap"), (run / "cpu").string(), dayphoton, std::string("run"),
                                 project_file.string(), std::string("-o"), (run / "results").string(),
                                 std::string("--cache"), (run / "cache").string(), std::string("-j"),
                                 std::string("1"), std::string("--quiet")})
      command.push_back(a);
    fs::create_directories(run);
    const Measured m = run_process(command, run / "cpu", ranks);
    const Prediction p = predict(steps, rest_cpu, cached_cpu, ranks, cores, "estimate", np > 0 ? mpi_start_cpu : 0);
    std::string cpu, pcpu;
    char buf[64];
    for (double c : m.cpu_of_rank) cpu += (std::snprintf(buf, sizeof buf, "%.2f ", c), buf);
    for (double c : p.cpu_of_rank) pcpu += (std::snprintf(buf, sizeof buf, "%.2f ", c), buf);
    const int differing = np == 0 ? 0 : differing_files(work / "alone/results", run / "results");
    std::printf("%-14s %8.2f %8.2f %7.0f%%  %-26s %-26s %.1f/%.1f, %s\n",
                np == 0 ? "alone" : ("mpirun -np " + std::to_string(np)).c_str(), m.wall, p.wall,
                100 * (p.wall - m.wall) / m.wall, cpu.c_str(), pcpu.c_str(), m.load_before, m.load_after,
                m.status != 0 ? ("FAILED, exit " + std::to_string(m.status)).c_str()
                : differing == 0 ? "byte-identical"
                                 : (std::to_string(differing) + " files DIFFER").c_str());
    if (np == 0) serial_wall = m.wall;
    if (np == 1) np1_wall = m.wall;
    if (np > 1)
      std::printf("%-14s speed-up %.2f over -np 1, %.2f over one process (predicted %.2f)\n", "",
                  np1_wall / m.wall, serial_wall / m.wall,
                  predict(steps, rest_cpu, cached_cpu, 1, cores, "estimate", mpi_start_cpu).wall / p.wall);
  }

  // 3. The effect of the cost estimates on the photon batches.
  std::printf("\nphoton batches, CPU balance (sum over ranks / largest rank; ranks = perfect):\n");
  std::printf("%6s %12s %12s %12s   %s\n", "ranks", "equal costs", "estimates", "true costs",
              "predicted wall s here (2, 3) or with a core per rank: equal costs / estimates");
  for (int r : {2, 3, 8, 16, 64}) {
    const double c = r <= 3 ? cores : double(r);
    std::printf("%6d %12.3f %12.3f %12.3f   %.2f / %.2f\n", r, batch_balance(steps, r, "equal"),
                batch_balance(steps, r, "estimate"), batch_balance(steps, r, "true"),
                predict(steps, rest_cpu, cached_cpu, r, c, "equal").wall,
                predict(steps, rest_cpu, cached_cpu, r, c, "estimate").wall);
  }
  fs::remove_all(work);
  return 0;
}
