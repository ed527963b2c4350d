// PortBound: a sphere holding every triangle of a port, so that a ray which misses it is
// known to cross none of them without a ray-triangle test per triangle. The direct
// component's port-sampling density (docs/direct-component.md) asks, for every sampled
// direction, which of the ports the ray crosses; with 20 windows a ray crosses one or two,
// and the sphere test (a few products) rules out the others.
//
// The test is conservative: the sphere is about the port's centroid through its farthest
// vertex, its squared radius widened by a relative 1e-6 (plus 1e-12 m^2), far above the
// rounding of the test and of the ray-triangle intersection, so a ray that crosses a
// triangle is never ruled out and the density, and every result, is unchanged.
#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/port_set.h"

namespace dayphoton::engine {

struct PortBound {
  Vec3 centre{0, 0, 0};
  double radius2_m2 = std::numeric_limits<double>::infinity();

  /// False only if no point of the sphere lies on the ray origin + t w with t > 0.
  bool may_cross(const Vec3& origin, const Vec3& w) const {
    const Vec3 v = centre - origin;
    const double ww = dot(w, w);
    const double along = dot(v, w);
    if (along < 0 && along * along > radius2_m2 * ww) return false;  // wholly behind the origin
    return dot(v, v) - along * along / ww <= radius2_m2;              // the line's distance
  }
};

/// The bound of every port of `ports`, in order. A port whose centroid is not finite (no
/// area) gets an infinite sphere: never ruled out.
inline std::vector<PortBound> port_bounds(const PortSet& ports) {
  std::vector<PortBound> bounds(ports.size());
  for (std::size_t j = 0; j < ports.size(); ++j) {
    const Vec3 c = ports[j].centroid;
    if (!is_finite(c)) continue;
    double r2 = 0;
    for (const std::array<Vec3, 3>& tri : ports[j].triangles)
      for (const Vec3& v : tri) r2 = std::max(r2, dot(v - c, v - c));
    bounds[j].centre = c;
    bounds[j].radius2_m2 = r2 * (1 + 1e-6) + 1e-12;
  }
  return bounds;
}

}  // namespace dayphoton::engine
