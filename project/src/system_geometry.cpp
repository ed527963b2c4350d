// Profile extrusion for the daylight-system generators (see system_geometry.h).
#include "system_geometry.h"

#include <algorithm>
#include <cmath>

#include "dayphoton/core/polygon.h"

namespace dayphoton::project::detail {

P2 rotate(P2 p, double angle_rad) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  return {c * p.x - s * p.y, s * p.x + c * p.y};
}

double signed_area2(const std::vector<P2>& profile) {
  double a = 0;
  for (std::size_t i = 0; i < profile.size(); ++i) {
    const P2& p = profile[i];
    const P2& q = profile[(i + 1) % profile.size()];
    a += p.x * q.y - q.x * p.y;
  }
  return a;
}

std::vector<Vec3> facing(std::vector<Vec3> polygon, const Vec3& normal) {
  if (dot(polygon_normal(polygon), normal) < 0) std::reverse(polygon.begin() + 1, polygon.end());
  return polygon;
}

void add_prism(const ProfilePlane& plane, const std::vector<P2>& profile, double c0, double c1,
               const std::vector<int>& edge_materials, int cap_material, const std::string& name,
               const SourceLocation& location, std::vector<Surface>& out) {
  // Outward normal of an edge (dx, dy): on its right for a counter-clockwise profile.
  const double orientation = signed_area2(profile) >= 0 ? 1.0 : -1.0;
  const std::size_t n = profile.size();
  for (std::size_t i = 0; i < n; ++i) {
    const P2 a = profile[i], b = profile[(i + 1) % n];
    const P2 d = b - a;
    const Vec3 outward = plane.direction(P2{d.y, -d.x} * orientation);
    Surface s;
    s.name = name + ".side" + std::to_string(i);
    s.material = edge_materials[i];
    s.vertices = facing({plane.at(a, c0), plane.at(b, c0), plane.at(b, c1), plane.at(a, c1)}, outward);
    s.location = location;
    out.push_back(std::move(s));
  }
  for (int end = 0; end < 2; ++end) {
    Surface s;
    s.name = name + ".cap" + std::to_string(end);
    s.material = cap_material;
    const double c = end == 0 ? c0 : c1;
    for (const P2& p : profile) s.vertices.push_back(plane.at(p, c));
    const double sign = (c1 > c0) == (end == 1) ? 1.0 : -1.0;
    s.vertices = facing(std::move(s.vertices), plane.ac * sign);
    s.location = location;
    out.push_back(std::move(s));
  }
}

void add_strip(const ProfilePlane& plane, const std::vector<P2>& polyline, double c0, double c1,
               int material, const std::string& name, const SourceLocation& location,
               std::vector<Surface>& out) {
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
    const P2 a = polyline[i], b = polyline[i + 1];
    const P2 d = b - a;
    Surface s;
    s.name = polyline.size() == 2 ? name : name + "." + std::to_string(i);
    s.material = material;
    s.vertices = facing({plane.at(a, c0), plane.at(b, c0), plane.at(b, c1), plane.at(a, c1)},
                        plane.direction(P2{-d.y, d.x}));
    s.location = location;
    out.push_back(std::move(s));
  }
}

}  // namespace dayphoton::project::detail
