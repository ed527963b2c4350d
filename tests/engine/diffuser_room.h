// A black room whose only opening is a Lambertian diffuser facing a far black wall, for the
// tests of the photon part on the sky's shape (tests/engine/photon_part_on_sky_test.cpp,
// tests/study/point_in_time_photon_part_test.cpp): every photon in the room crossed the
// diffuser, so what reaches a sensor is the diffuser's irradiance times a constant.
#pragma once

#include <cmath>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/vec3.h"
#include "test_scenes.h"

namespace dayphoton::engine::test {

/// A black wall OpposingDistance_m in front of the window, up to OpposingTop_m: from the window
/// (whose height it sees within 0.11 degrees alike) it hides the sky below 6 degrees, half of the
/// lowest Tregenza band, where the overcast sky's radiance is lowest.
constexpr double OpposingDistance_m = 500, OpposingHalfWidth_m = 5000;
inline const double OpposingTop_m = 1.0 + OpposingDistance_m * std::tan(6.0 * 3.14159265358979323846 / 180.0);

/// Whether the opposing wall hides direction w (toward the sky) from the window's centre.
inline bool hidden_by_opposing_wall(const Vec3& w) {
  if (w.y <= 0) return false;
  const double t = OpposingDistance_m / w.y;
  const double z = 1.0 + t * w.z;
  return z >= -1.0 && z <= OpposingTop_m && std::fabs(t * w.x) <= OpposingHalfWidth_m;
}

/// x [-3, 3], y [-3, 2], z [-1, 3], every surface black, the north wall's window (y = 2,
/// x [-1, 1], z [0.5, 1.5], facing +y) a Lambertian diffuser (translucent: colour 0.8,
/// transmissivity 0.75, transmitted specular 0), and the opposing wall.
inline SceneDescription diffuser_room() {
  SceneDescription d;
  const int black = add_material(d, "black", MaterialType::Lambertian, 0.0);
  MaterialSpec diffuser;
  diffuser.name = "diffuser";
  diffuser.type = MaterialType::Translucent;
  diffuser.reflectance = {0.8, 0.8, 0.8};
  diffuser.transmissivity = 0.75;
  diffuser.transmitted_specular = 0.0;
  d.materials.push_back(diffuser);
  add_window_room(d, black, static_cast<int>(d.materials.size()) - 1);
  const double y = 2 + OpposingDistance_m, w = OpposingHalfWidth_m;
  add_surface(d, "opposing", black, {{w, y, -1}, {-w, y, -1}, {-w, y, OpposingTop_m}, {w, y, OpposingTop_m}});
  return d;
}

}  // namespace dayphoton::engine::test
