// triangulate_with_holes (polygon_holes.h): Eberly's bridges and ear clipping, in the 2-D frame
// of the outer polygon's plane (u, v, normal right-handed, so the outer polygon is
// counter-clockwise there).
#include "polygon_holes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "dayphoton/core/polygon.h"

namespace dayphoton::project::detail {

namespace {

struct P2 {
  double x = 0, y = 0;
};

double cross2(const P2& o, const P2& a, const P2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

double signed_area(const std::vector<P2>& pts, const std::vector<int>& ring) {
  double a = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const P2& p = pts[ring[i]];
    const P2& q = pts[ring[(i + 1) % ring.size()]];
    a += p.x * q.y - q.x * p.y;
  }
  return 0.5 * a;
}

bool same_point(const P2& a, const P2& b, double eps) {
  return std::abs(a.x - b.x) <= eps && std::abs(a.y - b.y) <= eps;
}

/// p inside or on triangle (a, b, c), counter-clockwise.
bool in_triangle(const P2& p, const P2& a, const P2& b, const P2& c, double eps) {
  return cross2(a, b, p) >= -eps && cross2(b, c, p) >= -eps && cross2(c, a, p) >= -eps;
}

/// Whether direction d from vertex at list position k points into the polygon's interior
/// (counter-clockwise polygon): the bridge from that occurrence of a repeated vertex.
bool opens_toward(const std::vector<P2>& pts, const std::vector<int>& poly, std::size_t k, const P2& target) {
  const std::size_t n = poly.size();
  const P2& v = pts[poly[k]];
  const P2& prev = pts[poly[(k + n - 1) % n]];
  const P2& next = pts[poly[(k + 1) % n]];
  const bool convex = cross2(prev, v, next) > 0;
  const double to_next = cross2(v, next, target);  // > 0: target left of v->next
  const double from_prev = cross2(prev, v, target);  // > 0: target left of prev->v
  return convex ? (to_next > 0 && from_prev > 0) : (to_next > 0 || from_prev > 0);
}

}  // namespace

std::vector<std::array<Vec3, 3>> triangulate_with_holes(const std::vector<Vec3>& outer,
                                                        const std::vector<std::vector<Vec3>>& holes) {
  const Vec3 n = polygon_normal(outer);
  if (n == Vec3{0, 0, 0}) throw std::invalid_argument("the outer boundary is degenerate");
  // Frame: u perpendicular to n, v = n x u.
  const Vec3 helper = std::abs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 u = normalize(cross(helper, n));
  const Vec3 v = cross(n, u);

  std::vector<Vec3> pts3;
  std::vector<P2> pts;
  double extent = 0;
  auto add = [&](const Vec3& p) {
    pts3.push_back(p);
    pts.push_back({dot(p - outer[0], u), dot(p - outer[0], v)});
    extent = std::max({extent, std::abs(pts.back().x), std::abs(pts.back().y)});
    return static_cast<int>(pts.size() - 1);
  };
  std::vector<int> poly;
  for (const Vec3& p : outer) poly.push_back(add(p));
  std::vector<std::vector<int>> rings;
  for (const auto& hole : holes) {
    std::vector<int> ring;
    for (const Vec3& p : hole) ring.push_back(add(p));
    if (signed_area(pts, ring) > 0) std::reverse(ring.begin(), ring.end());  // clockwise
    rings.push_back(std::move(ring));
  }
  const double eps = 1e-12 * std::max(1.0, extent) * std::max(1.0, extent);
  const double eps_len = 1e-9 * std::max(1.0, extent);

  // Bridges, holes by decreasing largest x.
  auto max_x_vertex = [&](const std::vector<int>& ring) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < ring.size(); ++i)
      if (pts[ring[i]].x > pts[ring[best]].x) best = i;
    return best;
  };
  std::vector<std::size_t> order(rings.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return pts[rings[a][max_x_vertex(rings[a])]].x > pts[rings[b][max_x_vertex(rings[b])]].x;
  });
  for (const std::size_t h : order) {
    const std::vector<int>& ring = rings[h];
    const std::size_t mi = max_x_vertex(ring);
    const P2 m = pts[ring[mi]];
    // The nearest boundary point hit by the ray from m toward +x.
    double best_x = std::numeric_limits<double>::infinity();
    std::size_t best_edge = poly.size();
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const P2& a = pts[poly[k]];
      const P2& b = pts[poly[(k + 1) % poly.size()]];
      if (a.y == b.y) continue;  // parallel to the ray
      if (std::min(a.y, b.y) > m.y || std::max(a.y, b.y) < m.y) continue;
      const double x = a.x + (m.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (x < m.x - eps_len) continue;
      if (x < best_x) {
        best_x = x;
        best_edge = k;
      }
    }
    if (best_edge == poly.size()) throw std::invalid_argument("a hole is not inside the outer boundary");
    const std::size_t ka = best_edge, kb = (best_edge + 1) % poly.size();
    const P2 hit{best_x, m.y};
    std::size_t bridge;
    if (same_point(pts[poly[ka]], hit, eps_len)) {
      bridge = ka;
    } else if (same_point(pts[poly[kb]], hit, eps_len)) {
      bridge = kb;
    } else {
      bridge = pts[poly[ka]].x > pts[poly[kb]].x ? ka : kb;
      // A vertex inside triangle (m, hit, bridge) would hide the bridge vertex: take the one
      // at the smallest angle from the ray instead (ties: the nearest).
      const P2 p = pts[poly[bridge]];
      P2 t0 = m, t1 = hit, t2 = p;
      if (cross2(t0, t1, t2) < 0) std::swap(t1, t2);
      double best_cos = -2, best_d = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < poly.size(); ++k) {
        const P2& r = pts[poly[k]];
        if (k == bridge || same_point(r, p, eps_len) || same_point(r, m, eps_len)) continue;
        if (!in_triangle(r, t0, t1, t2, eps)) continue;
        const double d = std::hypot(r.x - m.x, r.y - m.y);
        const double c = (r.x - m.x) / d;
        if (c > best_cos + 1e-12 || (std::abs(c - best_cos) <= 1e-12 && d < best_d)) {
          best_cos = c;
          best_d = d;
          bridge = k;
        }
      }
    }
    // A vertex repeated by an earlier bridge: the occurrence whose corner opens toward m.
    for (std::size_t k = 0; k < poly.size(); ++k)
      if (poly[k] == poly[bridge] && k != bridge && opens_toward(pts, poly, k, m) &&
          !opens_toward(pts, poly, bridge, m)) {
        bridge = k;
        break;
      }
    std::vector<int> spliced(poly.begin(), poly.begin() + static_cast<std::ptrdiff_t>(bridge) + 1);
    for (std::size_t i = 0; i <= ring.size(); ++i) spliced.push_back(ring[(mi + i) % ring.size()]);
    spliced.push_back(poly[bridge]);
    spliced.insert(spliced.end(), poly.begin() + static_cast<std::ptrdiff_t>(bridge) + 1, poly.end());
    poly = std::move(spliced);
  }

  // Ear clipping. A vertex is an ear when its corner is convex and no other vertex of the
  // polygon (other than copies of the corner's own points) lies in its triangle.
  std::vector<std::array<Vec3, 3>> triangles;
  while (poly.size() > 3) {
    const std::size_t n_poly = poly.size();
    bool clipped = false;
    for (std::size_t i = 0; i < n_poly && !clipped; ++i) {
      const int ia = poly[(i + n_poly - 1) % n_poly], ib = poly[i], ic = poly[(i + 1) % n_poly];
      const P2 &a = pts[ia], &b = pts[ib], &c = pts[ic];
      if (cross2(a, b, c) <= eps) continue;
      bool blocked = false;
      for (std::size_t j = 0; j < n_poly && !blocked; ++j) {
        const P2& q = pts[poly[j]];
        if (same_point(q, a, eps_len) || same_point(q, b, eps_len) || same_point(q, c, eps_len)) continue;
        blocked = in_triangle(q, a, b, c, eps);
      }
      if (blocked) continue;
      triangles.push_back({pts3[ia], pts3[ib], pts3[ic]});
      poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (clipped) continue;
    // No ear: drop a vertex whose corner has no area (collinear with its neighbours).
    for (std::size_t i = 0; i < n_poly && !clipped; ++i) {
      const P2 &a = pts[poly[(i + n_poly - 1) % n_poly]], &b = pts[poly[i]], &c = pts[poly[(i + 1) % n_poly]];
      if (std::abs(cross2(a, b, c)) <= eps) {
        poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(i));
        clipped = true;
      }
    }
    if (!clipped) throw std::invalid_argument("no ear found (a hole touches the boundary or another hole?)");
  }
  if (poly.size() == 3 && cross2(pts[poly[0]], pts[poly[1]], pts[poly[2]]) > eps)
    triangles.push_back({pts3[poly[0]], pts3[poly[1]], pts3[poly[2]]});
  return triangles;
}

}  // namespace dayphoton::project::detail
