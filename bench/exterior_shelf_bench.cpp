// exterior_shelf_bench: an exterior system's reflections traced by default (`port: system`,
// outdoor scatterers) against the exact but expensive port enclosure and the shading-only
// window port, on projects/light_shelf (exterior mirror shelf below its clerestory).
//
// 1. Cost: the sky-photon pass of the project's own settings (Reinhart sky, photons per bin,
//    ground bin x16, final-gather photons kept) with the outer shelf as `port: window`
//    (today's shading-only approximation) and as `port: system`, one after the other in this
//    process: wall times and their ratio.
// 2. Accuracy: the three ceiling probes (final gather) under single suns, `port: system` at
//    the project's photon count against `port: enclosure` at REFERENCE_FACTOR x the photons
//    and 4096 gather rays (the reference), and `port: window` beside them (what the shading-
//    only approximation misses). Ceiling illuminance per unit sun radiance, photon part plus
//    direct part.
// Usage: exterior_shelf_bench [reference factor (default 20)]
#include <tbb/info.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/project/project.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/sky/solar_position.h"

using namespace dayphoton;
using Clock = std::chrono::steady_clock;

namespace {

struct Model {
  SceneDescription description;
  engine::Scene scene;
  std::vector<engine::Material> materials;
  std::vector<SensorPoint> probes;
  std::vector<engine::ReceiverPlane> planes;
};

Model model_with(project::Project proj, project::PortMode mode) {
  for (project::SystemSpec& s : proj.geometry.systems)
    if (s.mount.side == project::MountSide::Exterior) s.mount.port = mode;
  SceneDescription d = project::build_scene_description(proj);
  engine::Scene scene = engine::Scene::build(d);
  std::vector<engine::Material> materials;
  for (const MaterialSpec& m : d.materials) materials.push_back(engine::Material::from_spec(m));
  std::vector<SensorPoint> probes;
  std::vector<engine::ReceiverPlane> planes;
  for (const SensorGrid& g : d.grids) {
    if (g.planar) planes.push_back(engine::ReceiverPlane::from_grid(g));
    if (g.name == "ceiling_probes") probes = g.points;
  }
  return Model{std::move(d), std::move(scene), std::move(materials), std::move(probes), std::move(planes)};
}

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

double sky_pass_s(const Model& m, const engine::SourceSet& sources, const project::Simulation& sim) {
  engine::TracingOptions o;
  o.photons_per_source = static_cast<std::size_t>(sim.photons_per_bin);
  o.seed = sim.seed;
  o.source_photon_factor.assign(sources.size(), 1.0);
  o.source_photon_factor[0] = 16;
  o.store_direct_on_surfaces = true;
  const auto t0 = Clock::now();
  (void)engine::trace_photons(m.scene, m.materials, sources, m.planes, o);
  return seconds_since(t0);
}

/// Ceiling probes' illuminance per unit sun radiance (photon part + direct part).
std::vector<double> probes_under(const Model& m, const Vec3& toward_sun, std::size_t photons, int gather_rays,
                                 std::uint64_t seed) {
  engine::SourceSet sun;
  sun.add_sun_disc(toward_sun, sky::SunHalfAngle_rad);
  engine::TracingOptions o;
  o.photons_per_source = photons;
  o.seed = seed;
  o.store_direct_on_surfaces = true;
  const engine::TracedPhotons t = engine::trace_photons(m.scene, m.materials, sun, {}, o);
  engine::CoefficientOptions co;
  co.gather.rays_per_sensor = gather_rays;
  co.gather.seed = seed;
  const engine::GridPhotons grid = engine::GridPhotons::for_gather(t.surface, 1);
  const engine::DaylightCoefficients c = engine::daylight_coefficients(m.scene, m.materials, sun, grid, m.probes, co);
  std::vector<double> out;
  for (std::size_t s = 0; s < m.probes.size(); ++s) {
    const Vec3 e = c.direct[s] + c.caustic[s] + c.global[s];
    out.push_back((e.x + e.y + e.z) / 3.0);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const double reference_factor = argc > 1 ? std::stod(argv[1]) : 20.0;
  const project::Project proj =
      project::load_project(std::string(DAYPHOTON_BENCH_SOURCE_DIR) + "/projects/light_shelf/project.yaml");
  const project::Simulation& sim = proj.simulation;
  const Model window = model_with(proj, project::PortMode::Window);
  const Model system = model_with(proj, project::PortMode::System);
  const Model enclosure = model_with(proj, project::PortMode::Enclosure);
  const engine::SourceSet sky = engine::SourceSet::sky_bins(
      sim.basis == project::SkyBasis::Tregenza ? sky::PatchBasis::tregenza() : sky::PatchBasis::reinhart(sim.reinhart_mf));

  std::printf("projects/light_shelf, %u threads\n", static_cast<unsigned>(tbb::info::default_concurrency()));
  const double t_window = sky_pass_s(window, sky, sim);
  const double t_system = sky_pass_s(system, sky, sim);
  std::printf("sky photon pass (%zu sources, %lld photons per bin): port: window %.2f s, port: system %.2f s, "
              "ratio %.2f\n",
              sky.size(), static_cast<long long>(sim.photons_per_bin), t_window, t_system, t_system / t_window);

  // Suns in world coordinates (+y true north): altitude, azimuth clockwise from north.
  const double suns[][2] = {{30, 180}, {50, 160}, {65, 210}};
  const std::size_t n = static_cast<std::size_t>(sim.photons_per_bin);
  const auto big = static_cast<std::size_t>(std::llround(double(n) * reference_factor));
  std::printf("ceiling probes (illuminance per unit sun radiance): reference = enclosure at %zu photons and 4096 "
              "gather rays; system, enclosure and window (shading only) at %zu photons and 1024 rays\n",
              big, n);
  double sum2 = 0;
  int count = 0;
  for (const auto& sun : suns) {
    const double alt = sun[0] * Pi / 180, az = sun[1] * Pi / 180;
    const Vec3 d{std::cos(alt) * std::sin(az), std::cos(alt) * std::cos(az), std::sin(alt)};
    const auto t0 = Clock::now();
    const std::vector<double> s = probes_under(system, d, n, 1024, 7);
    const double ts = seconds_since(t0);
    const std::vector<double> r = probes_under(enclosure, d, big, 4096, 8);
    const std::vector<double> w = probes_under(window, d, n, 1024, 7);
    const std::vector<double> sr = probes_under(system, d, big, 4096, 9);
    const std::vector<double> er = probes_under(enclosure, d, n, 1024, 10);
    for (std::size_t p = 0; p < s.size(); ++p) {
      const double rel = sr[p] / r[p] - 1;
      sum2 += rel * rel;
      ++count;
      std::printf("  sun %2.0f/%3.0f probe %zu: reference %.4e; system %+.1f %% (%+.1f %% at the reference's photons),"
                  " enclosure %+.1f %%, window %+.1f %%  [system %.2f s]\n",
                  sun[0], sun[1], p, r[p], 100 * (s[p] / r[p] - 1), 100 * rel, 100 * (er[p] / r[p] - 1),
                  100 * (w[p] / r[p] - 1), ts);
    }
  }
  std::printf("RMS of system vs enclosure, both at the reference's photons, over %d probe-suns: %.2f %%\n", count,
              100 * std::sqrt(sum2 / count));
}
