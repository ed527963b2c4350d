// Plane cuts: see plane_cuts.h.
#include "dayphoton/engine/plane_cuts.h"

#include <algorithm>
#include <array>
#include <map>
#include <cmath>
#include <limits>

namespace dayphoton::engine {
namespace {

bool on_outline(const ReceiverPlane& plane, const PlaneSegment& s) {
  const std::vector<PlanePoint>& outline = plane.outline();
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const PlanePoint& a = outline[i];
    const PlanePoint& b = outline[(i + 1) % outline.size()];
    if (distance_to_segment_m(s.a.x, s.a.y, a, b) <= OnOutline_m && distance_to_segment_m(s.b.x, s.b.y, a, b) <= OnOutline_m)
      return true;
  }
  return false;
}

// The parts of a cut inside the outline: the cut split where it meets the outline's edges,
// the pieces whose middle lies inside kept. A partition that runs on out of a grid outline
// smaller than the room (or a triangle's cut longer than the room) still hides what lies
// behind it from the sensors inside; its part outside lies behind the outline anyway.
void add_inside_pieces(const ReceiverPlane& plane, const PlaneSegment& s, std::vector<PlaneSegment>& cuts) {
  const std::vector<PlanePoint>& outline = plane.outline();
  std::vector<double> at = {0.0, 1.0};
  const double ex = s.b.x - s.a.x, ey = s.b.y - s.a.y;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const PlanePoint& p = outline[i];
    const PlanePoint& q = outline[(i + 1) % outline.size()];
    const double fx = q.x - p.x, fy = q.y - p.y;
    const double den = ex * fy - ey * fx;
    if (den == 0) continue;  // parallel: the neighbouring edges bound any stretch along it
    // s.a + t e = p + u f
    const double t = ((p.x - s.a.x) * fy - (p.y - s.a.y) * fx) / den;
    const double u = ((p.x - s.a.x) * ey - (p.y - s.a.y) * ex) / den;
    if (t > 0 && t < 1 && u >= 0 && u <= 1) at.push_back(t);
  }
  std::sort(at.begin(), at.end());
  for (std::size_t k = 0; k + 1 < at.size(); ++k) {
    if (!(at[k + 1] > at[k])) continue;
    const PlaneSegment piece{{s.a.x + at[k] * ex, s.a.y + at[k] * ey}, {s.a.x + at[k + 1] * ex, s.a.y + at[k + 1] * ey}};
    const PlanePoint middle{0.5 * (piece.a.x + piece.b.x), 0.5 * (piece.a.y + piece.b.y)};
    if (!plane.contains(middle.x, middle.y) || on_outline(plane, piece)) continue;
    // A cut wholly inside is kept as computed (k = 0 and the end 1: no division).
    cuts.push_back(at.size() == 2 ? s : piece);
  }
}

}  // namespace

std::vector<PlaneSegment> interior_plane_cuts(const Scene& scene, const ReceiverPlane& plane, bool opaque_only) {
  const SceneDescription& description = scene.description();
  auto passes_light = [&](int surface) {
    const MaterialType type =
        description.materials[static_cast<std::size_t>(description.surfaces[static_cast<std::size_t>(surface)].material)].type;
    return type == MaterialType::Glass || type == MaterialType::Opening || type == MaterialType::Dielectric;
  };
  std::vector<PlaneSegment> cuts;
  const double z = plane.height_m();
  // Edges lying in the plane, (x0, y0, x1, y1) with the lesser end first, and the sides their
  // triangles reach (1 above, 2 below): a seam that both sides reach (a partition of two
  // panels meeting at the plane's height, a column mesh with a ring of vertices there) cuts
  // the plane; one side alone (the top edges of a desk whose top is the plane) does not.
  std::map<std::array<double, 4>, int> in_plane_edges;
  for (std::size_t t = 0; t < scene.triangle_count(); ++t) {
    const SceneTriangle& tri = scene.triangle(static_cast<std::uint32_t>(t));
    if (scene.is_port(tri.surface) || (opaque_only && passes_light(tri.surface))) continue;
    double d[3];
    bool above = false, below = false;
    for (int k = 0; k < 3; ++k) {
      d[k] = tri.vertices[k].z - z;
      above = above || d[k] > 0;
      below = below || d[k] < 0;
    }
    if (!above || !below) {
      for (int k = 0; k < 3; ++k) {
        const Vec3& p = tri.vertices[k];
        const Vec3& q = tri.vertices[(k + 1) % 3];
        if (d[k] != 0 || d[(k + 1) % 3] != 0 || (p.x == q.x && p.y == q.y)) continue;
        if (!above && !below) continue;  // the triangle lies in the plane
        const bool p_first = p.x < q.x || (p.x == q.x && p.y < q.y);
        const std::array<double, 4> key = p_first ? std::array<double, 4>{p.x, p.y, q.x, q.y}
                                                  : std::array<double, 4>{q.x, q.y, p.x, p.y};
        in_plane_edges[key] |= above ? 1 : 2;
      }
      continue;
    }
    // The two points where the triangle's boundary meets the plane: a vertex on it, or an
    // edge whose ends lie on opposite sides.
    PlanePoint ends[2];
    int found = 0;
    for (int k = 0; k < 3 && found < 2; ++k) {
      const Vec3& p = tri.vertices[k];
      const Vec3& q = tri.vertices[(k + 1) % 3];
      const double dp = d[k], dq = d[(k + 1) % 3];
      if (dp == 0) {
        ends[found++] = {p.x, p.y};
      } else if ((dp > 0 && dq < 0) || (dp < 0 && dq > 0)) {
        const double s = dp / (dp - dq);
        ends[found++] = {p.x + s * (q.x - p.x), p.y + s * (q.y - p.y)};
      }
    }
    if (found < 2) continue;
    const PlaneSegment cut{ends[0], ends[1]};
    if (cut.a.x == cut.b.x && cut.a.y == cut.b.y) continue;
    add_inside_pieces(plane, cut, cuts);
  }
  for (const auto& [edge, sides] : in_plane_edges)
    if (sides == 3) add_inside_pieces(plane, {{edge[0], edge[1]}, {edge[2], edge[3]}}, cuts);
  return cuts;
}

double distance_to_interior_cut_m(const ReceiverPlane& plane, double x, double y) {
  double nearest_m = std::numeric_limits<double>::infinity();
  for (const PlaneSegment& cut : plane.interior_cuts()) nearest_m = std::min(nearest_m, distance_to_segment_m(x, y, cut.a, cut.b));
  return nearest_m;
}

std::vector<std::size_t> sensors_near_cuts(const ReceiverPlane& plane, const std::vector<SensorPoint>& sensors,
                                           SensorRange rows) {
  rows = rows.within(sensors.size());
  std::vector<std::size_t> near;
  if (plane.interior_cuts().empty()) return near;
  for (std::size_t s = rows.begin; s < rows.end; ++s)
    if (distance_to_interior_cut_m(plane, sensors[s].position.x, sensors[s].position.y) < NearCutGather_m - NearCutMargin_m)
      near.push_back(s);
  return near;
}

std::vector<std::size_t> sensors_on_cuts(const ReceiverPlane& plane, const std::vector<SensorPoint>& sensors) {
  std::vector<std::size_t> on;
  if (plane.interior_cuts().empty()) return on;
  for (std::size_t s = 0; s < sensors.size(); ++s)
    if (distance_to_interior_cut_m(plane, sensors[s].position.x, sensors[s].position.y) < OnCut_m) on.push_back(s);
  return on;
}

}  // namespace dayphoton::engine
