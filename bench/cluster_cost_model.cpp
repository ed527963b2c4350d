// cluster_cost_model: what a run would cost on an MPI cluster, from costs measured here.
//
// 1. Runs the whole study of projects/office (`run --force`, no images or report) and reads off
//    each step's CPU seconds (process user + system time at the end of each step, so the
//    figures hold on a machine shared with other work, where wall times do not), the number of
//    sources, sun bins, photons and sensors, the bytes of every cached artefact (.bin files of
//    the cache folder, docs/cache.md) and of the results.
// 2. Measures this machine's file write bandwidth (256 MiB, fsync'd).
// 3. Turns them into unit costs (CPU seconds per traced photon, per sensor and source
//    estimate, per sensor for the direct sun and the annual multiply; bytes per photon, per
//    coefficient, per sensor of results) and predicts the wall time at 1, 64 and 512 ranks
//    (one core of this machine each) for the 10,000-sensor floor of
//    bench/scenes/open_plan (its photons per bin) and for a tower of 100 such floors, one
//    million sensors. Prints the inputs, each phase and the phase that dominates.
//
// The scheme modelled (docs/cluster.md "Cost model"): one job per (floor, source) traced where
// it is assigned (longest processing time first, dist::assign_jobs, the assignment the
// distributed run uses); the estimates, direct sun and annual multiply split by sensor
// blocks, each rank receiving its floor's photon maps; every result sent to rank 0, which
// writes the outputs alone. Floors are optically independent (opaque slabs, nothing outside).
// The network bandwidth is an assumption (no cluster here), printed for two networks.
//
// Usage: cluster_cost_model [threads [PROJECT [photons_per_bin]]]
//   PROJECT (default projects/office/project.yaml) is the run measured, optionally with fewer
//   photons per bin (the tracing cost is per photon; the estimates' cost hardly depends on it).
#include <fcntl.h>
#include <sys/resource.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <regex>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

#include "dayphoton/dist/job_assignment.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/study_runner.h"

using namespace dayphoton;
namespace fs = std::filesystem;

namespace {

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

/// Keeps the progress lines and the process CPU time at each "NAME: done in" line, so that the
/// CPU seconds of a step are the difference between its end and the previous step's end.
class StepClock : public std::streambuf {
 public:
  std::map<std::string, double> cpu_of_step;
  std::vector<std::string> lines;

 protected:
  int overflow(int c) override {
    if (c == '\n') {
      lines.push_back(m_line);
      const auto at = m_line.find(": done in ");
      if (at != std::string::npos) {
        const double now = cpu_seconds();
        cpu_of_step[m_line.substr(0, at)] += now - m_last;
        m_last = now;
      }
      m_line.clear();
    } else if (c != EOF) {
      m_line.push_back(static_cast<char>(c));
    }
    return c;
  }

 private:
  std::string m_line;
  double m_last = cpu_seconds();
};

std::uintmax_t folder_bytes(const fs::path& folder) {
  std::uintmax_t total = 0;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(folder))
    if (e.is_regular_file()) total += e.file_size();
  return total;
}

/// Bytes and count of the cache's artefacts by kind: the file name without its "-<hash>.bin".
std::map<std::string, std::pair<double, int>> artefacts_by_kind(const fs::path& cache) {
  std::map<std::string, std::pair<double, int>> out;
  for (const fs::directory_entry& e : fs::directory_iterator(cache)) {
    const std::string name = e.path().filename().string();
    if (!e.is_regular_file() || e.path().extension() != ".bin") continue;
    const std::string kind = name.substr(0, name.rfind('-'));
    out[kind].first += double(e.file_size());
    out[kind].second += 1;
  }
  return out;
}

/// Bytes per second of writing 256 MiB to a new file in `folder` and fsync'ing it.
double write_bandwidth(const fs::path& folder) {
  const fs::path file = folder / "bandwidth.tmp";
  const std::vector<char> block(std::size_t{4} << 20, 'x');
  const int blocks = 64;
  const auto t0 = std::chrono::steady_clock::now();
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) return 0;
  for (int i = 0; i < blocks; ++i)
    if (::write(fd, block.data(), block.size()) != static_cast<ssize_t>(block.size())) break;
  ::fsync(fd);
  ::close(fd);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  fs::remove(file);
  return double(blocks) * double(block.size()) / s;
}

double sum_of(const std::map<std::string, double>& m, const std::string& prefix) {
  double s = 0;
  for (const auto& [name, v] : m)
    if (name.rfind(prefix, 0) == 0) s += v;
  return s;
}

struct Target {
  std::string name;
  double floors;
  double sensors_per_floor;
};

}  // namespace

