// photon_tracing_bench: forward-pass throughput on the reference office (projects/office),
// next to the raw Embree rate of the same scene as the ceiling.
//
// Prints attempts/s, stored photons/s and rays/s of trace_photons for the 146 Tregenza
// sources (ground bin photons x16, as the pipeline does), then the rate of Scene::intersect
// on random rays inside the same room, on all cores, and the bytes per stored photon (record
// + tree). Rates are given per second of wall time and per second of process CPU time; the
// ratio of the forward pass to the raw rate is taken from CPU time, which other programs
// sharing the machine do not distort (the wall-time ratio is printed too). Last, a digest of
// the traced photons (every byte of every record, in order) and of the per-source tallies:
// a change meant to leave the photons byte-identical must leave it unchanged.
// Usage: photon_tracing_bench [photons_per_bin (default 20000)]
#include <tbb/parallel_for.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <random>
#include <string>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/photon_map.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/project/project.h"

using namespace dayphoton;
using Clock = std::chrono::steady_clock;

namespace {
// FNV-1a (Fowler, Noll and Vo), 64-bit, over `bytes` bytes.
std::uint64_t fnv1a(std::uint64_t hash, const void* data, std::size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) hash = (hash ^ p[i]) * 1099511628211ull;
  return hash;
}

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}
}  // namespace

int main(int argc, char** argv) {
  const std::size_t photons = argc > 1 ? std::stoul(argv[1]) : 20000;
  const project::Project proj =
      project::load_project(std::string(DAYPHOTON_BENCH_SOURCE_DIR) + "/projects/office/project.yaml");
  const SceneDescription d = project::build_scene_description(proj);
  const engine::Scene scene = engine::Scene::build(d);
  std::vector<engine::Material> materials;
  for (const MaterialSpec& m : d.materials) materials.push_back(engine::Material::from_spec(m));
  const engine::SourceSet sources = engine::SourceSet::sky_bins(sky::PatchBasis::tregenza());
  const engine::ReceiverPlane plane = engine::ReceiverPlane::from_grid(d.grids.at(0));

  engine::TracingOptions o;
  o.photons_per_source = photons;
  o.source_photon_factor.assign(sources.size(), 1.0);
  o.source_photon_factor[0] = 16;
  auto t0 = Clock::now();
  double c0 = cpu_seconds();
  const engine::TracedPhotons t = engine::trace_photons(scene, materials, sources, {plane}, o);
  const double trace_s = std::chrono::duration<double>(Clock::now() - t0).count();
  const double trace_cpu_s = cpu_seconds() - c0;
  std::uint64_t attempts = 0, rays = 0, entered = 0;
  for (const auto& tally : t.tallies) {
    attempts += tally.prepass_attempts + tally.mainpass_attempts;
    rays += tally.rays;
    entered += tally.entered;
  }
  const std::size_t stored = t.surface.size() + t.planes[0].size();
  std::printf("forward pass, office, %zu stored photons per bin target, %u threads\n", photons,
              static_cast<unsigned>(tbb::info::default_concurrency()));
  std::printf("  %.2f s: %.3g attempts/s, %.3g photons entering/s, %.3g stored photons/s, %.3g rays/s"
              " (%zu stored, %.2f rays per stored photon, %.2f attempts per entering photon)\n",
              trace_s, attempts / trace_s, entered / trace_s, stored / trace_s, rays / trace_s, stored,
              double(rays) / double(stored), double(attempts) / double(entered));
  std::printf("  %.2f CPU s: %.3g rays per CPU second\n", trace_cpu_s, rays / trace_cpu_s);

  // The ceiling: Scene::intersect on random rays from inside the room, all cores.
  const std::size_t n = 4000000;
  std::vector<engine::Ray> random_rays(n);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0, 1);
  for (auto& r : random_rays) {
    const double z = 1 - 2 * u(rng), phi = 2 * Pi * u(rng), s = std::sqrt(1 - z * z);
    r.origin = {0.1 + 5.8 * u(rng), 0.1 + 7.8 * u(rng), 0.1 + 2.8 * u(rng)};
    r.direction = {s * std::cos(phi), s * std::sin(phi), z};
  }
  std::vector<int> hit(n);
  t0 = Clock::now();
  c0 = cpu_seconds();
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) { hit[i] = scene.intersect(random_rays[i]) ? 1 : 0; });
  const double embree_s = std::chrono::duration<double>(Clock::now() - t0).count();
  const double embree_cpu_s = cpu_seconds() - c0;
  std::printf("  raw Scene::intersect on the same scene: %.3g rays/s, %.3g rays per CPU second\n", n / embree_s,
              n / embree_cpu_s);
  std::printf("  forward pass / raw rate: %.0f %% (CPU time; wall time: %.0f %%)\n",
              100.0 * (rays / trace_cpu_s) / (n / embree_cpu_s), 100.0 * (rays / trace_s) / (n / embree_s));

  const engine::PhotonMap map(t.planes[0]);
  std::printf("  memory: %zu bytes per photon record, %.1f bytes per photon in a built map\n",
              sizeof(engine::Photon), double(map.memory_bytes()) / double(map.size()));
  // The records with their sky ratio codes as 0: the digest predates the codes (photon.h), so
  // it pins the positions, fluxes, sources, normals and classes as they were recorded.
  std::uint64_t digest = 14695981039346656037ull;
  auto digest_records = [&digest](const std::vector<engine::Photon>& records) {
    for (engine::Photon p : records) {
      p.sky_ratio_code = 0;
      digest = fnv1a(digest, &p, sizeof p);
    }
  };
  digest_records(t.surface);
  for (const auto& p : t.planes) digest_records(p);
  for (const auto& tally : t.tallies)
    for (const std::uint64_t v : {tally.prepass_attempts, tally.mainpass_attempts, tally.entered, tally.stored_global,
                                  tally.stored_caustic, tally.stored_direct, tally.rays})
      digest = fnv1a(digest, &v, sizeof v);
  std::printf("  photon digest (FNV-1a of the records and tallies): %016llx\n",
              static_cast<unsigned long long>(digest));
  return 0;
}
