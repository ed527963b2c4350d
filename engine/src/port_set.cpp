// PortSet: uniform area sampling of photon ports. Method and sources: see port_set.h
// (Schregle thesis, seeds/000 section 4.1.3; PBRT 4th ed. section A.5.5 for the triangle warp).
#include "dayphoton/engine/port_set.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dayphoton/core/polygon.h"

namespace dayphoton::engine {

int PortSet::add(int surface_index, const Surface& surface,
                 const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  Port port;
  port.surface = surface_index;
  port.name = surface.name;
  port.location = surface.location;
  port.normal = polygon_normal(surface.vertices);
  Vec3 weighted_centroid{0, 0, 0};
  for (const auto& tri : triangles) {
    const Vec3& a = surface.vertices.at(tri[0]);
    const Vec3& b = surface.vertices.at(tri[1]);
    const Vec3& c = surface.vertices.at(tri[2]);
    const double area_m2 = 0.5 * length(cross(b - a, c - a));
    if (!(area_m2 > 0)) continue;  // zero-area ear at collinear vertices: covers nothing
    port.triangles.push_back({a, b, c});
    port.area_m2 += area_m2;
    port.cumulative_area_m2.push_back(port.area_m2);
    weighted_centroid += (a + b + c) * (area_m2 / 3.0);
  }
  if (!(port.area_m2 > 0))
    throw std::invalid_argument("port '" + surface.name + "' has zero area");
  port.centroid = weighted_centroid / port.area_m2;
  // A parallelogram v0 + s (v1 - v0) + t (v3 - v0): v0 + v2 = v1 + v3 (to rounding).
  const std::vector<Vec3>& v = surface.vertices;
  if (v.size() == 4) {
    const Vec3 gap = (v[0] + v[2]) - (v[1] + v[3]);
    const double scale = std::max(length(v[1] - v[0]), length(v[3] - v[0]));
    const double area_m2 = length(cross(v[1] - v[0], v[3] - v[0]));
    if (length(gap) <= 1e-9 * scale && std::fabs(area_m2 - port.area_m2) <= 1e-9 * port.area_m2)
      port.parallelogram = std::array<Vec3, 3>{v[0], v[1] - v[0], v[3] - v[0]};
  }
  m_ports.push_back(std::move(port));
  return static_cast<int>(m_ports.size()) - 1;
}

double PortSet::total_area_m2() const {
  double sum = 0;
  for (const auto& p : m_ports) sum += p.area_m2;
  return sum;
}

int PortSet::port_of_surface(int surface_index) const {
  for (std::size_t i = 0; i < m_ports.size(); ++i)
    if (m_ports[i].surface == surface_index) return static_cast<int>(i);
  return -1;
}

void PortSet::orient(std::size_t port_index, bool against_winding, PortSideReason reason,
                     double sky_fraction_winding, double sky_fraction_opposite) {
  Port& port = m_ports.at(port_index);
  if (port.against_winding != against_winding) port.normal = port.normal * -1.0;
  port.against_winding = against_winding;
  port.side_reason = reason;
  port.sky_fraction_winding = sky_fraction_winding;
  port.sky_fraction_opposite = sky_fraction_opposite;
}

PortSample PortSet::sample(std::size_t port_index, double u1, double u2) const {
  if (port_index >= m_ports.size())
    throw std::out_of_range("port index " + std::to_string(port_index) + " out of range (" +
                            std::to_string(m_ports.size()) + " ports)");
  const Port& port = m_ports[port_index];
  // Pick a triangle with probability area_i / area, then reuse u1 rescaled to [0, 1).
  const double target_m2 = u1 * port.area_m2;
  const auto it =
      std::upper_bound(port.cumulative_area_m2.begin(), port.cumulative_area_m2.end(), target_m2);
  const std::size_t i = std::min<std::size_t>(
      static_cast<std::size_t>(it - port.cumulative_area_m2.begin()), port.triangles.size() - 1);
  const double before_m2 = i == 0 ? 0.0 : port.cumulative_area_m2[i - 1];
  const double area_i_m2 = port.cumulative_area_m2[i] - before_m2;
  const double w = std::clamp((target_m2 - before_m2) / area_i_m2, 0.0, 1.0);
  // Square-root warp: uniform by area in the triangle.
  const double s = std::sqrt(w);
  const double b0 = 1.0 - s;
  const double b1 = u2 * s;
  const auto& t = port.triangles[i];
  PortSample out;
  out.position = t[0] * b0 + t[1] * b1 + t[2] * (1.0 - b0 - b1);
  out.normal = port.normal;
  out.pdf_per_m2 = 1.0 / port.area_m2;
  return out;
}

}  // namespace dayphoton::engine