int main(int argc, char** argv) {
  std::unique_ptr<tbb::global_control> limit;
  if (argc > 1)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, std::stoul(argv[1]));
  const std::string source_dir = DAYPHOTON_BENCH_SOURCE_DIR;
  const std::string measured_path = argc > 2 ? argv[2] : source_dir + "/projects/office/project.yaml";
  project::Project office = project::load_project(measured_path);
  if (argc > 3) office.simulation.photons_per_bin = std::stoll(argv[3]);
  const project::Project floor = project::load_project(source_dir + "/bench/scenes/open_plan/project.yaml");

  const fs::path work = fs::temp_directory_path() / "dayphoton_cluster_cost_model";
  fs::remove_all(work);
  fs::create_directories(work);
  const double disk_bytes_per_s = write_bandwidth(work);

  StepClock clock;
  std::ostream log(&clock);
  study::Progress progress(log, study::ProgressStyle::Lines, 1e9);
  study::RunSettings settings;
  settings.output_dir = (work / "results").string();
  settings.cache_dir = (work / "cache").string();
  settings.force = true;
  const double cpu0 = cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  const study::RunReport report = study::run_study(office, settings, progress);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = cpu_seconds() - cpu0;

  // Counts of the measured run.
  double sensors = 0;
  for (const study::GridReport& g : report.grids) sensors += double(g.sensors);
  double sky_sources = 0, sun_bins = 0, sun_photons_per_bin = 0;
  for (const study::Progress::StepTime& s : progress.steps()) {
    if (s.name == "photons") sky_sources = double(s.work);
    if (s.name == "sun photons") sun_bins = double(s.work);
  }
  const std::regex sun_note(R"(send light through the ports, (\d+) photons each)");
  for (const std::string& line : clock.lines) {
    std::smatch m;
    if (std::regex_search(line, m, sun_note)) sun_photons_per_bin = std::stod(m[1]);
  }
  const double photons_per_bin = double(office.simulation.photons_per_bin);
  const double sun_fraction = sun_photons_per_bin / photons_per_bin;
  if (sensors <= 0 || sky_sources <= 0 || sun_bins <= 0 || sun_photons_per_bin <= 0) {
    std::fprintf(stderr, "cluster_cost_model: the run did not report its sources, sun bins or sensors\n");
    return 1;
  }

  const auto& c = clock.cpu_of_step;
  const auto artefacts = artefacts_by_kind(settings.cache_dir);
  auto bytes_of = [&](const std::string& kind) {
    auto it = artefacts.find(kind);
    return it == artefacts.end() ? 0.0 : it->second.first;
  };
  const double results_bytes = double(folder_bytes(settings.output_dir));

  // Unit costs: CPU seconds on one core of this machine, bytes.
  const double c_sky_photon = c.at("photons") / (sky_sources * photons_per_bin);
  const double c_sun_photon = c.at("sun photons") / (sun_bins * sun_photons_per_bin);
  const double c_sky_estimate = sum_of(c, "coefficients") / (sensors * sky_sources);
  const double c_sun_estimate = sum_of(c, "sun coefficients") / (sensors * sun_bins);
  const double c_direct_sensor = sum_of(c, "direct sun") / sensors;
  const double c_annual_sensor = sum_of(c, "annual") / sensors;
  const double c_setup = sum_of(c, "scene") + sum_of(c, "sky matrix");
  // Photon maps: bytes per source at this photon count (sources no port sees store nothing, so
  // a per-photon figure would mislead); scaled by the photon count of the target.
  const double b_sky_map = bytes_of("photons") / sky_sources;
  const double b_sun_map = bytes_of("sun-photons") / sun_bins;
  const double b_results_sensor = results_bytes / sensors;

  std::printf("measured on %s (%d threads): %.0f s wall, %.1f s CPU\n",
              fs::path(measured_path).parent_path().filename().c_str(),
              int(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)), wall, cpu);
  std::printf("  %.0f sensors, %.0f sky sources x %.0f photons, %.0f sun bins x %.0f photons\n", sensors, sky_sources,
              photons_per_bin, sun_bins, sun_photons_per_bin);
  std::printf("  CPU seconds by step:\n");
  for (const auto& [name, s] : c) std::printf("    %-32s %8.2f\n", name.c_str(), s);
  std::printf("  cached artefacts:\n");
  for (const auto& [kind, v] : artefacts)
    std::printf("    %-20s %5d files %10.0f bytes (%.0f per file)\n", kind.c_str(), v.second, v.first,
                v.first / v.second);
  std::printf("  results folder %.0f bytes\n", results_bytes);
  std::printf("unit costs (one core of this machine):\n");
  std::printf("  tracing           %.3g us per sky photon, %.3g us per sun photon\n", 1e6 * c_sky_photon,
              1e6 * c_sun_photon);
  std::printf("  estimates         %.3g us per sensor and sky source, %.3g us per sensor and sun bin\n",
              1e6 * c_sky_estimate, 1e6 * c_sun_estimate);
  std::printf("  direct sun        %.3g ms per sensor (this climate's sun hours)\n", 1e3 * c_direct_sensor);
  std::printf("  annual multiply   %.3g ms per sensor (8760 hours)\n", 1e3 * c_annual_sensor);
  std::printf("  set-up            %.3g s per rank (scene, sky matrix)\n", c_setup);
  std::printf("  photon maps       %.0f bytes per sky source, %.0f per sun bin (cache, at these photon counts)\n",
              b_sky_map, b_sun_map);
  std::printf("  results           %.0f bytes per sensor, written by rank 0\n", b_results_sensor);
  std::printf("  file writing      %.0f MB/s (256 MiB, fsync, this machine)\n", disk_bytes_per_s / 1e6);

  // The floor of bench/scenes/open_plan at its own photon count, and a tower of 100 of them.
  const double floor_ppb = double(floor.simulation.photons_per_bin);
  const double floor_sun_ppb = floor_ppb * sun_fraction;
  const std::vector<Target> targets = {{"open-plan floor (10,000 sensors)", 1, 10000},
                                       {"tower of 100 floors (1,000,000 sensors)", 100, 10000}};
  // Assumed (no cluster here): a 100 Gb/s InfiniBand link per rank and a parallel file system
  // taking 2 GB/s from one client, or 10 Gb/s Ethernet and a disk as fast as this machine's.
  struct Cluster {
    std::string name;
    double network_bytes_per_s, storage_bytes_per_s;
  };
  const std::vector<Cluster> clusters = {
      {"100 Gb/s network, 2 GB/s parallel file system (assumed)", 12.5e9, 2e9},
      {"10 Gb/s network (assumed), this machine's disk (measured)", 1.25e9, disk_bytes_per_s}};
  std::printf(
      "\npredictions (ranks of one core of this machine; sources per floor %.0f sky x %.0f photons, "
      "%.0f sun bins x %.0f photons):\n",
      sky_sources, floor_ppb, sun_bins, floor_sun_ppb);
  for (const Target& t : targets) {
    const double n = t.floors * t.sensors_per_floor;
    const double floor_map_bytes = (sky_sources * b_sky_map + sun_bins * b_sun_map) * (floor_ppb / photons_per_bin);
    // One tracing job per (floor, source).
    std::vector<double> trace_jobs;
    for (int f = 0; f < int(t.floors); ++f) {
      for (int s = 0; s < int(sky_sources); ++s) trace_jobs.push_back(c_sky_photon * floor_ppb);
      for (int s = 0; s < int(sun_bins); ++s) trace_jobs.push_back(c_sun_photon * floor_sun_ppb);
    }
    double trace_work = 0;
    for (double j : trace_jobs) trace_work += j;
    const double estimate_work = n * (sky_sources * c_sky_estimate + sun_bins * c_sun_estimate);
    const double direct_work = n * c_direct_sensor;
    const double annual_work = n * c_annual_sensor;
    const double result_bytes = n * b_results_sensor;
    std::printf("\n%s: %.3g photons traced, %.3g CPU s in all, photon maps %.3g GB per floor, results %.3g GB\n",
                t.name.c_str(), t.floors * (sky_sources * floor_ppb + sun_bins * floor_sun_ppb),
                trace_work + estimate_work + direct_work + annual_work + c_setup, floor_map_bytes / 1e9,
                result_bytes / 1e9);
    for (const Cluster& cluster : clusters) {
      const double net = cluster.network_bytes_per_s;
      std::printf("  %s\n", cluster.name.c_str());
      std::printf("    %5s %9s %9s %9s %9s %9s %9s %9s %9s  %s\n", "ranks", "set-up", "tracing", "maps in", "estimates",
                  "sun+annual", "to rank 0", "writing", "total s", "dominated by");
      for (int ranks : {1, 64, 512}) {
        const dist::JobAssignment a = dist::assign_jobs(trace_jobs, ranks);
        const double p = ranks;
        const double floors_per_rank = std::max(1.0, t.floors / p);
        const double phases[] = {
            c_setup * floors_per_rank,
            a.makespan(),
            ranks > 1 ? floors_per_rank * floor_map_bytes / net : 0.0,
            estimate_work / p,
            (direct_work + annual_work) / p,
            ranks > 1 ? result_bytes / net : 0.0,
            result_bytes / cluster.storage_bytes_per_s,
        };
        const char* names[] = {"set-up", "tracing", "maps in", "estimates", "sun+annual", "to rank 0", "writing"};
        double total = 0;
        int top = 0;
        for (int i = 0; i < 7; ++i) {
          total += phases[i];
          if (phases[i] > phases[top]) top = i;
        }
        std::printf("    %5d %9.3g %9.3g %9.3g %9.3g %9.3g %9.3g %9.3g %9.3g  %s (%.0f %%)\n", ranks, phases[0],
                    phases[1], phases[2], phases[3], phases[4], phases[5], phases[6], total, names[top],
                    100 * phases[top] / total);
      }
    }
  }
  fs::remove_all(work);
  return 0;
}
