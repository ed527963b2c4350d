// split_source_bench: ONE big source traced in attempt ranges over the ranks
// (study/split_photon_steps.h, docs/cluster.md "Big sources in attempt ranges"): the ground bin
// of projects/office (GroundPhotonFactor x photons_per_bin photons, as the run traces it) as a
// photon step with ranges, run through run_split_photon_steps with the policy's smallest range
// (MinSplitRangeAttempts). Alone (no launcher) the step is traced whole by
// engine::trace_source_photons; under `mpirun -np N --bind-to none` in ranges. Rank 0 prints the
// wall time, every rank's CPU seconds, the bytes of the step's artefact and their digest, which
// must be the same for every rank count. Not a test.
// Usage: split_source_bench [photons_per_bin (default 20000) [threads per rank]]
#include <sys/resource.h>
#include <tbb/global_control.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "dayphoton/dist/launcher.h"
#include "dayphoton/dist/mpi_session.h"
#include "dayphoton/dist/serial_communicator.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/port_emission.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/artifact_codec.h"
#include "dayphoton/study/photon_range_step.h"
#include "dayphoton/study/plan_policy.h"
#include "dayphoton/study/split_photon_steps.h"

using namespace dayphoton;

namespace {

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

int run(dist::Communicator& comm, std::size_t photons) {
  const project::Project proj =
      project::load_project(std::string(DAYPHOTON_BENCH_SOURCE_DIR) + "/projects/office/project.yaml");
  const SceneDescription d = project::build_scene_description(proj);
  const engine::Scene scene = engine::Scene::build(d);
  std::vector<engine::Material> materials;
  for (const MaterialSpec& m : d.materials) materials.push_back(engine::Material::from_spec(m));
  const engine::SourceSet sources = engine::SourceSet::sky_bins(sky::PatchBasis::tregenza());
  const std::vector<engine::ReceiverPlane> planes{engine::ReceiverPlane::from_grid(d.grids.at(0))};
  const engine::PortEmitter emitter(scene, sources);
  engine::TracingOptions o;
  o.photons_per_source = photons;
  o.source_photon_factor.assign(sources.size(), 1.0);
  o.source_photon_factor[0] = study::GroundPhotonFactor;  // the run's policy (plan_policy.h)
  constexpr std::size_t Ground = 0;

  study::Step step;
  step.kind = study::StepKind::SourcePhotons;
  step.ranges = study::sky_source_ranges(scene, materials, emitter, planes, o, Ground);
  std::string bytes;
  comm.barrier();
  const double cpu0 = cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  if (comm.size() == 1) {
    bytes = study::encode_photons(engine::trace_source_photons(scene, materials, emitter, planes, o, Ground));
  } else {
    study::run_split_photon_steps(
        comm, {step}, {0}, [&](std::size_t, const std::vector<std::string>& artefacts) { bytes = artefacts.at(0); },
        study::MinSplitRangeAttempts);
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = cpu_seconds() - cpu0;

  dist::ByteBuffer mine(sizeof cpu);
  std::memcpy(mine.data(), &cpu, sizeof cpu);
  const std::vector<dist::ByteBuffer> all = comm.gather_to_root(mine);
  if (comm.rank() != dist::RootRank) return 0;
  std::uint64_t digest = 0xcbf29ce484222325ull;  // FNV-1a, 64 bit
  for (char x : bytes) {
    digest ^= static_cast<unsigned char>(x);
    digest *= 0x100000001b3ull;
  }
  const engine::TracedPhotons t = study::decode_photons(bytes);
  const engine::SourceTally& tally = t.tallies.at(0);
  std::printf("the ground bin of projects/office %s: %d ranks x %d threads, %zu photons per bin (x%g)\n",
              comm.size() == 1 ? "traced whole" : "in attempt ranges", comm.size(),
              int(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)), photons,
              study::GroundPhotonFactor);
  std::printf("  attempts %llu pre-pass + %llu main pass and top-up, %llu stored global photons\n",
              static_cast<unsigned long long>(tally.prepass_attempts),
              static_cast<unsigned long long>(tally.mainpass_attempts),
              static_cast<unsigned long long>(tally.stored_global));
  std::printf("  wall %.2f s; CPU s by rank:", wall);
  double cpu_all = 0, cpu_max = 0;
  for (const dist::ByteBuffer& b : all) {
    double c = 0;
    std::memcpy(&c, b.data(), sizeof c);
    cpu_all += c;
    cpu_max = std::max(cpu_max, c);
    std::printf(" %.2f", c);
  }
  std::printf(" (sum %.2f, balance sum / max %.2f)\n", cpu_all, cpu_all / cpu_max);
  std::printf("  artefact %zu bytes, digest %016llx\n", bytes.size(), static_cast<unsigned long long>(digest));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t photons = argc > 1 ? std::stoul(argv[1]) : 20000;
  std::unique_ptr<tbb::global_control> limit;
  if (argc > 2)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, std::stoul(argv[2]));
  if (!dist::detect_launcher([](const char* name) { return std::getenv(name); })) {
    auto comm = dist::make_serial_communicator();
    return run(*comm, photons);
  }
  dist::MpiSession session(&argc, &argv);
  int code = 0;
  {
    auto comm = session.world();
    try {
      code = run(*comm, photons);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "rank %d: error: %s\n", comm->rank(), e.what());
      code = 1;
    }
  }
  return code;
}
