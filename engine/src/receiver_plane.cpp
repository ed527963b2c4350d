// ReceiverPlane: see receiver_plane.h. The disc/polygon area is the sum over the outline's
// edges of the signed area of (disc centred at the origin) intersected with the triangle
// (origin, a, b): each edge is split where it crosses the circle; pieces inside contribute
// their triangle area, pieces outside the circular sector they subtend.
// clipped_disc_moments uses Green's theorem, int int f dA = closed integral over the boundary,
// oriented counter-clockwise: A = 1/2 (x dy - y dx), int x = 1/2 x^2 dy, int y = -1/2 y^2 dx,
// int x^2 = 1/3 x^3 dy, int y^2 = -1/3 y^3 dx, int xy = 1/2 x^2 y dy. On straight pieces the
// integrands are cubic polynomials of the parameter (3-point Gauss-Legendre is exact); on arcs
// they are integrated in closed form.
#include "dayphoton/engine/receiver_plane.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "dayphoton/core/units.h"

namespace dayphoton::engine {
namespace {

double cross2(const PlanePoint& a, const PlanePoint& b) { return a.x * b.y - a.y * b.x; }

// Twice the signed area of a polygon (shoelace formula): positive when counter-clockwise.
double outline_area_signed_twice(const std::vector<PlanePoint>& outline) {
  double twice = 0;
  for (std::size_t i = 0; i < outline.size(); ++i) twice += cross2(outline[i], outline[(i + 1) % outline.size()]);
  return twice;
}

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

// Green's-theorem contributions of the straight piece p -> q.
void add_segment(AreaMoments& m, const PlanePoint& p, const PlanePoint& q) {
  const double dx = q.x - p.x, dy = q.y - p.y;
  m.area += 0.5 * (p.x * q.y - p.y * q.x);
  static const double node[3] = {0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6)};
  static const double weight[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
  for (int k = 0; k < 3; ++k) {
    const double x = p.x + node[k] * dx, y = p.y + node[k] * dy, w = weight[k];
    m.mx += w * 0.5 * x * x * dy;
    m.my += w * -0.5 * y * y * dx;
    m.mxx += w * x * x * x * dy / 3.0;
    m.myy += w * -y * y * y * dx / 3.0;
    m.mxy += w * 0.5 * x * x * y * dy;
  }
}

// The antiderivatives' differences F(t1) - F(t0) an arc from angle t0 to t1 needs: of cos^3,
// sin^3, cos^4, sin^4 and cos^3 sin.
struct ArcTrig {
  double cos3 = 0, sin3 = 0, cos4 = 0, sin4 = 0, cos3sin = 0;
};

ArcTrig arc_trig(double t0, double t1) {
  auto cos3 = [](double t) { const double s = std::sin(t); return s - s * s * s / 3.0; };
  auto sin3 = [](double t) { const double c = std::cos(t); return -c + c * c * c / 3.0; };
  auto cos4 = [](double t) { return 3.0 * t / 8.0 + std::sin(2 * t) / 4.0 + std::sin(4 * t) / 32.0; };
  auto sin4 = [](double t) { return 3.0 * t / 8.0 - std::sin(2 * t) / 4.0 + std::sin(4 * t) / 32.0; };
  auto cos3sin = [](double t) { const double c = std::cos(t); return -c * c * c * c / 4.0; };
  return {cos3(t1) - cos3(t0), sin3(t1) - sin3(t0), cos4(t1) - cos4(t0), sin4(t1) - sin4(t0),
          cos3sin(t1) - cos3sin(t0)};
}

// Contributions of the counter-clockwise arc of radius r from angle t0 to t1 (t1 > t0);
// `d` = arc_trig(t0, t1).
void add_arc(AreaMoments& m, double r, double t0, double t1, const ArcTrig& d) {
  const double r2 = r * r, r3 = r2 * r, r4 = r2 * r2;
  m.area += 0.5 * r2 * (t1 - t0);
  m.mx += 0.5 * r3 * d.cos3;
  m.my += 0.5 * r3 * d.sin3;
  m.mxx += r4 / 3.0 * d.cos4;
  m.myy += r4 / 3.0 * d.sin4;
  m.mxy += 0.5 * r4 * d.cos3sin;
}

}  // namespace

namespace {

/// Walks the boundary of the disc of radius r about the origin clipped to `poly` (the outline
/// relative to the disc's centre, counter-clockwise): `segment(p, q)` for every outline piece
/// inside the disc, `arc(t0, t1)` for every circle arc inside the outline (`inside(angle)`
/// says whether the arc's midpoint lies inside). Returns false when the circle crosses no
/// edge (the disc wholly inside or outside the outline, or the outline inside the disc,
/// whose edges were passed to `segment`). `crossings` is working storage.
template <class Segment, class Arc, class Inside>
bool walk_clipped_disc(const std::vector<PlanePoint>& poly, double r, std::vector<double>& crossings,
                       Segment segment, Arc arc, Inside inside) {
  crossings.clear();
  const double r2 = r * r;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const PlanePoint a = poly[i], b = poly[(i + 1) % poly.size()];
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double qa = dx * dx + dy * dy;
    if (qa <= 0) continue;
    const double qb = a.x * dx + a.y * dy, qc = a.x * a.x + a.y * a.y - r2;
    double cuts[4] = {0.0, 0.0, 0.0, 0.0};
    std::size_t cut_count = 1;
    const double disc = qb * qb - qa * qc;
    if (disc > 0) {
      const double root = std::sqrt(disc);
      for (double t : {(-qb - root) / qa, (-qb + root) / qa})
        if (t > 0 && t < 1) {
          cuts[cut_count++] = t;
          crossings.push_back(std::atan2(a.y + t * dy, a.x + t * dx));
        }
    }
    cuts[cut_count++] = 1.0;
    for (std::size_t k = 0; k + 1 < cut_count; ++k) {
      const double tm = 0.5 * (cuts[k] + cuts[k + 1]);
      const double mx = a.x + tm * dx, my = a.y + tm * dy;
      if (mx * mx + my * my < r2)
        segment(PlanePoint{a.x + cuts[k] * dx, a.y + cuts[k] * dy},
                PlanePoint{a.x + cuts[k + 1] * dx, a.y + cuts[k + 1] * dy});
    }
  }
  if (crossings.empty()) return false;
  std::sort(crossings.begin(), crossings.end());
  for (std::size_t k = 0; k < crossings.size(); ++k) {
    const double t0 = crossings[k];
    const double t1 = k + 1 < crossings.size() ? crossings[k + 1] : crossings[0] + 2 * Pi;
    if (t1 > t0 && inside(0.5 * (t0 + t1))) arc(t0, t1);
  }
  return true;
}

/// The outline relative to (x, y), scaled by 1 / scale, counter-clockwise, into `poly`.
void centred_outline(const std::vector<PlanePoint>& outline, double x, double y, double scale,
                     std::vector<PlanePoint>& poly) {
  poly.clear();
  for (const PlanePoint& p : outline) poly.push_back({(p.x - x) / scale, (p.y - y) / scale});
  if (outline_area_signed_twice(poly) < 0) std::reverse(poly.begin(), poly.end());
}

/// int_{t0}^{t1} cos^m t sin^n t dt by the reduction formulas (Gradshteyn and Ryzhik 2.510,
/// 2.513): for n >= 2, (m + n) J(m, n) = -[cos^(m+1) sin^(n-1)] + (n - 1) J(m, n - 2);
/// J(m, 1) = -[cos^(m+1)] / (m + 1); for m >= 2, m J(m, 0) = [cos^(m-1) sin] + (m - 1) J(m - 2, 0).
double cos_sin_integral(int m, int n, double t0, double t1) {
  const double c0 = std::cos(t0), s0 = std::sin(t0), c1 = std::cos(t1), s1 = std::sin(t1);
  auto bracket = [&](int pc, int ps) { return std::pow(c1, pc) * std::pow(s1, ps) - std::pow(c0, pc) * std::pow(s0, ps); };
  if (n >= 2) return (-bracket(m + 1, n - 1) + (n - 1) * cos_sin_integral(m, n - 2, t0, t1)) / (m + n);
  if (n == 1) return -bracket(m + 1, 0) / (m + 1);
  if (m >= 2) return (bracket(m - 1, 1) + (m - 1) * cos_sin_integral(m - 2, 0, t0, t1)) / m;
  if (m == 1) return s1 - s0;
  return t1 - t0;
}

}  // namespace

