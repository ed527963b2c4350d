// PortView: see port_view.h for the test and its margin.
#include "dayphoton/engine/port_view.h"

#include <algorithm>
#include <cmath>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/direct_component.h"

namespace dayphoton::engine {
namespace {

/// Embree's single-precision vertices, origins and directions, as a length relative to the
/// ray epsilon (1e-5 x the scene's scale): 1e-6 x the scale covers a few float ulps of every
/// coordinate and of a direction over the scene's size.
constexpr double FloatPadEpsilons = 0.1;

}  // namespace

bool transmits_straight(const Material& material) {
  for (const Vec3& incoming : {Vec3{0, 0, -1}, normalize(Vec3{1, 0, -0.2})}) {
    const Vec3 t = material.straight_transmittance(incoming, {0, 0, 1});
    if (t.x > 0 || t.y > 0 || t.z > 0) return true;
  }
  return false;
}

bool has_straight_transmitting_non_port(const Scene& scene, const std::vector<Material>& materials) {
  const std::vector<Surface>& surfaces = scene.description().surfaces;
  for (std::size_t i = 0; i < surfaces.size(); ++i)
    if (!scene.is_port(static_cast<int>(i)) &&
        transmits_straight(materials.at(static_cast<std::size_t>(surfaces[i].material))))
      return true;
  return false;
}

double port_view_pad_m(const Scene& scene, const std::vector<Material>& materials) {
  const double crossings = has_straight_transmitting_non_port(scene, materials) ? MaxShadowRayCrossings + 1 : 0;
  return scene.ray_epsilon_m() * (FloatPadEpsilons + 2.0 * crossings);
}

PortView::PortView(const Scene& scene, const Vec3& origin, double pad, double usual_half_angle_rad)
    : m_usual_half_angle_rad(usual_half_angle_rad) {
  for (const Port& port : scene.ports().ports()) {
    PortCone cone;
    cone.first = m_triangles.size();
    double radius = 0;
    for (const std::array<Vec3, 3>& tri : port.triangles)
      for (const Vec3& v : tri) radius = std::max(radius, length(v - port.centroid));
    radius += pad;
    const Vec3 to_centre = port.centroid - origin;
    const double distance = length(to_centre);
    cone.axis = distance > 0 ? to_centre / distance : Vec3{0, 0, 1};
    cone.half_angle_rad = distance > radius ? std::asin(radius / distance) : Pi;
    cone.cos_usual_reach = std::cos(cone.half_angle_rad + usual_half_angle_rad);
    for (const std::array<Vec3, 3>& tri : port.triangles) {
      Triangle t;
      const Vec3 a[3] = {tri[0] - origin, tri[1] - origin, tri[2] - origin};
      const Vec3 plane_normal = cross(tri[1] - tri[0], tri[2] - tri[0]);
      const double d = std::fabs(dot(a[0], plane_normal)) / length(plane_normal);
      t.margin_rad = d > pad ? std::asin(pad / d) : Pi;
      for (int e = 0; e < 3 && t.margin_rad < Pi; ++e) {
        Vec3 m = cross(a[e], a[(e + 1) % 3]);
        const double len = length(m);
        if (!(len > 0)) {
          t.margin_rad = Pi;  // an edge in line with the origin: never ruled out
          break;
        }
        m = m / len;
        if (dot(m, a[(e + 2) % 3]) < 0) m = m * -1.0;
        t.edge_normals[static_cast<std::size_t>(e)] = m;
      }
      t.sin_usual_widened = std::sin(usual_half_angle_rad + t.margin_rad);
      m_triangles.push_back(t);
    }
    cone.last = m_triangles.size();
    m_ports.push_back(cone);
  }
}

bool PortView::may_cross_port(const Vec3& direction, double half_angle_rad) const {
  for (const PortCone& port : m_ports) {
    const double reach = port.half_angle_rad + half_angle_rad;
    // Farther from the axis than `reach` (cos below cos(reach)): the port is missed. At the
    // usual half-angle the cosine was computed once, by the same expression.
    if (reach < Pi &&
        dot(direction, port.axis) < (half_angle_rad == m_usual_half_angle_rad ? port.cos_usual_reach : std::cos(reach)))
      continue;
    if (may_cross(port, direction, half_angle_rad)) return true;
  }
  return false;
}

bool PortView::may_cross(const PortCone& port, const Vec3& direction, double half_angle_rad) const {
  for (std::size_t i = port.first; i < port.last; ++i) {
    const Triangle& t = m_triangles[i];
    const double widened = half_angle_rad + t.margin_rad;
    if (!(widened < 0.5 * Pi)) return true;
    const double limit = half_angle_rad == m_usual_half_angle_rad ? -t.sin_usual_widened : -std::sin(widened);
    bool outside = false;
    for (const Vec3& m : t.edge_normals)
      if (dot(direction, m) < limit) {
        outside = true;
        break;
      }
    if (!outside) return true;
  }
  return false;
}

}  // namespace dayphoton::engine
