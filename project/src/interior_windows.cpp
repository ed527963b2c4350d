// Interior windows (docs/daylight-systems.md, "Interior windows"): a window in a wall that
// another room shares lets light from one room into the other.
//
// Rooms share a wall when a wall of one and the opposite wall of the other lie in the same
// plane (within 1e-6 m), e.g. room A's north wall at y = 5 and room B's south wall at
// y = 5: the rooms touch there, each wall facing into its own room. A window of A in that
// plane is then
//   - an interior window when its rectangle lies inside B's wall (within 1e-6 m): the room
//     generator cuts it out of both walls, and its glazing is ordinary glazing (no port:
//     light reaches it through the rooms' exterior openings, and the photon tracer and the
//     direct component pass straight transmission through it as they do through any pane);
//   - an error when it overlaps B's wall only in part (one part would open into B, the rest
//     to the sky), or when it overlaps an interior window that B defines for the same
//     opening (each opening is defined once, in either room);
//   - an exterior window, as before, when it does not overlap B's wall at all.
// Detected from the geometry, with no key: a window that opens into another room can only
// be an interior window, and before this was built it silently let no light through.
#include <algorithm>
#include <cmath>
#include <optional>
#include <variant>

#include "geometry_generators.h"

namespace dayphoton::project {

namespace detail {

namespace {

constexpr double Tolerance_m = 1e-6;

Wall opposite(Wall w) {
  switch (w) {
    case Wall::South: return Wall::North;
    case Wall::North: return Wall::South;
    case Wall::East: return Wall::West;
    case Wall::West: return Wall::East;
  }
  return Wall::North;
}

bool along_x(Wall w) { return w == Wall::South || w == Wall::North; }

/// The constant coordinate of a wall's plane (y for south/north walls, x for east/west).
double plane_of(const RoomSpec& room, Wall w) {
  switch (w) {
    case Wall::South: return room.origin.y;
    case Wall::North: return room.origin.y + room.size_m.y;
    case Wall::West: return room.origin.x;
    case Wall::East: return room.origin.x + room.size_m.x;
  }
  return 0;
}

/// A rectangle in a wall plane, model coordinates: a along the wall (x or y), z up.
struct Span {
  double a0 = 0, a1 = 0, z0 = 0, z1 = 0;
};

Span wall_span(const RoomSpec& room, Wall w) {
  const double a = along_x(w) ? room.origin.x : room.origin.y;
  const double length = along_x(w) ? room.size_m.x : room.size_m.y;
  return {a, a + length, room.origin.z, room.origin.z + room.size_m.z};
}

/// The window's rectangle in model coordinates, or nothing if the window is not one the room
/// generator builds (it reports those).
std::optional<Span> window_span(const RoomSpec& room, const WindowSpec& w) {
  auto finite_positive = [](double x) { return std::isfinite(x) && x > 0; };
  if (!finite_positive(w.width_m) || !finite_positive(w.height_m) || !std::isfinite(w.sill_m) || w.sill_m < 0 ||
      (w.offset_m && (!std::isfinite(*w.offset_m) || *w.offset_m < 0)))
    return std::nullopt;
  const WallRect r = window_rect(room, w);
  const double length = along_x(w.wall) ? room.size_m.x : room.size_m.y;
  if (r.u0 < 0 || r.u1 > length || r.v1 > room.size_m.z || r.u1 - r.u0 <= Tolerance_m || r.v1 - r.v0 <= Tolerance_m)
    return std::nullopt;
  const Span wall = wall_span(room, w.wall);
  return Span{wall.a0 + r.u0, wall.a0 + r.u1, wall.z0 + r.v0, wall.z0 + r.v1};
}

bool overlap(const Span& a, const Span& b) {
  return std::min(a.a1, b.a1) - std::max(a.a0, b.a0) > Tolerance_m &&
         std::min(a.z1, b.z1) - std::max(a.z0, b.z0) > Tolerance_m;
}

bool inside(const Span& a, const Span& b) {
  return a.a0 >= b.a0 - Tolerance_m && a.a1 <= b.a1 + Tolerance_m && a.z0 >= b.z0 - Tolerance_m &&
         a.z1 <= b.z1 + Tolerance_m;
}

std::string describe(const Span& s, Wall w) {
  return std::string(along_x(w) ? "x " : "y ") + format_number(s.a0) + " to " + format_number(s.a1) + " m, z " +
         format_number(s.z0) + " to " + format_number(s.z1) + " m";
}

std::string defined_at(const SourceLocation& where) {
  return where.known() ? " (defined at " + where.to_string() + ")" : "";
}

}  // namespace

std::vector<InteriorOpening> find_interior_windows(const std::vector<RoomSpec>& rooms, Diagnostics* diag) {
  std::vector<InteriorOpening> found;
  std::vector<Span> found_spans;
  for (const RoomSpec& room : rooms)
    for (const WindowSpec& w : room.windows) {
      const std::optional<Span> span = window_span(room, w);
      if (!span) continue;
      const Wall far_wall = opposite(w.wall);
      const double plane = plane_of(room, w.wall);
      const RoomSpec* into = nullptr;
      const RoomSpec* partly = nullptr;
      for (const RoomSpec& other : rooms) {
        if (&other == &room || std::fabs(plane_of(other, far_wall) - plane) > Tolerance_m) continue;
        const Span wall = wall_span(other, far_wall);
        if (!overlap(*span, wall)) continue;
        if (into || !inside(*span, wall)) {
          partly = &other;
          break;
        }
        into = &other;
      }
      const std::string what = "window '" + w.name + "' of room '" + room.name + "'";
      if (partly) {
        if (diag)
          report(*diag, w.location,
                 what + " (" + describe(*span, w.wall) + ") lies partly in the " + wall_name(far_wall) +
                     " wall of room '" + partly->name + "' (" + describe(wall_span(*partly, far_wall), w.wall) +
                     "): a window in a wall two rooms share must lie wholly inside the other room's wall "
                     "(an interior window) or wholly outside it");
        continue;
      }
      if (!into) continue;
      bool defined_twice = false;
      for (std::size_t k = 0; k < found.size() && !defined_twice; ++k)
        if (found[k].room == into && found[k].adjoining == &room && found[k].window->wall == far_wall &&
            overlap(*span, found_spans[k])) {
          if (diag)
            report(*diag, w.location,
                   what + " overlaps window '" + found[k].window->name + "' of room '" + into->name + "'" +
                       defined_at(found[k].window->location) +
                       " in the wall the rooms share: an interior window is defined once, in either room");
          defined_twice = true;
        }
      if (defined_twice) continue;
      const Span far = wall_span(*into, far_wall);
      InteriorOpening opening;
      opening.room = &room;
      opening.window = &w;
      opening.adjoining = into;
      opening.adjoining_wall = far_wall;
      // The same rectangle in the adjoining room's wall frame, snapped to its edges.
      opening.rect_in_adjoining.u0 = std::max(0.0, span->a0 - far.a0);
      opening.rect_in_adjoining.u1 = std::min(far.a1 - far.a0, span->a1 - far.a0);
      opening.rect_in_adjoining.v0 = std::max(0.0, span->z0 - far.z0);
      opening.rect_in_adjoining.v1 = std::min(far.z1 - far.z0, span->z1 - far.z0);
      found.push_back(opening);
      found_spans.push_back(*span);
    }
  return found;
}

std::set<std::string> rooms_lit_only_through_interior_windows(const Geometry& geometry) {
  const std::vector<InteriorOpening> openings = find_interior_windows(geometry.rooms, nullptr);
  std::set<std::string> out;
  for (const RoomSpec& room : geometry.rooms) {
    bool borrows = false, own_port = !room.roof_lights.empty();
    for (const InteriorOpening& o : openings) borrows = borrows || o.room == &room || o.adjoining == &room;
    for (const WindowSpec& w : room.windows) {
      bool interior = false;
      for (const InteriorOpening& o : openings) interior = interior || o.window == &w;
      own_port = own_port || !interior;
    }
    for (const SystemSpec& sys : geometry.systems)
      if (const auto* pipe = std::get_if<LightPipeSpec>(&sys.params))
        own_port = own_port || (sys.enabled && pipe->room == room.name);
    const Vec3 lo = room.origin, hi = room.origin + room.size_m;
    for (const PolygonSpec& poly : geometry.polygons) {
      if (!poly.port || poly.vertices.empty()) continue;
      Vec3 c{0, 0, 0};
      for (const Vec3& v : poly.vertices) c = c + v;
      c = c / double(poly.vertices.size());
      bool inside = true;
      for (int k = 0; k < 3; ++k) inside = inside && c[k] >= lo[k] - Tolerance_m && c[k] <= hi[k] + Tolerance_m;
      own_port = own_port || inside;
    }
    if (borrows && !own_port) out.insert(room.name);
  }
  return out;
}

std::string borrowed_light_room_of(const GridSpec& spec, const SensorGrid& grid, const std::vector<RoomSpec>& rooms,
                                   const std::set<std::string>& borrowed) {
  if (!spec.room.empty()) return borrowed.count(spec.room) ? spec.room : "";
  for (const RoomSpec& room : rooms) {
    if (!borrowed.count(room.name)) continue;
    const Vec3 lo = room.origin, hi = room.origin + room.size_m;
    for (const SensorPoint& p : grid.points) {
      bool inside = true;
      for (int k = 0; k < 3; ++k)
        inside = inside && p.position[k] >= lo[k] - Tolerance_m && p.position[k] <= hi[k] + Tolerance_m;
      if (inside) return room.name;
    }
  }
  return "";
}

}  // namespace detail

std::vector<InteriorWindow> interior_windows(const Geometry& geometry) {
  std::vector<InteriorWindow> out;
  for (const detail::InteriorOpening& o : detail::find_interior_windows(geometry.rooms, nullptr))
    out.push_back({o.room->name, o.window->name, o.adjoining->name});
  return out;
}

}  // namespace dayphoton::project
