// Sensor placement: see sensor_placement.h.
#include "dayphoton/engine/sensor_placement.h"

#include <cstdint>
#include <cstring>
#include <algorithm>
#include <atomic>
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

/// Whether one walk from `origin` (header comment) crosses a port within SensorEnclosureBounces
/// bounces.
bool walk_reaches_port(const Scene& scene, const Vec3& origin, const Vec3& first_direction, Rng& rng) {
  const SceneDescription& description = scene.description();
  Ray ray{origin, first_direction};
  int crossings = 0;
  for (int bounce = 0; bounce < SensorEnclosureBounces;) {
    const std::optional<Hit> hit = scene.intersect(ray);
    if (!hit) return false;  // out through a gap in the drawing: no photon comes in that way
    if (hit->port >= 0) return true;
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

/// A sensor's test frame (header comment): its unit normal (+z for a sensor without one) and
/// the placement rays' origin, 10 ray epsilons along the normal.
struct TestFrame {
  bool has_normal = false;
  Vec3 normal{0, 0, 1};
  Vec3 origin;
};

TestFrame test_frame(const Scene& scene, const SensorPoint& sensor) {
  TestFrame f;
  f.has_normal = is_finite(sensor.normal) && length(sensor.normal) > 0;
  if (f.has_normal) f.normal = normalize(sensor.normal);
  f.origin = f.has_normal ? sensor.position + f.normal * (10.0 * scene.ray_epsilon_m()) : sensor.position;
  return f;
}

/// Walk `w` of a sensor (header comment): its random generator and first direction.
bool walk_from(const Scene& scene, const SensorPoint& sensor, std::uint64_t key, int w) {
  const TestFrame f = test_frame(scene, sensor);
  Rng rng(0, key, static_cast<std::uint64_t>(w), RandomStream::Placement);
  const double u1 = rng.uniform(), u2 = rng.uniform();
  const Vec3 d = f.has_normal ? detail::sample_cosine(f.normal, u1, u2)
                              : detail::sample_cosine(rng.uniform() < 0.5 ? f.normal : f.normal * -1.0, u1, u2);
  return walk_reaches_port(scene, f.origin, d, rng);
}

/// Everything but the walks; `needs_walks` when the sensor saw neither a port nor the sky.
SensorPlacementTest direct_placement(const Scene& scene, const SensorPoint& sensor, bool& needs_walks) {
  needs_walks = false;
  SensorPlacementTest out;
  if (!is_finite(sensor.position)) return out;
  const TestFrame frame = test_frame(scene, sensor);
  const bool has_normal = frame.has_normal;
  const Vec3 n = frame.normal;
  std::vector<Vec3> directions = detail::hemisphere_directions(n, has_normal ? SensorPlacementRays
                                                                             : SensorPlacementRays / 2);
  if (!has_normal) {
    const std::vector<Vec3> down = detail::hemisphere_directions(n * -1.0, SensorPlacementRays / 2);
    directions.insert(directions.end(), down.begin(), down.end());
  }
  const SceneDescription& description = scene.description();
  const Vec3 origin = frame.origin;
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
    needs_walks = true;  // sees neither a port nor the sky, not even aimed at a port
  }
  return out;
}

/// The walks of a sensor, in parallel: the number of walks up to and including the first that
/// reaches a port (the same whatever the threads do: a walk is skipped only when a lower one
/// already reached), or SensorEnclosureWalks + 1 when none does.
int first_reaching_walk(const Scene& scene, const SensorPoint& sensor) {
  const std::uint64_t key = sensor_key(sensor);
  std::atomic<int> first{SensorEnclosureWalks};
  tbb::parallel_for(tbb::blocked_range<int>(0, SensorEnclosureWalks, 16), [&](const tbb::blocked_range<int>& r) {
    for (int w = r.begin(); w != r.end(); ++w) {
      if (w >= first.load(std::memory_order_relaxed)) return;
      if (walk_from(scene, sensor, key, w)) {
        int seen = first.load();
        while (w < seen && !first.compare_exchange_weak(seen, w)) {
        }
        return;
      }
    }
  });
  return first.load() + 1;
}

void finish_walks(SensorPlacementTest& out, int walks) {
  out.enclosure_walks = std::min(walks, SensorEnclosureWalks);
  if (walks > SensorEnclosureWalks) out.placement = SensorPlacement::Enclosed;
}

/// Whether nothing lies between two sensors' test origins (then they are in the same volume).
bool see_each_other(const Scene& scene, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double distance_m = length(ab);
  if (!(distance_m > 0)) return true;
  return !scene.occluded(Ray{a, ab * (1.0 / distance_m), 0, distance_m});
}

}  // namespace

SensorPlacementTest test_sensor_placement(const Scene& scene, const SensorPoint& sensor) {
  bool needs_walks = false;
  SensorPlacementTest out = direct_placement(scene, sensor, needs_walks);
  if (needs_walks) finish_walks(out, first_reaching_walk(scene, sensor));
  return out;
}

std::vector<SensorPlacementTest> test_sensor_placements(const Scene& scene, const std::vector<SensorPoint>& sensors) {
  std::vector<SensorPlacementTest> out(sensors.size());
  std::vector<char> needs_walks(sensors.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, sensors.size(), 64),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i) {
                        bool walks = false;
                        out[i] = direct_placement(scene, sensors[i], walks);
                        needs_walks[i] = walks;
                      }
                    });
  // The sensors to walk from, in order: one that sees a sensor already decided (no surface
  // between them) is in the same volume and shares its verdict; only the others walk. A grid
  // in one closed room then walks once, not once per sensor.
  std::vector<std::size_t> decided;
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    if (!needs_walks[i]) continue;
    const Vec3 origin = test_frame(scene, sensors[i]).origin;
    bool shared = false;
    for (std::size_t k = 0; k < decided.size() && k < SensorEnclosureNeighbours && !shared; ++k) {
      const std::size_t j = decided[decided.size() - 1 - k];
      if (!see_each_other(scene, origin, test_frame(scene, sensors[j]).origin)) continue;
      if (out[j].placement == SensorPlacement::Enclosed) out[i].placement = SensorPlacement::Enclosed;
      out[i].same_volume_as = static_cast<int>(out[j].same_volume_as >= 0 ? out[j].same_volume_as : j);
      shared = true;
    }
    if (!shared) finish_walks(out[i], first_reaching_walk(scene, sensors[i]));
    decided.push_back(i);
  }
  return out;
}

}  // namespace dayphoton::engine
