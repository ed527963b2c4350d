// Planar polygon utilities (see polygon.h).
//
// - Normal and area: Newell's method (M. E. Newell, 1972; as given in F. S. Hill, "Computer
//   Graphics", and Foley et al. 2nd ed. section 11.1.1): N = sum over edges (y_i - y_j)(z_i + z_j),
//   ... whose magnitude is twice the vector area. Robust for non-convex and slightly
//   non-planar polygons, and exact for planar simple ones.
// - Triangulation: ear clipping (G. H. Meisters, "Polygons have ears", Amer. Math. Monthly 82,
//   1975), done in a 2D frame (u, v) with u x v = polygon normal, so counter-clockwise in the
//   frame is counter-clockwise about the normal and every emitted triangle keeps the winding.
//   Before clipping, consecutive duplicate vertices and collinear (zero-angle) corners are
//   dropped; they add no area. Tolerances are relative to the polygon's size.
// - Point in polygon: the even-odd crossing rule in the same 2D frame.
#include "dayphoton/core/polygon.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace dayphoton {

namespace {

Vec3 newell_sum(const std::vector<Vec3>& v) {
  Vec3 n{0, 0, 0};
  const std::size_t count = v.size();
  if (count < 3) return n;
  // Subtracting the first vertex keeps the sum accurate far from the origin.
  const Vec3 o = v[0];
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3 a = v[i] - o;
    const Vec3 b = v[(i + 1) % count] - o;
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return n;
}

/// Largest extent of the axis-aligned bounding box (the polygon's length scale).
double extent_m(const std::vector<Vec3>& v) {
  if (v.empty()) return 0;
  Vec3 lo = v[0], hi = v[0];
  for (const Vec3& p : v)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  return std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
}

struct Point2 {
  double x = 0, y = 0;
};

/// Orthonormal (u, v) in the polygon's plane with u x v = n.
void plane_frame(const Vec3& n, Vec3& u, Vec3& v) {
  const Vec3 helper = std::fabs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  u = normalize(cross(helper, n));
  v = cross(n, u);
}

std::vector<Point2> project_to_plane(const std::vector<Vec3>& vertices, const Vec3& n) {
  Vec3 u, v;
  plane_frame(n, u, v);
  const Vec3 o = vertices.empty() ? Vec3{} : vertices[0];
  std::vector<Point2> out;
  out.reserve(vertices.size());
  for (const Vec3& p : vertices) out.push_back({dot(p - o, u), dot(p - o, v)});
  return out;
}

/// Twice the signed area of triangle (a, b, c); positive when counter-clockwise.
double orient(const Point2& a, const Point2& b, const Point2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

double distance_point_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = dot(ab, ab);
  double t = len2 > 0 ? dot(p - a, ab) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return length(p - (a + ab * t));
}

}  // namespace

Vec3 polygon_normal(const std::vector<Vec3>& vertices) {
  const Vec3 n = newell_sum(vertices);
  const double len = length(n);
  const double scale = extent_m(vertices);
  // Degenerate when the vector area is negligible against the polygon's size squared.
  if (!(len > 0) || !std::isfinite(len) || len <= 1e-14 * scale * scale) return {0, 0, 0};
  return n / len;
}

double polygon_area_m2(const std::vector<Vec3>& vertices) {
  return 0.5 * length(newell_sum(vertices));
}

double planarity_deviation_m(const std::vector<Vec3>& vertices) {
  if (vertices.size() <= 3) return 0;
  const Vec3 n = polygon_normal(vertices);
  if (n == Vec3{0, 0, 0}) return 0;
  const Vec3 c = polygon_centroid(vertices);
  double worst = 0;
  for (const Vec3& p : vertices) worst = std::max(worst, std::fabs(dot(p - c, n)));
  return worst;
}

Vec3 polygon_centroid(const std::vector<Vec3>& vertices) {
  Vec3 sum{0, 0, 0};
  if (vertices.empty()) return sum;
  for (const Vec3& p : vertices) sum += p;
  return sum / static_cast<double>(vertices.size());
}