AreaMoments ReceiverPlane::clipped_disc_moments(double x, double y, double r_m) const {
  AreaMoments m;
  if (!(r_m > 0)) return m;
  // The outline relative to the centre, counter-clockwise. The working lists are reused per
  // thread: this runs once per k-nearest lookup, so allocations would cost as much as the
  // arithmetic.
  thread_local std::vector<PlanePoint> poly;
  thread_local std::vector<double> crossings;  // angles where the circle meets the outline
  centred_outline(m_outline, x, y, 1.0, poly);
  const bool crossed = walk_clipped_disc(
      poly, r_m, crossings, [&m](const PlanePoint& p, const PlanePoint& q) { add_segment(m, p, q); },
      [&m, r_m](double t0, double t1) { add_arc(m, r_m, t0, t1, arc_trig(t0, t1)); },
      [&](double tm) { return contains(x + r_m * std::cos(tm), y + r_m * std::sin(tm)); });
  if (!crossed) {
    // Whole disc inside the outline, or disjoint (or the outline inside the disc, whose
    // edges were added above).
    // The whole circle's trigonometric terms do not depend on the radius: computed once
    // (the disc lies wholly inside the outline at most sensors).
    static const ArcTrig whole = arc_trig(0.0, 2 * Pi);
    if (contains(x, y) && m.area == 0) add_arc(m, r_m, 0.0, 2 * Pi, whole);
  }
  return m;
}

