// distributed_tracing_bench: the forward pass of projects/office (146 Tregenza sources and
// the ground, ground photons x16 as the pipeline does) as one dist::distribute_jobs job per
// source, each result the source's cache encoding (study/artifact_codec.h), delivered to rank
// 0 in source order. Run it alone and under `mpirun -np 2`, `-np 3 --oversubscribe` (with
// `--bind-to none`): rank 0 prints the wall time, every rank's CPU seconds, the bytes
// delivered and a digest of them, which must be the same for every rank count, and the
// longest-processing-time makespan predicted from the per-source cost estimates: by default
// the photon targets (equal, the ground 16); with `pilot`, the rays each source cast in a
// pilot pass of a twentieth of the photons that rank 0 traces first (its time is printed).
// The strong-scaling check of the tracing phase of docs/cluster.md; not a test.
// Usage: distributed_tracing_bench [photons_per_bin (default 20000) [threads per rank [pilot]]]
#include <sys/resource.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "dayphoton/dist/distribute_jobs.h"
#include "dayphoton/dist/job_assignment.h"
#include "dayphoton/dist/launcher.h"
#include "dayphoton/dist/mpi_session.h"
#include "dayphoton/dist/serial_communicator.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/port_emission.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/artifact_codec.h"
#include "dayphoton/study/plan_policy.h"

using namespace dayphoton;

namespace {

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

/// Rays cast per source by a pass of photons_per_source / 20 (rank 0 only), as cost estimates.
std::vector<double> pilot_costs(const engine::Scene& scene, const std::vector<engine::Material>& materials,
                                const engine::SourceSet& sources, const engine::ReceiverPlane& plane,
                                engine::TracingOptions o) {
  o.photons_per_source = std::max<std::size_t>(1, o.photons_per_source / 20);
  const engine::TracedPhotons t = engine::trace_photons(scene, materials, sources, {plane}, o);
  std::vector<double> costs;
  for (const engine::SourceTally& tally : t.tallies) costs.push_back(double(tally.rays));
  return costs;
}

int run(dist::Communicator& comm, std::size_t photons, bool pilot) {
  const project::Project proj =
      project::load_project(std::string(DAYPHOTON_BENCH_SOURCE_DIR) + "/projects/office/project.yaml");
  const SceneDescription d = project::build_scene_description(proj);
  const engine::Scene scene = engine::Scene::build(d);
  std::vector<engine::Material> materials;
  for (const MaterialSpec& m : d.materials) materials.push_back(engine::Material::from_spec(m));
  const engine::SourceSet sources = engine::SourceSet::sky_bins(sky::PatchBasis::tregenza());
  const engine::ReceiverPlane plane = engine::ReceiverPlane::from_grid(d.grids.at(0));
  const engine::PortEmitter emitter(scene, sources);
  engine::TracingOptions o;
  o.photons_per_source = photons;
  o.source_photon_factor.assign(sources.size(), 1.0);
  o.source_photon_factor[0] = study::GroundPhotonFactor;  // the run's policy (plan_policy.h)

  double pilot_wall = 0;
  std::vector<double> costs(o.source_photon_factor);
  if (pilot && comm.rank() == dist::RootRank) {
    const auto p0 = std::chrono::steady_clock::now();
    costs = pilot_costs(scene, materials, sources, plane, o);
    pilot_wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - p0).count();
  }

  dist::JobSet jobs;
  jobs.count = sources.size();
  jobs.cost_of = [&](std::size_t i) { return costs[i]; };
  jobs.compute = [&](std::size_t i) {
    const std::string bytes =
        study::encode_photons(engine::trace_source_photons(scene, materials, emitter, {plane}, o, i));
    dist::ByteBuffer out(bytes.size());
    std::memcpy(out.data(), bytes.data(), bytes.size());
    return out;
  };
  std::uint64_t digest = 0xcbf29ce484222325ull, delivered_bytes = 0;  // FNV-1a, 64 bit
  jobs.deliver = [&](std::size_t, dist::ByteBuffer b) {
    delivered_bytes += b.size();
    for (std::byte x : b) {
      digest ^= std::to_integer<unsigned>(x);
      digest *= 0x100000001b3ull;
    }
  };
  jobs.name_of = [](std::size_t i) { return "source " + std::to_string(i); };

  comm.barrier();
  const double cpu0 = cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  dist::distribute_jobs(comm, jobs);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = cpu_seconds() - cpu0;

  dist::ByteBuffer mine(sizeof cpu);
  std::memcpy(mine.data(), &cpu, sizeof cpu);
  const std::vector<dist::ByteBuffer> all = comm.gather_to_root(mine);
  if (comm.rank() != dist::RootRank) return 0;
  const dist::JobAssignment a = dist::assign_jobs(costs, comm.size());
  double total_cost = 0;
  for (double c : costs) total_cost += c;
  std::printf("forward pass of projects/office by source: %d ranks x %d threads, %zu photons per bin\n", comm.size(),
              int(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)), photons);
  std::printf("  wall %.2f s; CPU s by rank:", wall);
  double cpu_all = 0;
  for (const dist::ByteBuffer& b : all) {
    double c = 0;
    std::memcpy(&c, b.data(), sizeof c);
    cpu_all += c;
    std::printf(" %.2f", c);
  }
  std::printf(" (sum %.2f)\n", cpu_all);
  std::printf("  delivered %llu bytes, digest %016llx\n", static_cast<unsigned long long>(delivered_bytes),
              static_cast<unsigned long long>(digest));
  std::printf("  costs: %s%s; LPT makespan %.4g of %.4g: predicted speed-up over one rank %.2f\n",
              pilot ? "rays of a pilot pass" : "photon targets",
              pilot ? (", pilot " + std::to_string(pilot_wall) + " s wall").c_str() : "", a.makespan(), total_cost,
              total_cost / a.makespan());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t photons = argc > 1 ? std::stoul(argv[1]) : 20000;
  const bool pilot = argc > 3 && std::string(argv[3]) == "pilot";
  std::unique_ptr<tbb::global_control> limit;
  if (argc > 2)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, std::stoul(argv[2]));
  if (!dist::detect_launcher([](const char* name) { return std::getenv(name); })) {
    auto comm = dist::make_serial_communicator();
    return run(*comm, photons, pilot);
  }
  dist::MpiSession session(&argc, &argv);
  int code = 0;
  {
    auto comm = session.world();
    try {
      code = run(*comm, photons, pilot);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "rank %d: error: %s\n", comm->rank(), e.what());
      code = 1;
    }
  }
  return code;
}
