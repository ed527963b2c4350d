// ray_throughput: rays per second of the engine's Scene on the reference office
// (../shared/refdata/scenes/office.rad: 6 x 8 x 3 m room, 4 x 1.5 m window port), built
// in C++ here. Rays start at uniform random points inside the room in uniform random
// directions (every ray hits: the room is closed), are generated up front, then cast with
// Scene::intersect and Scene::occluded, on one thread and with oneTBB parallel_for on all
// cores. Usage: ray_throughput [rays (default 2000000)] [seed (default 1)]
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/units.h"
#include "dayphoton/engine/engine_error.h"
#include "dayphoton/engine/scene.h"

using namespace dayphoton;
using dayphoton::engine::Ray;
using dayphoton::engine::Scene;

namespace {

SceneDescription office() {
  SceneDescription d;
  auto material = [&](const char* name, MaterialType type, double r) {
    MaterialSpec m;
    m.name = name;
    m.type = type;
    m.reflectance = {r, r, r};
    d.materials.push_back(m);
    return static_cast<int>(d.materials.size()) - 1;
  };
  const int floor = material("floor_mat", MaterialType::Lambertian, 0.2);
  const int wall = material("wall_mat", MaterialType::Lambertian, 0.5);
  const int ceiling = material("ceiling_mat", MaterialType::Lambertian, 0.7);
  const int glass = material("glass_mat", MaterialType::Glass, 0.0);
  auto surface = [&](const char* name, int m, std::vector<Vec3> v, bool port = false) {
    Surface s;
    s.name = name;
    s.material = m;
    s.vertices = std::move(v);
    s.port = port;
    d.surfaces.push_back(std::move(s));
  };
  surface("floor", floor, {{0, 0, 0}, {6, 0, 0}, {6, 8, 0}, {0, 8, 0}});
  surface("ceiling", ceiling, {{0, 0, 3}, {0, 8, 3}, {6, 8, 3}, {6, 0, 3}});
  surface("wall_west", wall, {{0, 0, 0}, {0, 8, 0}, {0, 8, 3}, {0, 0, 3}});
  surface("wall_east", wall, {{6, 0, 0}, {6, 0, 3}, {6, 8, 3}, {6, 8, 0}});
  surface("wall_north", wall, {{0, 8, 0}, {6, 8, 0}, {6, 8, 3}, {0, 8, 3}});
  surface("wall_south_sill", wall, {{0, 0, 0}, {0, 0, 0.9}, {6, 0, 0.9}, {6, 0, 0}});
  surface("wall_south_head", wall, {{0, 0, 2.4}, {0, 0, 3}, {6, 0, 3}, {6, 0, 2.4}});
  surface("wall_south_jamb_w", wall, {{0, 0, 0.9}, {0, 0, 2.4}, {1, 0, 2.4}, {1, 0, 0.9}});
  surface("wall_south_jamb_e", wall, {{5, 0, 0.9}, {5, 0, 2.4}, {6, 0, 2.4}, {6, 0, 0.9}});
  surface("window", glass, {{1, 0, 0.9}, {1, 0, 2.4}, {5, 0, 2.4}, {5, 0, 0.9}}, true);
  return d;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void report(const char* what, std::size_t rays, double seconds, std::size_t hits) {
  std::printf("  %-34s %10.3f Mrays/s  (%zu rays in %.3f s, %zu hits)\n", what,
              rays / seconds * 1e-6, rays, seconds, hits);
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 2000000;
  const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
  if (n == 0) {
    std::fprintf(stderr, "usage: ray_throughput [rays > 0] [seed]\n");
    return 2;
  }
  const int threads = tbb::this_task_arena::max_concurrency();
  std::printf("ray_throughput: Embree %s, %d hardware threads for TBB\n",
              engine::embree_version().c_str(), threads);

  auto t0 = std::chrono::steady_clock::now();
  const Scene scene = Scene::build(office());
  std::printf("office scene: %zu triangles, %zu port(s), built in %.3f ms\n",
              scene.triangle_count(), scene.ports().size(), 1e3 * seconds_since(t0));

  std::vector<Ray> rays(n);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (auto& r : rays) {
    const double z = 1 - 2 * u(rng), phi = 2 * Pi * u(rng), s = std::sqrt(1 - z * z);
    r.origin = {6 * u(rng), 8 * u(rng), 3 * u(rng)};
    r.direction = {s * std::cos(phi), s * std::sin(phi), z};
  }

  std::printf("single thread:\n");
  t0 = std::chrono::steady_clock::now();
  std::size_t hits = 0;
  for (const auto& r : rays) hits += scene.intersect(r).has_value();
  report("intersect", n, seconds_since(t0), hits);

  t0 = std::chrono::steady_clock::now();
  hits = 0;
  for (const auto& r : rays) hits += scene.occluded(r);
  report("occluded", n, seconds_since(t0), hits);

  std::printf("oneTBB parallel_for, %d threads:\n", threads);
  std::atomic<std::size_t> parallel_hits{0};
  t0 = std::chrono::steady_clock::now();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      std::size_t local = 0;
                      for (std::size_t i = range.begin(); i != range.end(); ++i)
                        local += scene.intersect(rays[i]).has_value();
                      parallel_hits += local;
                    });
  report("intersect", n, seconds_since(t0), parallel_hits.load());

  parallel_hits = 0;
  t0 = std::chrono::steady_clock::now();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      std::size_t local = 0;
                      for (std::size_t i = range.begin(); i != range.end(); ++i)
                        local += scene.occluded(rays[i]);
                      parallel_hits += local;
                    });
  report("occluded", n, seconds_since(t0), parallel_hits.load());

  std::vector<std::optional<engine::Hit>> batch_hits(n);
  t0 = std::chrono::steady_clock::now();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      scene.intersect_batch(rays.data() + range.begin(), range.size(),
                                            batch_hits.data() + range.begin());
                    });
  const double batch_s = seconds_since(t0);
  hits = 0;
  for (const auto& h : batch_hits) hits += h.has_value();
  report("intersect_batch (4096-ray chunks)", n, batch_s, hits);
  return 0;
}
