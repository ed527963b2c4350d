// Local origin of a scene in survey coordinates (rule and reasons in local_origin.h).
#include "dayphoton/project/local_origin.h"

#include <algorithm>
#include <cmath>

namespace dayphoton::project {

Vec3 local_origin_of(const Vec3& lower_m, const Vec3& upper_m) {
  Vec3 origin{0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    if (!(lower_m[k] <= upper_m[k])) return {0, 0, 0};
    // The centre in whole steps; + 0.0 turns a rounded -0 into +0.
    origin[k] = std::round(0.5 * (lower_m[k] + upper_m[k]) / LocalOriginStep_m) * LocalOriginStep_m + 0.0;
  }
  return origin;
}

void move_to_local_origin(SceneDescription& scene) {
  Vec3 lower{HUGE_VAL, HUGE_VAL, HUGE_VAL}, upper{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  auto extend = [&](const Vec3& p) {
    if (!is_finite(p)) return;
    for (int k = 0; k < 3; ++k) {
      lower[k] = std::min(lower[k], p[k]);
      upper[k] = std::max(upper[k], p[k]);
    }
  };
  for (const Surface& s : scene.surfaces)
    for (const Vec3& v : s.vertices) extend(v);
  for (const SensorGrid& g : scene.grids)
    for (const SensorPoint& p : g.points) extend(p.position);
  const Vec3 origin = local_origin_of(lower, upper);
  if (origin == Vec3{0, 0, 0}) return;
  for (Surface& s : scene.surfaces)
    for (Vec3& v : s.vertices) v = v - origin;
  for (SensorGrid& g : scene.grids) {
    for (SensorPoint& p : g.points) p.position = p.position - origin;
    for (Vec3& v : g.outline) v = v - origin;
    g.plane_height_m -= dot(g.plane_normal, origin);
  }
  scene.world_origin_m = scene.world_origin_m + origin;
}

}  // namespace dayphoton::project
