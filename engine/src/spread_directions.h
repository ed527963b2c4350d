// Well-spread directions for the placement tests (port_facing.cpp, sensor_placement.cpp):
// `count` unit directions over the hemisphere about `normal`, uniform in solid angle, on a
// spherical Fibonacci lattice (Keinert, Innmann, Saenger & Stamminger, "Spherical Fibonacci
// Mapping", ACM TOG 34(6), 2015, section 3: cos(theta_i) = 1 - (i + 1/2) / count on the
// hemisphere, phi_i = 2 pi i / golden ratio). Deterministic, so a test gives the same answer
// every time, and no two directions cluster as random ones do.
#pragma once

#include <cmath>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/core/vec3.h"

namespace dayphoton::engine::detail {

inline std::vector<Vec3> hemisphere_directions(const Vec3& normal, int count) {
  const Vec3 n = normalize(normal);
  // An orthonormal frame about n (Duff et al., "Building an Orthonormal Basis, Revisited",
  // JCGT 6(1), 2017).
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z), b = n.x * n.y * a;
  const Vec3 t{1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
  const Vec3 bt{b, sign + n.y * n.y * a, -n.y};
  const double golden = 0.5 * (1.0 + std::sqrt(5.0));
  std::vector<Vec3> out;
  out.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const double cos_theta = 1.0 - (i + 0.5) / count;
    const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
    const double phi = 2.0 * Pi * std::fmod(i / golden, 1.0);
    out.push_back(normalize(t * (sin_theta * std::cos(phi)) + bt * (sin_theta * std::sin(phi)) + n * cos_theta));
  }
  return out;
}

}  // namespace dayphoton::engine::detail
