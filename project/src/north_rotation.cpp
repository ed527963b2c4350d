// Model -> world rotation about +Z by the site's angle to true north (convention and
// formula in north_rotation.h).
#include "dayphoton/project/north_rotation.h"

#include <cmath>

#include "dayphoton/core/units.h"

namespace dayphoton::project {

namespace {
Vec3 rotate_ccw_about_z(const Vec3& v, double angle_deg) {
  if (angle_deg == 0) return v;
  double c, s;
  // Quarter turns are exact, so a model rotated by 90 degrees keeps axis-aligned walls
  // exactly axis-aligned (cos(pi/2) is 6e-17 in floating point).
  const double turns = std::fmod(angle_deg, 360.0) / 90.0;
  if (turns == std::floor(turns)) {
    const int q = (static_cast<int>(turns) % 4 + 4) % 4;
    const double cs[4] = {1, 0, -1, 0};
    const double sn[4] = {0, 1, 0, -1};
    c = cs[q];
    s = sn[q];
  } else {
    const double a = deg_to_rad(angle_deg);
    c = std::cos(a);
    s = std::sin(a);
  }
  return {v.x * c - v.y * s, v.x * s + v.y * c, v.z};
}
}  // namespace

Vec3 model_to_world(const Vec3& v, double rotation_to_true_north_deg) {
  return rotate_ccw_about_z(v, rotation_to_true_north_deg);
}

Vec3 world_to_model(const Vec3& v, double rotation_to_true_north_deg) {
  return rotate_ccw_about_z(v, -rotation_to_true_north_deg);
}

}  // namespace dayphoton::project