std::vector<std::array<std::uint32_t, 3>> triangulate_polygon(const std::vector<Vec3>& vertices) {
  if (vertices.size() < 3)
    throw std::invalid_argument("polygon has fewer than 3 vertices");
  for (const Vec3& p : vertices)
    if (!is_finite(p)) throw std::invalid_argument("polygon has a non-finite vertex");
  const Vec3 n = polygon_normal(vertices);
  if (n == Vec3{0, 0, 0}) throw std::invalid_argument("polygon is degenerate (zero area)");

  const std::vector<Point2> pts = project_to_plane(vertices, n);
  const double scale = extent_m(vertices);
  const double len_eps = 1e-9 * scale;               // coincident vertices
  const double area_eps = 1e-12 * scale * scale;     // collinear corners (twice the area)

  // Remaining polygon as a list of original indices.
  std::vector<std::uint32_t> ring;
  ring.reserve(vertices.size());
  for (std::uint32_t i = 0; i < vertices.size(); ++i) {
    if (!ring.empty() && length(vertices[i] - vertices[ring.back()]) <= len_eps) continue;
    ring.push_back(i);
  }
  while (ring.size() > 1 && length(vertices[ring.front()] - vertices[ring.back()]) <= len_eps)
    ring.pop_back();

  std::vector<std::array<std::uint32_t, 3>> triangles;
  triangles.reserve(vertices.size());

  auto remove_collinear = [&]() {
    bool changed = true;
    while (changed && ring.size() >= 3) {
      changed = false;
      for (std::size_t i = 0; i < ring.size() && ring.size() >= 3; ++i) {
        const std::size_t m = ring.size();
        const Point2& a = pts[ring[(i + m - 1) % m]];
        const Point2& b = pts[ring[i]];
        const Point2& c = pts[ring[(i + 1) % m]];
        if (std::fabs(orient(a, b, c)) <= area_eps) {
          ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
          changed = true;
          --i;
        }
      }
    }
  };

  auto is_ear = [&](std::size_t i) {
    const std::size_t m = ring.size();
    const std::uint32_t ia = ring[(i + m - 1) % m], ib = ring[i], ic = ring[(i + 1) % m];
    const Point2 &a = pts[ia], &b = pts[ib], &c = pts[ic];
    if (orient(a, b, c) <= area_eps) return false;  // reflex or flat corner
    // Only points in the bounding box of the ear grown by the tests' tolerance can pass them:
    // a cheap test first keeps polygons of many thousand vertices fast. The tolerance
    // area_eps is a distance of up to t = area_eps / (shortest edge) from each edge line; the
    // triangle grown by t is the triangle scaled about its incentre by (r + t) / r (r the
    // inradius, twice the area over the perimeter), so no point of it lies farther than
    // t / r x (longest edge) from the triangle.
    const double ab = std::hypot(b.x - a.x, b.y - a.y), bc = std::hypot(c.x - b.x, c.y - b.y),
                 ca = std::hypot(a.x - c.x, a.y - c.y);
    const double inradius = orient(a, b, c) / (ab + bc + ca);
    const double t = area_eps / std::max(std::min({ab, bc, ca}), 1e-300);
    const double pad = len_eps + t / inradius * std::max({ab, bc, ca});
    const double lo_x = std::min({a.x, b.x, c.x}) - pad, hi_x = std::max({a.x, b.x, c.x}) + pad;
    const double lo_y = std::min({a.y, b.y, c.y}) - pad, hi_y = std::max({a.y, b.y, c.y}) + pad;
    for (std::size_t k = 0; k < m; ++k) {
      const std::uint32_t ip = ring[k];
      const Point2& p = pts[ip];
      if (p.x < lo_x || p.x > hi_x || p.y < lo_y || p.y > hi_y) continue;
      if (ip == ia || ip == ib || ip == ic) continue;
      // A vertex at the same place as a corner (a touching polygon) does not block.
      auto same = [&](const Point2& q) { return std::hypot(p.x - q.x, p.y - q.y) <= len_eps; };
      if (same(a) || same(b) || same(c)) continue;
      // Inside or on the boundary of the candidate ear: not an ear.
      if (orient(a, b, p) >= -area_eps && orient(b, c, p) >= -area_eps &&
          orient(c, a, p) >= -area_eps)
        return false;
    }
    return true;
  };

  remove_collinear();
  // The search resumes where the last ear was cut (its neighbours are the likeliest new
  // ears), which keeps typical polygons at O(n^2) instead of O(n^3).
  std::size_t cursor = 0;
  while (ring.size() > 3) {
    bool clipped = false;
    const std::size_t m = ring.size();
    for (std::size_t step = 0; step < m; ++step) {
      const std::size_t i = (cursor + step) % m;
      if (!is_ear(i)) continue;
      triangles.push_back({ring[(i + m - 1) % m], ring[i], ring[(i + 1) % m]});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
      cursor = i == 0 ? 0 : i - 1;
      clipped = true;
      break;
    }
    if (!clipped)
      throw std::invalid_argument("polygon is self-intersecting or not simple: no ear to clip");
    remove_collinear();
  }
  if (ring.size() == 3) {
    if (orient(pts[ring[0]], pts[ring[1]], pts[ring[2]]) <= area_eps)
      throw std::invalid_argument("polygon is self-intersecting or not simple: inverted triangle");
    triangles.push_back({ring[0], ring[1], ring[2]});
  }
  if (triangles.empty()) throw std::invalid_argument("polygon is degenerate (zero area)");

  // Ear clipping conserves area for a simple polygon; a mismatch reveals self-intersection
  // (e.g. a bow-tie, whose Newell area is the difference of its lobes).
  double sum = 0;
  for (const auto& t : triangles)
    sum += 0.5 * orient(pts[t[0]], pts[t[1]], pts[t[2]]);
  const double area = polygon_area_m2(vertices);
  if (std::fabs(sum - area) > 1e-6 * std::max(area, scale * scale * 1e-6))
    throw std::invalid_argument("polygon is self-intersecting: triangles do not cover its area");
  return triangles;
}

bool polygon_contains(const std::vector<Vec3>& vertices, const Vec3& p) {
  if (vertices.size() < 3) return false;
  const Vec3 n = polygon_normal(vertices);
  if (n == Vec3{0, 0, 0}) return false;
  std::vector<Vec3> with_point = vertices;
  with_point.push_back(p);
  const std::vector<Point2> pts = project_to_plane(with_point, n);
  const Point2 q = pts.back();
  bool inside = false;
  const std::size_t m = vertices.size();
  for (std::size_t i = 0, j = m - 1; i < m; j = i++) {
    const Point2 &a = pts[i], &b = pts[j];
    if ((a.y > q.y) != (b.y > q.y)) {
      const double x_cross = a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (q.x < x_cross) inside = !inside;
    }
  }
  return inside;
}

double distance_to_polygon_boundary_m(const std::vector<Vec3>& vertices, const Vec3& p) {
  if (vertices.empty()) return std::numeric_limits<double>::infinity();
  if (vertices.size() == 1) return length(p - vertices[0]);
  double best = std::numeric_limits<double>::infinity();
  const std::size_t m = vertices.size();
  for (std::size_t i = 0; i < m; ++i)
    best = std::min(best, distance_point_segment(p, vertices[i], vertices[(i + 1) % m]));
  return best;
}

}  // namespace dayphoton
