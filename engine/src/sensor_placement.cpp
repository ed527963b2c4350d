// Sensor placement: see sensor_placement.h.
#include "dayphoton/engine/sensor_placement.h"

#include <cstdint>
#include <cstring>
#include <map>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "dayphoton/engine/random.h"
#include "dayphoton/engine/scene.h"
#include "material_common.h"
#include "spread_directions.h"

namespace dayphoton::engine {
namespace {

bool is_transparent(MaterialType type) {
  return type == MaterialType::Glass || type == MaterialType::Opening || type == MaterialType::Dielectric;
}

/// Surfaces light may pass through or scatter back from (header comment): a walk goes
/// straight on or diffusely back with even odds.
bool may_transmit(MaterialType type) {
  return type == MaterialType::Translucent || type == MaterialType::Glazing || type == MaterialType::Registered;
}

bool is_specular_reflector(MaterialType type) {
  return type == MaterialType::Mirror || type == MaterialType::Metal;
}

/// The walks' random key of a sensor: a function of its position and normal only, so the
/// test of a sensor gives the same answer in any order, thread or set.
std::uint64_t sensor_key(const SensorPoint& sensor) {
  std::uint64_t key = 0;
  for (double v : {sensor.position.x, sensor.position.y, sensor.position.z, sensor.normal.x, sensor.normal.y,
                   sensor.normal.z}) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    key = Rng::mix(key ^ bits);
  }
  return key;
}

/// Whether one walk from `origin` (header comment) crosses a port or escapes to the sky within
/// SensorEnclosureBounces bounces.
bool walk_reaches_outside(const Scene& scene, const Vec3& origin, const Vec3& first_direction, Rng& rng) {
  const SceneDescription& description = scene.description();
  Ray ray{origin, first_direction};
  int crossings = 0;
  for (int bounce = 0; bounce < SensorEnclosureBounces;) {
    const std::optional<Hit> hit = scene.intersect(ray);
    if (!hit || hit->port >= 0) return true;
    const MaterialType type = description.materials[static_cast<std::size_t>(hit->material)].type;
    const Vec3 d = ray.direction;
    const Vec3 facing = dot(d, hit->normal) < 0 ? hit->normal : hit->normal * -1.0;  // the side it came from
    Vec3 next = d;
    if (is_transparent(type) || (may_transmit(type) && rng.uniform() < 0.5)) {
      // Straight on: a crossing, not a bounce (bounded on its own, as the spread rays').
      if (++crossings >= SensorPlacementMaxCrossings) return false;
    } else {
      next = is_specular_reflector(type) ? detail::reflect(d, hit->normal) : detail::sample_cosine(facing, rng.uniform(), rng.uniform());
      ++bounce;
    }
    ray = Ray{scene.offset_ray_origin(hit->position, hit->normal, next), next};
  }
  return false;
}

}  // namespace

SensorPlacementTest test_sensor_placement(const Scene& scene, const SensorPoint& sensor) {
  SensorPlacementTest out;
  if (!is_finite(sensor.position)) return out;
  const bool has_normal = is_finite(sensor.normal) && length(sensor.normal) > 0;
  const Vec3 n = has_normal ? normalize(sensor.normal) : Vec3{0, 0, 1};
  std::vector<Vec3> directions = detail::hemisphere_directions(n, has_normal ? SensorPlacementRays
                                                                             : SensorPlacementRays / 2);
  if (!has_normal) {
    const std::vector<Vec3> down = detail::hemisphere_directions(n * -1.0, SensorPlacementRays / 2);
    directions.insert(directions.end(), down.begin(), down.end());
  }
  const SceneDescription& description = scene.description();
  const Vec3 origin = has_normal ? sensor.position + n * (10.0 * scene.ray_epsilon_m()) : sensor.position;
  std::map<int, int> back_hits;  // surface -> rays stopped at its back
  // Follows one ray through ports and transparent surfaces; true if it crossed a port.
  auto trace = [&](const Vec3& d, bool count) {
    Ray ray{origin, d};
    bool crossed_port = false;
    for (int crossing = 0;; ++crossing) {
      const std::optional<Hit> hit = scene.intersect(ray);
      if (!hit) {
        if (count && !crossed_port) ++out.sky_without_port;
        break;
      }
      const Surface& surface = description.surfaces[static_cast<std::size_t>(hit->surface)];
      const MaterialType type = description.materials[static_cast<std::size_t>(hit->material)].type;
      if (hit->port >= 0 || is_transparent(type)) {
        crossed_port = crossed_port || hit->port >= 0;
        if (crossing + 1 >= SensorPlacementMaxCrossings) break;
        ray.origin = scene.offset_ray_origin(hit->position, hit->normal, d);
        continue;
      }
      if (count && surface.solid_face && !hit->front_face) {
        ++out.back_of_solid;
        ++back_hits[hit->surface];
      }
      break;
    }
    return crossed_port;
  };
  for (const Vec3& d : directions) {
    ++out.rays;
    if (trace(d, true)) ++out.through_port;
  }
  // A sensor that sees no port and no sky (inside a solid, or behind a partition) gets a second
  // chance: one ray aimed at the centroid of each port. One that reaches a port sees out (a
  // room whose mesh faces point outward, a window too small for the spread directions to
  // meet); inside a closed solid none does.
  const bool sees_out = out.through_port > 0 || out.sky_without_port > 0;
  if (!sees_out) {
    for (const Port& port : scene.ports().ports()) {
      const Vec3 to = port.centroid - origin;
      if (!(length(to) > 0)) continue;
      if (trace(normalize(to), false)) {
        out.through_port = 1;
        break;
      }
    }
  }
  if (out.sky_without_port >= SensorOutsideSkyFraction * out.rays) {
    out.placement = SensorPlacement::OutsideRooms;
  } else if (out.through_port == 0 && out.sky_without_port == 0 &&
             out.back_of_solid >= SensorInsideSolidFraction * out.rays) {
    out.placement = SensorPlacement::InsideSolid;
    int most = 0;
    for (const auto& [surface, count] : back_hits)
      if (count > most) most = count, out.solid_surface = surface;
  } else if (out.through_port == 0 && out.sky_without_port == 0) {
    // Sees neither a port nor the sky, not even aimed at a port: walk (header comment).
    const std::uint64_t key = sensor_key(sensor);
    for (int w = 0; w < SensorEnclosureWalks; ++w) {
      ++out.enclosure_walks;
      Rng rng(0, key, static_cast<std::uint64_t>(w), RandomStream::Placement);
      const double u1 = rng.uniform(), u2 = rng.uniform();
      const Vec3 d = has_normal ? detail::sample_cosine(n, u1, u2)
                                : detail::sample_cosine(rng.uniform() < 0.5 ? n : n * -1.0, u1, u2);
      if (walk_reaches_outside(scene, origin, d, rng)) return out;
    }
    out.placement = SensorPlacement::Enclosed;
  }
  return out;
}

std::vector<SensorPlacementTest> test_sensor_placements(const Scene& scene, const std::vector<SensorPoint>& sensors) {
  std::vector<SensorPlacementTest> out(sensors.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, sensors.size(), 64),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        out[i] = test_sensor_placement(scene, sensors[i]);
                    });
  return out;
}

}  // namespace dayphoton::engine