ScaledMoments4 ReceiverPlane::clipped_disc_moments4(double x, double y, double r_m) const {
  // Green's theorem on the clipped unit disc (coordinates (q - p) / r): int int u^a v^b dA =
  // closed integral of u^(a+1) v^b / (a + 1) dv. On straight pieces the integrand is a
  // polynomial of degree a + b + 1 <= 5 in the parameter (3-point Gauss-Legendre is exact);
  // on the unit circle it is cos^(a+2) t sin^b t / (a + 1) dt.
  ScaledMoments4 m;
  if (!(r_m > 0)) return m;
  thread_local std::vector<PlanePoint> poly;
  thread_local std::vector<double> crossings;
  centred_outline(m_outline, x, y, r_m, poly);
  auto add_piece = [&m](const PlanePoint& p, const PlanePoint& q) {
    static const double node[3] = {0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6)};
    static const double weight[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
    const double dx = q.x - p.x, dy = q.y - p.y;
    for (int k = 0; k < 3; ++k) {
      const double u = p.x + node[k] * dx, v = p.y + node[k] * dy;
      for (int a = 0; a <= 4; ++a)
        for (int b = 0; a + b <= 4; ++b)
          m.at(a, b) += weight[k] * std::pow(u, a + 1) * std::pow(v, b) / (a + 1) * dy;
    }
  };
  auto add_circle_arc = [&m](double t0, double t1) {
    for (int a = 0; a <= 4; ++a)
      for (int b = 0; a + b <= 4; ++b) m.at(a, b) += cos_sin_integral(a + 2, b, t0, t1) / (a + 1);
  };
  const bool crossed = walk_clipped_disc(
      poly, 1.0, crossings, add_piece, add_circle_arc,
      [&](double tm) { return contains(x + r_m * std::cos(tm), y + r_m * std::sin(tm)); });
  if (!crossed && contains(x, y) && m.at(0, 0) == 0) add_circle_arc(0.0, 2 * Pi);
  return m;
}

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
  // Reflex vertices: the turn at the vertex is against the outline's winding.
  const std::size_t n = m_outline.size();
  const double winding = outline_area_signed_twice(m_outline) >= 0 ? 1.0 : -1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const PlanePoint& prev = m_outline[(i + n - 1) % n];
    const PlanePoint& at = m_outline[i];
    const PlanePoint& next = m_outline[(i + 1) % n];
    const double turn = (at.x - prev.x) * (next.y - at.y) - (at.y - prev.y) * (next.x - at.x);
    if (turn * winding < 0) m_reflex.push_back(at);
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

double distance_to_segment_m(double x, double y, const PlanePoint& a, const PlanePoint& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  const double t = length2 > 0 ? std::clamp(((x - a.x) * dx + (y - a.y) * dy) / length2, 0.0, 1.0) : 0.0;
  return std::hypot(x - (a.x + t * dx), y - (a.y + t * dy));
}

double ReceiverPlane::outline_area_m2() const { return 0.5 * std::fabs(outline_area_signed_twice(m_outline)); }

}  // namespace dayphoton::engine
