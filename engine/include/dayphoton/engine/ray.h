// Ray and Hit: what the engine's scene queries take and return.
//
// Units and conventions (DESIGN.md section 4): positions in metres, +X east, +Y north, +Z up.
// A ray is origin + t * direction for t in [tmin, tmax]. The direction need not be unit
// length, but t is measured in multiples of |direction|; every dayphoton caller passes unit
// directions, so t is then a distance in metres.
//
// Normals follow the source polygon's winding (counter-clockwise seen from the side the
// normal points to), as in RADIANCE scene files; for rooms they face into the room. A hit is
// "front facing" when the ray arrives on the side the normal points to (dot(d, n) < 0).
//
// Self-intersection: a ray leaving a hit point must start slightly off the surface. Use
// Scene::offset_ray_origin(hit.position, hit.normal, new_direction) (or the free function
// below with Scene::ray_epsilon_m()) and tmin = 0; see scene.h for why that is enough.
#pragma once

#include <cstdint>
#include <limits>

#include "dayphoton/core/vec3.h"

namespace dayphoton::engine {

struct Ray {
  Vec3 origin;     ///< metres
  Vec3 direction;  ///< non-zero; unit length by convention
  double tmin = 0;                                         ///< metres for a unit direction
  double tmax = std::numeric_limits<double>::infinity();   ///< metres for a unit direction
};

struct Hit {
  double t = 0;             ///< ray parameter of the hit (metres for a unit direction)
  Vec3 position;            ///< origin + t * direction, metres (lies on the triangle's plane)
  Vec3 normal;              ///< unit geometric normal of the hit triangle (source winding)
  bool front_face = false;  ///< the ray arrives on the side `normal` points to
  int surface = -1;         ///< index into SceneDescription::surfaces
  int material = -1;        ///< index into SceneDescription::materials
  int port = -1;            ///< index into Scene::ports() if the surface is a port, else -1
  /// Index into Scene::outdoor_scatterers() if the surface is one, else -1.
  int scatterer = -1;
  std::uint32_t primitive = 0;  ///< triangle index, see Scene::triangle()
  /// Barycentrics of the hit in its triangle (v0, v1, v2):
  /// position = (1 - u - v) * v0 + u * v1 + v * v2.
  double u = 0, v = 0;
};

/// Move `position` (on a surface with unit normal `normal`) by `epsilon_m` along the normal,
/// to the side `direction` points to, so that a ray from there in `direction` cannot hit the
/// surface it starts on.
inline Vec3 offset_ray_origin(const Vec3& position, const Vec3& normal, const Vec3& direction,
                              double epsilon_m) {
  return dot(direction, normal) >= 0 ? position + normal * epsilon_m
                                     : position - normal * epsilon_m;
}

}  // namespace dayphoton::engine
