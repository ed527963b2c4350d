// ReceiverPlane: see receiver_plane.h. The disc/polygon area is the sum over the outline's
// edges of the signed area of (disc centred at the origin) intersected with the triangle
// (origin, a, b): each edge is split where it crosses the circle; pieces inside contribute
// their triangle area, pieces outside the circular sector they subtend.
#include "dayphoton/engine/receiver_plane.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dayphoton::engine {
namespace {

double cross2(const PlanePoint& a, const PlanePoint& b) { return a.x * b.y - a.y * b.x; }

// Signed area of disc(0, r) intersected with triangle (0, a, b).
double disc_triangle_area(PlanePoint a, PlanePoint b, double r) {
  const double r2 = r * r;
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double qa = dx * dx + dy * dy;
  auto sector = [&](const PlanePoint& p, const PlanePoint& q) {
    return 0.5 * r2 * std::atan2(cross2(p, q), p.x * q.x + p.y * q.y);
  };
  if (qa <= 0) return 0;
  // Points a + s (b - a) on the circle: qa s^2 + 2 qb s + qc = 0.
  const double qb = a.x * dx + a.y * dy;
  const double qc = a.x * a.x + a.y * a.y - r2;
  const double disc = qb * qb - qa * qc;
  if (disc <= 0) return sector(a, b);  // the line misses the circle: all outside
  const double root = std::sqrt(disc);
  const double s1 = std::clamp((-qb - root) / qa, 0.0, 1.0);
  const double s2 = std::clamp((-qb + root) / qa, 0.0, 1.0);
  const PlanePoint p1{a.x + s1 * dx, a.y + s1 * dy};
  const PlanePoint p2{a.x + s2 * dx, a.y + s2 * dy};
  // a..p1 outside (sector), p1..p2 inside (triangle), p2..b outside (sector).
  return sector(a, p1) + 0.5 * cross2(p1, p2) + sector(p2, b);
}

}  // namespace

ReceiverPlane ReceiverPlane::from_grid(const SensorGrid& grid) {
  if (!grid.planar || std::fabs(std::fabs(grid.plane_normal.z) - 1) > 1e-12)
    throw std::invalid_argument("sensor grid '" + grid.name + "' is not a horizontal plane");
  std::vector<PlanePoint> outline;
  for (const Vec3& v : grid.outline) outline.push_back({v.x, v.y});
  const bool up = grid.plane_normal.z > 0;
  // plane_height_m is the signed distance along the normal: z = height * normal.z.
  return ReceiverPlane(grid.plane_height_m * grid.plane_normal.z, up, std::move(outline));
}

ReceiverPlane::ReceiverPlane(double z_m, bool faces_up, std::vector<PlanePoint> outline)
    : m_z_m(z_m), m_faces_up(faces_up), m_outline(std::move(outline)) {
  if (m_outline.size() < 3) throw std::invalid_argument("receiver plane outline needs 3 points");
  m_min_x = m_max_x = m_outline[0].x;
  m_min_y = m_max_y = m_outline[0].y;
  for (const PlanePoint& p : m_outline) {
    m_min_x = std::min(m_min_x, p.x);
    m_max_x = std::max(m_max_x, p.x);
    m_min_y = std::min(m_min_y, p.y);
    m_max_y = std::max(m_max_y, p.y);
  }
}

double ReceiverPlane::front_crossing(const Vec3& origin, const Vec3& direction) const {
  const double dz = direction.z;
  // Front side: arriving against the normal (moving down onto an upward plane).
  if (m_faces_up ? dz >= 0 : dz <= 0) return -1;
  return (m_z_m - origin.z) / dz;
}

bool ReceiverPlane::contains(double x, double y) const {
  if (x < m_min_x || x > m_max_x || y < m_min_y || y > m_max_y) return false;
  bool inside = false;
  const std::size_t n = m_outline.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const PlanePoint& a = m_outline[i];
    const PlanePoint& b = m_outline[j];
    if ((a.y > y) != (b.y > y) && x < (b.x - a.x) * (y - a.y) / (b.y - a.y) + a.x)
      inside = !inside;
  }
  return inside;
}

double ReceiverPlane::disc_area_inside_m2(double x, double y, double r_m) const {
  if (r_m <= 0) return 0;
  double area = 0;
  const std::size_t n = m_outline.size();
  for (std::size_t i = 0; i < n; ++i) {
    const PlanePoint& a = m_outline[i];
    const PlanePoint& b = m_outline[(i + 1) % n];
    area += disc_triangle_area({a.x - x, a.y - y}, {b.x - x, b.y - y}, r_m);
  }
  return std::fabs(area);  // the outline may wind either way
}

}  // namespace dayphoton::engine
