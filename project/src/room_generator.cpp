// Room generator: a box room with all normals facing INTO the room and rectangular windows
// cut into its walls, matching the reference office (../shared/refdata/scenes/office.rad).
//
// Model frame: the room spans origin + [0, size.x] x [0, size.y] x [0, size.z]. Walls are
// named by the direction they face outward: south = minimum y, north = maximum y,
// east = maximum x, west = minimum x. A window is placed in wall coordinates: u along the
// wall from its lower-coordinate end (min x for south/north, min y for east/west), from
// `offset_m` (or centred) over `width_m`; v above the floor from `sill_m` over `height_m`.
//
// A wall with openings is split into rectangles: the u breakpoints (wall ends and window
// jambs) cut the wall into columns; in each column the wall is the complement of the
// windows' v ranges; neighbouring columns with identical strips are merged. For the office
// (one 4 x 1.5 m window centred in the 6 x 3 m south wall) this gives two full-height jambs
// and a sill and a head strip: 18 - 6 = 12 m^2 of wall. Each window becomes a glazing
// Surface (port = true) in the wall plane with the same inward normal.
//
// Daylight systems and adjoining rooms may change a room (RoomCutouts): light pipes cut
// convex openings into the ceiling (ceiling_pieces below), a window inside an exterior
// system's port enclosure stays glazing but is no longer a port, and an interior window
// (interior_windows.cpp) is glazing, not a port, and is cut out of the adjoining room's
// wall as well. Roof lights (roof_light_generator.cpp) cut rectangular openings into the
// ceiling.
//
// Surface names: "<room>.floor", "<room>.ceiling" (".1", ".2", ... with openings),
// "<room>.wall_<dir>" (".1", ".2", ... when split), "<room>.<window name>", and the roof
// lights' (roof_light_generator.cpp).
#include "dayphoton/core/diagnostics.h"
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "dayphoton/core/units.h"

#include "dayphoton/core/polygon.h"
#include "geometry_generators.h"
#include "window_frame.h"

