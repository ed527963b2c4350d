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
// Surface names: "<room>.floor", "<room>.ceiling", "<room>.wall_<dir>" (".1", ".2", ...
// when split), "<room>.<window name>".
#include "dayphoton/core/diagnostics.h"
#include <algorithm>
#include <cmath>

#include "geometry_generators.h"

namespace dayphoton::project {

namespace detail {

namespace {

constexpr double SnapTolerance_m = 1e-6;

struct Rect {
  double u0, u1, v0, v1;
};

/// A wall in model space: p(u, v) = origin + u * u_axis + v * (0,0,1), inward normal.
struct WallFrame {
  Vec3 origin;
  Vec3 u_axis;
  Vec3 inward;
  double length_m;
};

WallFrame wall_frame(const RoomSpec& room, Wall wall) {
  const Vec3 o = room.origin, s = room.size_m;
  switch (wall) {
    case Wall::South: return {o, {1, 0, 0}, {0, 1, 0}, s.x};
    case Wall::North: return {o + Vec3{0, s.y, 0}, {1, 0, 0}, {0, -1, 0}, s.x};
    case Wall::West: return {o, {0, 1, 0}, {1, 0, 0}, s.y};
    case Wall::East: return {o + Vec3{s.x, 0, 0}, {0, 1, 0}, {-1, 0, 0}, s.y};
  }
  return {o, {1, 0, 0}, {0, 1, 0}, s.x};
}

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

}  // namespace

void generate_room(const RoomSpec& room, MaterialLookup& materials, Diagnostics& diag,
                   std::vector<Surface>& out) {
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
  out.push_back({room.name + ".ceiling", ceiling_mat,
                 {o + Vec3{0, 0, s.z}, o + Vec3{0, s.y, s.z}, o + Vec3{s.x, s.y, s.z}, o + Vec3{s.x, 0, s.z}},
                 false, room.location});

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
    const int glass_mat = materials.resolve(w.material, w.location, wwhat);
    out.push_back({room.name + "." + wname, glass_mat, wall_rectangle(frame, r), true, w.location});
  }

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
