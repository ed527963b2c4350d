// Direct component: stratified shadow-ray sampling of each distant source from each sensor,
// through straight-transmitting glazing up to the first port (rule and estimator in
// engine/include/dayphoton/engine/direct_component.h; DESIGN.md section 5).
#include "dayphoton/engine/direct_component.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "dayphoton/engine/random.h"

namespace dayphoton::engine {
namespace {

/// Largest double below 1: a jittered stratum coordinate (i + xi) / k can round up to 1.0,
/// which would put the sample on the far edge of the source (outside a half-open bin).
constexpr double OneMinusEpsilon = 0x1.fffffffffffffp-1;

void check_materials(const Scene& scene, const std::vector<Material>& materials) {
  const std::size_t needed = scene.description().materials.size();
  if (materials.size() < needed)
    throw std::invalid_argument("direct component: " + std::to_string(materials.size()) +
                                " material models for a scene with " + std::to_string(needed) +
                                " materials");
}

int strata_per_axis(int samples) {
  if (samples < 1)
    throw std::invalid_argument("direct component: " + std::to_string(samples) +
                                " samples per source; at least 1 is needed");
  int k = static_cast<int>(std::sqrt(static_cast<double>(samples)));
  while (k * k < samples) ++k;
  return k;
}

Vec3 checked_unit_normal(const SensorPoint& sensor) {
  const double len = length(sensor.normal);
  if (!is_finite(sensor.normal) || !(len > 0.0) || !is_finite(sensor.position))
    throw std::invalid_argument(
        "direct component: a sensor needs a finite position and a finite non-zero normal");
  return sensor.normal / len;
}

/// Stratified estimate of integral over source p of L(w) T(w) max(0, dot(w, n)) dw, with
/// L = 1 when `radiance` is null. `origin` is the sensor already moved off its surface.
Vec3 integrate_source(const Scene& scene, const std::vector<Material>& materials,
                      const SourceSet& sources, std::size_t p, const Vec3& origin,
                      const Vec3& normal, int k, std::uint64_t seed, std::uint64_t sensor_index,
                      const std::function<Vec3(const Vec3&)>* radiance) {
  Rng rng(seed, p, sensor_index, RandomStream::Direct);
  Vec3 sum;
  for (int i = 0; i < k; ++i) {
    for (int j = 0; j < k; ++j) {
      // Draw both numbers before any early exit so that every stratum uses the same pair
      // whatever the scene: glazed and unglazed runs then trace identical directions.
      const double u1 = std::min((i + rng.uniform()) / k, OneMinusEpsilon);
      const double u2 = std::min((j + rng.uniform()) / k, OneMinusEpsilon);
      const Vec3 w = sources.sample_direction(p, u1, u2);
      const double cos_theta = dot(w, normal);
      if (!(cos_theta > 0.0)) continue;
      const Vec3 t = sky_transmittance(scene, materials, origin, w);
      if (t.x == 0.0 && t.y == 0.0 && t.z == 0.0) continue;
      sum += (radiance ? mul(t, (*radiance)(w)) : t) * cos_theta;
    }
  }
  return sum * (sources[p].solid_angle_sr / (static_cast<double>(k) * k));
}

}  // namespace

Vec3 sky_transmittance(const Scene& scene, const std::vector<Material>& materials,
                       const Vec3& origin, const Vec3& direction) {
  check_materials(scene, materials);
  // Light from the sky propagates toward the sensor, against the shadow ray.
  const Vec3 incoming = -direction;
  Vec3 transmittance{1.0, 1.0, 1.0};
  bool through_port = false;
  Ray ray;
  ray.origin = origin;
  ray.direction = direction;
  for (int crossings = 0;; ++crossings) {
    const std::optional<Hit> hit = scene.intersect(ray);
    if (!hit) return through_port ? transmittance : Vec3{};
    // Outside the room nothing is transmitted or reflected toward the sensor: whatever
    // the ray meets after its port (an obstruction, another building) blocks the sky.
    if (through_port || crossings >= MaxShadowRayCrossings) return Vec3{};
    const Material& material = materials[static_cast<std::size_t>(hit->material)];
    transmittance = mul(transmittance, material.straight_transmittance(incoming, hit->normal));
    if (!(transmittance.x > 0.0 || transmittance.y > 0.0 || transmittance.z > 0.0))
      return Vec3{};
    if (hit->port >= 0) through_port = true;
    ray.origin = scene.offset_ray_origin(hit->position, hit->normal, direction);
  }
}

std::vector<Vec3> direct_coefficients(const Scene& scene, const std::vector<Material>& materials,
                                      const SourceSet& sources,
                                      const std::vector<SensorPoint>& sensors,
                                      const DirectOptions& options) {
  check_materials(scene, materials);
  const int k = strata_per_axis(options.samples_per_source);
  std::vector<Vec3> normals;
  normals.reserve(sensors.size());
  for (const SensorPoint& sensor : sensors) normals.push_back(checked_unit_normal(sensor));

  const std::size_t n_sources = sources.size();
  std::vector<Vec3> result(sensors.size() * n_sources);
  // One sensor per task item: each writes only its own row, and its random numbers depend
  // on (seed, source, sensor) alone, so the partition into threads changes nothing.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, sensors.size()),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t s = range.begin(); s != range.end(); ++s) {
                        const Vec3 origin = sensors[s].position +
                                            normals[s] * scene.ray_epsilon_m();
                        for (std::size_t p = 0; p < n_sources; ++p)
                          result[s * n_sources + p] =
                              integrate_source(scene, materials, sources, p, origin,
                                               normals[s], k, options.seed, s, nullptr);
                      }
                    });
  return result;
}

Vec3 direct_irradiance(const Scene& scene, const std::vector<Material>& materials,
                       const SourceSet& sources, const SensorPoint& sensor,
                       const std::function<Vec3(const Vec3&)>& radiance, int samples,
                       std::uint64_t seed) {
  check_materials(scene, materials);
  const int k = strata_per_axis(samples);
  const Vec3 normal = checked_unit_normal(sensor);
  const Vec3 origin = sensor.position + normal * scene.ray_epsilon_m();
  Vec3 sum;
  for (std::size_t p = 0; p < sources.size(); ++p)
    sum += integrate_source(scene, materials, sources, p, origin, normal, k, seed, 0, &radiance);
  return sum;
}

}  // namespace dayphoton::engine