namespace dayphoton::project {

namespace detail {

namespace {

constexpr double SnapTolerance_m = 1e-6;

struct Rect {
  double u0, u1, v0, v1;
};

/// Rectangle's corners wound counter-clockwise about the wall's inward normal.
std::vector<Vec3> wall_rectangle(const WallFrame& f, const Rect& r) {
  const Vec3 up{0, 0, 1};
  auto at = [&](double u, double v) { return f.origin + f.u_axis * u + up * v; };
  std::vector<Vec3> ccw_about_u_cross_up{at(r.u0, r.v0), at(r.u1, r.v0), at(r.u1, r.v1), at(r.u0, r.v1)};
  if (dot(cross(f.u_axis, up), f.inward) < 0)
    std::reverse(ccw_about_u_cross_up.begin() + 1, ccw_about_u_cross_up.end());
  return ccw_about_u_cross_up;
}

/// Wall pieces around the openings (see the header comment).
std::vector<Rect> wall_pieces(double length_m, double height_m, const std::vector<Rect>& holes) {
  std::vector<double> us{0, length_m};
  for (const Rect& h : holes) {
    us.push_back(h.u0);
    us.push_back(h.u1);
  }
  std::sort(us.begin(), us.end());
  us.erase(std::unique(us.begin(), us.end(), [](double a, double b) { return b - a <= SnapTolerance_m; }),
           us.end());
  us.back() = length_m;

  struct Column {
    double u0, u1;
    std::vector<std::pair<double, double>> strips;
  };
  std::vector<Column> columns;
  for (std::size_t i = 0; i + 1 < us.size(); ++i) {
    Column c{us[i], us[i + 1], {}};
    const double mid = 0.5 * (c.u0 + c.u1);
    std::vector<std::pair<double, double>> cut;
    for (const Rect& h : holes)
      if (h.u0 < mid && mid < h.u1) cut.push_back({h.v0, h.v1});
    std::sort(cut.begin(), cut.end());
    double v = 0;
    for (const auto& [v0, v1] : cut) {
      if (v0 - v > SnapTolerance_m) c.strips.push_back({v, v0});
      v = std::max(v, v1);
    }
    if (height_m - v > SnapTolerance_m) c.strips.push_back({v, height_m});
    if (!columns.empty() && columns.back().strips == c.strips)
      columns.back().u1 = c.u1;
    else
      columns.push_back(std::move(c));
  }
  std::vector<Rect> pieces;
  for (const Column& c : columns)
    for (const auto& [v0, v1] : c.strips) pieces.push_back({c.u0, c.u1, v0, v1});
  return pieces;
}

bool finite_positive(double x) { return std::isfinite(x) && x > 0; }

/// `polygon` turned, if needed, so that its winding normal points along `normal`.
std::vector<Vec3> facing(std::vector<Vec3> polygon, const Vec3& normal) {
  if (dot(polygon_normal(polygon), normal) < 0) std::reverse(polygon.begin() + 1, polygon.end());
  return polygon;
}

/// The ceiling rectangle [0, sx] x [0, sy] (room coordinates, at height z) minus
/// rectangular openings (roof lights, room coordinates) and convex holes (model coordinates,
/// each containing its vertex centroid, as the light pipe's regular polygons do): the
/// rectangle minus the openings and the holes' bounding boxes is split like a wall
/// (wall_pieces), and the ring between each bounding box and its hole is cut into one piece
/// per hole edge by the rays from the hole's centre through its vertices (each piece: hole
/// edge, two ray segments and the box boundary between them, corners included). Every piece
/// is planar and simple; pieces of zero area (a hole edge lying on its box) are dropped.
std::vector<std::vector<Vec3>> ceiling_pieces(const Vec3& origin, double sx, double sy, double z,
                                              const std::vector<CeilingRect>& openings,
                                              const std::vector<std::vector<Vec3>>& holes) {
  std::vector<Rect> boxes;
  for (const auto& hole : holes) {
    Rect b{hole[0].x - origin.x, hole[0].x - origin.x, hole[0].y - origin.y, hole[0].y - origin.y};
    for (const Vec3& p : hole) {
      b.u0 = std::min(b.u0, p.x - origin.x);
      b.u1 = std::max(b.u1, p.x - origin.x);
      b.v0 = std::min(b.v0, p.y - origin.y);
      b.v1 = std::max(b.v1, p.y - origin.y);
    }
    boxes.push_back(b);
  }
  std::vector<std::vector<Vec3>> pieces;
  const Vec3 down{0, 0, -1};
  std::vector<Rect> cut = boxes;
  for (const CeilingRect& r : openings) cut.push_back({r.x0, r.x1, r.y0, r.y1});
  for (const Rect& r : wall_pieces(sx, sy, cut))
    pieces.push_back(facing({origin + Vec3{r.u0, r.v0, z}, origin + Vec3{r.u1, r.v0, z},
                             origin + Vec3{r.u1, r.v1, z}, origin + Vec3{r.u0, r.v1, z}},
                            down));
  for (std::size_t h = 0; h < holes.size(); ++h) {
    const std::vector<Vec3>& hole = holes[h];
    const Rect& b = boxes[h];
    Vec3 c{0, 0, 0};
    for (const Vec3& p : hole) c = c + p;
    c = c * (1.0 / double(hole.size()));
    const double bx0 = origin.x + b.u0, bx1 = origin.x + b.u1, by0 = origin.y + b.v0,
                 by1 = origin.y + b.v1;
    // Where the ray from c through p leaves the box, and the box corners by angle.
    auto exit_point = [&](const Vec3& p) {
      const Vec3 d = p - c;
      double t = std::numeric_limits<double>::infinity();
      if (d.x > 0) t = std::min(t, (bx1 - c.x) / d.x);
      if (d.x < 0) t = std::min(t, (bx0 - c.x) / d.x);
      if (d.y > 0) t = std::min(t, (by1 - c.y) / d.y);
      if (d.y < 0) t = std::min(t, (by0 - c.y) / d.y);
      return Vec3{c.x + d.x * t, c.y + d.y * t, z};
    };
    const Vec3 corners[4] = {{bx1, by1, z}, {bx0, by1, z}, {bx0, by0, z}, {bx1, by0, z}};
    auto angle = [&](const Vec3& p) { return std::atan2(p.y - c.y, p.x - c.x); };
    // Vertices counter-clockwise seen from above.
    std::vector<Vec3> ring = facing(hole, Vec3{0, 0, 1});
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec3& a = ring[i];
      const Vec3& d = ring[(i + 1) % ring.size()];
      const double a0 = angle(a);
      double a1 = angle(d);
      if (a1 <= a0) a1 += 2 * Pi;
      std::vector<Vec3> piece{a, exit_point(a)};
      std::vector<std::pair<double, Vec3>> between;
      for (const Vec3& k : corners) {
        double ak = angle(k);
        while (ak <= a0) ak += 2 * Pi;
        if (ak < a1) between.push_back({ak, k});
      }
      std::sort(between.begin(), between.end(),
                [](const auto& x, const auto& y) { return x.first < y.first; });
      for (const auto& k : between) piece.push_back(k.second);
      piece.push_back(exit_point(d));
      piece.push_back(d);
      // Drop repeated points (a hole vertex on its box: the ray segment has zero length).
      std::vector<Vec3> clean;
      for (const Vec3& p : piece)
        if (clean.empty() || length(p - clean.back()) > SnapTolerance_m) clean.push_back(p);
      while (clean.size() > 1 && length(clean.front() - clean.back()) <= SnapTolerance_m) clean.pop_back();
      if (clean.size() < 3 || polygon_area_m2(clean) < 1e-10) continue;
      pieces.push_back(facing(clean, down));
    }
  }
  return pieces;
}

}  // namespace

void generate_room(const RoomSpec& room, const RoomCutouts& cutouts, MaterialLookup& materials,
                   Diagnostics& diag, std::vector<Surface>& out) {
  const std::string what = "room '" + room.name + "'";
  if (!is_finite(room.origin)) {
    report(diag, room.location, what + ": origin is not finite");
    return;
  }
  if (!finite_positive(room.size_m.x) || !finite_positive(room.size_m.y) || !finite_positive(room.size_m.z)) {
    report(diag, room.location,
           what + ": every size must be positive, got " + std::to_string(room.size_m.x) + " x " +
               std::to_string(room.size_m.y) + " x " + std::to_string(room.size_m.z) + " m");
    return;
  }
  const Vec3 o = room.origin, s = room.size_m;
  const int floor_mat = materials.resolve(room.floor_material, room.location, "the floor of " + what);
  const int ceiling_mat = materials.resolve(room.ceiling_material, room.location, "the ceiling of " + what);

  // Floor (normal +z) and ceiling (normal -z), as in office.rad.
  out.push_back({room.name + ".floor", floor_mat,
                 {o, o + Vec3{s.x, 0, 0}, o + Vec3{s.x, s.y, 0}, o + Vec3{0, s.y, 0}}, false, room.location});
  // Roof lights: glazing and light wells; their openings are cut out of the ceiling.
  const std::vector<CeilingRect> roof_openings = generate_roof_lights(room, cutouts, materials, diag, out);
  if (cutouts.ceiling_holes.empty() && roof_openings.empty()) {
    out.push_back({room.name + ".ceiling", ceiling_mat,
                   {o + Vec3{0, 0, s.z}, o + Vec3{0, s.y, s.z}, o + Vec3{s.x, s.y, s.z}, o + Vec3{s.x, 0, s.z}},
                   false, room.location});
  } else {
    // Openings of light pipes (validated by their generator: inside the ceiling, apart) and
    // of roof lights (validated by theirs: inside the ceiling, apart from each other and
    // from the pipes).
    const auto pieces = ceiling_pieces(o, s.x, s.y, s.z, roof_openings, cutouts.ceiling_holes);
    for (std::size_t i = 0; i < pieces.size(); ++i)
      out.push_back({room.name + ".ceiling." + std::to_string(i + 1), ceiling_mat, pieces[i], false,
                     room.location});
  }

  // Windows per wall, validated against the wall and each other.
  std::vector<Rect> holes[4];
  std::vector<const WindowSpec*> placed[4];
  for (std::size_t wi = 0; wi < room.windows.size(); ++wi) {
    const WindowSpec& w = room.windows[wi];
    const int wall_index = static_cast<int>(w.wall);
    const WallFrame frame = wall_frame(room, w.wall);
    const std::string wname = w.name.empty() ? "window_" + std::to_string(wi + 1) : w.name;
    const std::string wwhat = "window '" + wname + "' of " + what;
    if (!finite_positive(w.width_m) || !finite_positive(w.height_m)) {
      report(diag, w.location, wwhat + ": width and height must be positive");
      continue;
    }
    if (!std::isfinite(w.sill_m) || w.sill_m < 0) {
      report(diag, w.location, wwhat + ": sill must be >= 0");
      continue;
    }
    if (w.offset_m && (!std::isfinite(*w.offset_m) || *w.offset_m < 0)) {
      report(diag, w.location, wwhat + ": offset must be >= 0");
      continue;
    }
    Rect r;
    r.u0 = w.offset_m ? *w.offset_m : 0.5 * (frame.length_m - w.width_m);
    r.u1 = r.u0 + w.width_m;
    r.v0 = w.sill_m;
    r.v1 = w.sill_m + w.height_m;
    if (r.u0 < -SnapTolerance_m || r.u1 > frame.length_m + SnapTolerance_m || r.v1 > s.z + SnapTolerance_m) {
      report(diag, w.location,
             wwhat + " does not fit in the " + wall_name(w.wall) + " wall (" +
                 format_number(frame.length_m) + " x " + format_number(s.z) + " m): it spans " +
                 format_number(r.u0) + " to " + format_number(r.u1) + " m along the wall and " +
                 format_number(r.v0) + " to " + format_number(r.v1) + " m above the floor");
      continue;
    }
    // Snap to the wall edges so no sliver of wall is left.
    r.u0 = std::max(0.0, r.u0);
    r.u1 = std::min(frame.length_m, r.u1);
    r.v1 = std::min(s.z, r.v1);
    if (r.u1 - r.u0 <= SnapTolerance_m || r.v1 - r.v0 <= SnapTolerance_m) {
      report(diag, w.location, wwhat + " has no area");
      continue;
    }
    bool overlaps = false;
    for (std::size_t k = 0; k < holes[wall_index].size(); ++k) {
      const Rect& q = holes[wall_index][k];
      const double du = std::min(r.u1, q.u1) - std::max(r.u0, q.u0);
      const double dv = std::min(r.v1, q.v1) - std::max(r.v0, q.v0);
      if (du > SnapTolerance_m && dv > SnapTolerance_m) {
        const WindowSpec& other = *placed[wall_index][k];
        report(diag, w.location,
               wwhat + " overlaps window '" + other.name + "' in the " + wall_name(w.wall) + " wall" +
                   (other.location.known() ? " (defined at " + other.location.to_string() + ")" : ""));
        overlaps = true;
        break;
      }
    }
    if (overlaps) continue;
    holes[wall_index].push_back(r);
    placed[wall_index].push_back(&w);
    const int glass_mat = window_material(w, wwhat, materials, diag);
    // A window inside a daylight system's port enclosure is glazing, not a port (the
    // enclosure's openings are the ports; docs/daylight-systems.md); so is an interior
    // window (light reaches it through the rooms' exterior openings).
    const bool port = cutouts.windows_without_port.count(w.name) == 0;
    out.push_back({room.name + "." + wname, glass_mat, wall_rectangle(frame, r), port, w.location});
  }

  // Interior windows of adjoining rooms open through this room's walls too (validated by
  // find_interior_windows: inside the wall, apart from this room's own windows).
  for (const WallHole& h : cutouts.wall_holes)
    holes[static_cast<int>(h.wall)].push_back({h.rect.u0, h.rect.u1, h.rect.v0, h.rect.v1});

  // Walls around their openings.
  for (Wall wall : {Wall::South, Wall::North, Wall::East, Wall::West}) {
    const int wall_index = static_cast<int>(wall);
    const WallFrame frame = wall_frame(room, wall);
    const std::string base = room.name + ".wall_" + wall_name(wall);
    const int mat = materials.resolve(room.wall_material[wall_index], room.location,
                                      std::string("the ") + wall_name(wall) + " wall of " + what);
    const std::vector<Rect> pieces = wall_pieces(frame.length_m, s.z, holes[wall_index]);
    for (std::size_t i = 0; i < pieces.size(); ++i)
      out.push_back({pieces.size() == 1 ? base : base + "." + std::to_string(i + 1), mat,
                     wall_rectangle(frame, pieces[i]), false, room.location});
  }
}

}  // namespace detail
}  // namespace dayphoton::project
