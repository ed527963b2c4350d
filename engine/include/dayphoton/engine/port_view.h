// PortView: the ports as seen from one point, to tell cheaply that a shadow ray toward the
// sky cannot succeed. sky_transmittance (direct_component.h) is zero for a ray that crosses
// no port, whatever else it meets; so if a whole cone of directions misses every port
// triangle, every ray in it has zero sky transmittance and need not be traced.
//
// The test is exact geometry with a safety margin, never an approximation: seen from the
// origin o, a triangle (a, b, c) in front of it covers the directions w with
// dot(w, m_e) >= 0 for its three edge planes through o, m_e = (a - o) x (b - o) oriented
// toward the third vertex (the cone spanned by three independent vectors is the intersection
// of the three half-spaces bounded by its faces). A cone of half-angle alpha about w_c misses
// the triangle if, for one edge, w_c lies more than alpha beyond that edge plane:
// dot(w_c, m_e) < -sin(alpha). The margin widens alpha by asin(pad / d), d the distance from
// o to the triangle's plane, for the ways a traced ray departs from the ideal line:
// Embree's single-precision vertices, origins and directions (1e-6 x the scene's scale), and,
// when a non-port surface of the scene transmits light straight through (an interior
// window), the sideways offset of each crossing before a port (2 ray epsilons per crossing,
// up to MaxShadowRayCrossings). A triangle whose plane passes within the margin of o is never
// ruled out. Each port is first tested as a whole against the cone that holds its bounding
// sphere, so the cost per query grows with the ports near the direction, not with all their
// triangles.
#pragma once

#include <array>
#include <vector>

#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/scene.h"

namespace dayphoton::engine {

class PortView {
 public:
  /// The ports of `scene` seen from `origin` (a shadow ray's start), with the sideways
  /// margin `pad_m` (port_view_pad_m, computed once per scene). The queries at
  /// `usual_half_angle_rad` (a single ray: 0; the sun's disc) find their cosines and sines
  /// computed here, by the same expressions, so they cost no trigonometry; any other
  /// half-angle computes them per query. The answers do not depend on it.
  PortView(const Scene& scene, const Vec3& origin, double pad_m, double usual_half_angle_rad = 0);

  /// False only if no ray from the origin within `half_angle_rad` of the unit vector
  /// `direction` can cross a port, so each has zero sky transmittance. True otherwise
  /// (which does not mean a ray will reach the sky).
  bool may_cross_port(const Vec3& direction, double half_angle_rad) const;

 private:
  struct Triangle {
    std::array<Vec3, 3> edge_normals;  ///< unit m_e, pointing into the triangle's cone
    double margin_rad = 0;             ///< asin(pad / d), or >= pi/2: never ruled out
    double sin_usual_widened = 0;      ///< sin(usual half-angle + margin_rad)
  };
  /// A port's triangles [first, last) and the cone about `axis` that holds all of them
  /// (their bounding sphere, widened by the pad, seen from the origin): a cone of directions
  /// farther than half_angle_rad from the axis misses the port without a triangle test.
  struct PortCone {
    Vec3 axis;
    double half_angle_rad = 0;  ///< >= pi: the origin is inside the sphere
    double cos_usual_reach = -1;  ///< cos(half_angle_rad + usual half-angle)
    std::size_t first = 0, last = 0;
  };
  bool may_cross(const PortCone& port, const Vec3& direction, double half_angle_rad) const;

  double m_usual_half_angle_rad = 0;
  std::vector<Triangle> m_triangles;
  std::vector<PortCone> m_ports;
};

/// The margin of the header comment for `scene`, metres.
double port_view_pad_m(const Scene& scene, const std::vector<Material>& materials);

/// True if `material` passes light straight through (its straight transmittance is non-zero
/// at normal or oblique incidence): glass, glazing, an opening, a dielectric.
bool transmits_straight(const Material& material);

/// True if some non-port surface of `scene` passes light straight through (its material's
/// straight transmittance is non-zero at normal or oblique incidence): a shadow ray may then
/// cross surfaces before it reaches a port.
bool has_straight_transmitting_non_port(const Scene& scene, const std::vector<Material>& materials);

}  // namespace dayphoton::engine
