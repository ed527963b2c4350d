// direct_sun_bench: cost of the exact hourly direct sun (study::direct_sun_coefficients) on
// the reference office (projects/office), in milliseconds per sensor-year, next to the
// plain per-ray loop it replaced (one engine::sky_transmittance per disc sample, below), on
// the same sensors, suns and random numbers, in the same run. Prints both times (wall and
// process CPU: the machine may be shared), the speed-up, and the largest difference between
// the two matrices (they trace the same rays, so it should be 0).
//
// Sensors: the office's work-plane grid (165), or, with a count N > 0, N sensors on a square
// lattice over the floor at 0.8 m (at 0.5 m from the walls), facing up.
// Usage: direct_sun_bench [sensors N (default 0: the project grid)] [threads (default all)]
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <string>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/direct_component.h"
#include "dayphoton/engine/distant_source.h"
#include "dayphoton/engine/random.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/annual_illuminance.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/sun_site.h"
#include "dayphoton/weather/epw_reader.h"

using namespace dayphoton;
using Clock = std::chrono::steady_clock;

namespace {

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

/// The loop direct_sun_coefficients ran before its rays were traced in packets: the same
/// strata, random numbers and disc map, one sky_transmittance call per sample.
RadianceMatrix per_ray_reference(const engine::Scene& scene, const std::vector<engine::Material>& materials,
                                 const std::vector<SensorPoint>& sensors, const std::vector<sky::SunRecord>& suns,
                                 int samples, std::uint64_t seed) {
  int k = static_cast<int>(std::sqrt(double(samples)));
  while (k * k < samples) ++k;
  engine::SourceSet discs;
  for (const sky::SunRecord& s : suns) discs.add_sun_disc(s.direction, sky::SunHalfAngle_rad);
  const double weight = discs.size() ? discs[0].solid_angle_sr / (double(k) * k) : 0.0;
  constexpr double OneMinusEpsilon = 0x1.fffffffffffffp-1;
  RadianceMatrix result(sensors.size(), suns.size(), 3);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, sensors.size()), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t s = r.begin(); s != r.end(); ++s) {
      const Vec3 normal = sensors[s].normal / length(sensors[s].normal);
      const Vec3 origin = sensors[s].position + normal * scene.ray_epsilon_m();
      for (std::size_t i = 0; i < suns.size(); ++i) {
        Vec3 sum;
        if (dot(suns[i].direction, normal) > -std::sin(sky::SunHalfAngle_rad)) {
          engine::Rng rng(seed, suns[i].step, s, engine::RandomStream::Direct);
          for (int a = 0; a < k; ++a)
            for (int b = 0; b < k; ++b) {
              const double u1 = std::min((a + rng.uniform()) / k, OneMinusEpsilon);
              const double u2 = std::min((b + rng.uniform()) / k, OneMinusEpsilon);
              const Vec3 w = discs.sample_direction(i, u1, u2);
              const double c = dot(w, normal);
              if (!(c > 0.0)) continue;
              sum += engine::sky_transmittance(scene, materials, origin, w) * c;
            }
        }
        for (int c = 0; c < 3; ++c) result.at(s, i, c) = static_cast<float>(sum[c] * weight);
      }
    }
  });
  return result;
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t lattice = argc > 1 ? std::stoul(argv[1]) : 0;
  std::unique_ptr<tbb::global_control> limit;
  if (argc > 2 && std::stoul(argv[2]) > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, std::stoul(argv[2]));
  const project::Project proj =
      project::load_project(std::string(DAYPHOTON_BENCH_SOURCE_DIR) + "/projects/office/project.yaml");
  const SceneDescription description = project::build_scene_description(proj);
  const engine::Scene scene = engine::Scene::build(description);
  std::vector<engine::Material> materials;
  for (const MaterialSpec& m : description.materials) materials.push_back(engine::Material::from_spec(m));

  std::vector<SensorPoint> sensors = description.grids.at(0).points;
  if (lattice > 0) {
    // The office floor is 6 x 8 m (x, y from 0); a square lattice of about `lattice` points.
    const double spacing = std::sqrt(5.0 * 7.0 / double(lattice));
    sensors.clear();
    for (double y = 0.5; y <= 7.5 + 1e-9; y += spacing)
      for (double x = 0.5; x <= 5.5 + 1e-9; x += spacing) sensors.push_back({{x, y, 0.8}, {0, 0, 1}});
  }
  const weather::HourlyWeather epw = weather::read_hourly_weather(proj.weather.path);
  const sky::SolarSite site = study::resolve_sun_site(proj.site, epw).solar;
  const study::SkyAndSuns ss = study::annual_sky_and_suns(epw, site, sky::PatchBasis::tregenza(),
                                                          study::sun_excluded_sky_options(proj.simulation.ground_reflectance));
  const std::vector<sky::SunRecord>& suns = ss.suns;
  const std::uint64_t seed = std::uint64_t(proj.simulation.seed);
  std::printf("direct sun, office: %zu sensors x %zu sun hours x %d rays, %d threads\n", sensors.size(), suns.size(),
              study::SunDirectSamples, tbb::this_task_arena::max_concurrency());

  auto time = [&](const char* what, auto&& run, RadianceMatrix& out) {
    const auto w0 = Clock::now();
    const double c0 = cpu_seconds();
    out = run();
    const double wall = std::chrono::duration<double>(Clock::now() - w0).count(), cpu = cpu_seconds() - c0;
    std::printf("  %-34s %8.3f ms per sensor-year wall, %8.3f ms CPU  (%.2f s wall, %.2f s CPU)\n", what,
                1e3 * wall / double(sensors.size()), 1e3 * cpu / double(sensors.size()), wall, cpu);
    return cpu;
  };
  RadianceMatrix fast, reference;
  const double cpu_fast = time("direct_sun_coefficients", [&] {
    return study::direct_sun_coefficients(scene, materials, sensors, suns, study::SunDirectSamples, seed);
  }, fast);
  const double cpu_ref = time("per-ray reference loop", [&] {
    return per_ray_reference(scene, materials, sensors, suns, study::SunDirectSamples, seed);
  }, reference);
  double largest = 0, total = 0;
  for (std::size_t s = 0; s < sensors.size(); ++s)
    for (std::size_t i = 0; i < suns.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        largest = std::max(largest, std::fabs(double(fast.at(s, i, c)) - double(reference.at(s, i, c))));
        total += double(reference.at(s, i, c));
      }
  std::printf("  speed-up (CPU) %.2f x; largest |difference| %.3g (matrix sum %.6g)\n", cpu_ref / cpu_fast, largest,
              total);
  return 0;
}
