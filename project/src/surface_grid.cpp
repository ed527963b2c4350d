// Wall and rectangle sensor grids (model coordinates; build_scene_description rotates them).
//
// Both are a lattice over a parallelogram P(s, t) = origin + s u + t v, s, t in [0, 1],
// with the sensors facing the unit normal n and moved offset_m along it:
//   - rectangle: the given origin, u and v; n = normalize(u x v) (right-hand rule: with the
//     fingers of the right hand curling from u to v, the thumb is n).
//   - wall reference: the room surface's rectangle with n into the room. In a room with
//     origin o and size (X, Y, Z):
//         surface   origin            u            v            n
//         south     o + (X, 0, 0)     (-X, 0, 0)   (0, 0, Z)    +y
//         north     o + (0, Y, 0)     (X, 0, 0)    (0, 0, Z)    -y
//         east      o + (X, Y, 0)     (0, -Y, 0)   (0, 0, Z)    -x
//         west      o                 (0, Y, 0)    (0, 0, Z)    +x
//         floor     o                 (X, 0, 0)    (0, Y, 0)    +z
//         ceiling   o + (0, 0, Z)     (X, 0, 0)    (0, Y, 0)    -z
//     For the walls n = u x v: seen from inside the room, u runs left to right and v up.
//     The floor and ceiling share the room grid's order (x inner, y outer), so the ceiling
//     is the one surface whose n is v x u.
// Lattice: along u and v the centred lattice of sensor_grid.cpp, `spacing_m` apart, over
// the parallelogram shrunk by `inset_m` measured perpendicular to its edges (along u that is
// inset / sin(angle between u and v), 1 for a rectangle). Order: v outer, u inner, both
// ascending: index = columns * iv + iu.
// Windows: on a wall, lattice points in a window of that wall or closer than inset_m to its
// rectangle are left out (a sensor there would lie on the glazing); the grid then has no
// columns/rows (as polygon grids), since index = columns * iv + iu no longer holds.
// The outline is the parallelogram's corners moved offset_m along n (the sensors' plane).
// These grids are not receiver planes (planar = false), even when horizontal: the engine
// estimates them as point sensors; plane_normal = n and plane_height_m = n . (a point of
// the sensors' plane) describe their plane.
#include <algorithm>
#include <cmath>
#include <string>

#include "dayphoton/core/diagnostics.h"
#include "geometry_generators.h"
#include "window_frame.h"

namespace dayphoton::project::detail {

namespace {

/// Edges shorter than this, or |u x v| below this fraction of |u| |v|, are degenerate.
constexpr double MinEdge_m = 1e-9;
constexpr double MinSine = 1e-6;

struct Frame {
  Vec3 origin, u, v, normal;
};

Frame surface_frame(const RoomSpec& room, RoomSurface surface) {
  const Vec3 o = room.origin, s = room.size_m;
  const Vec3 up{0, 0, s.z};
  switch (surface) {
    case RoomSurface::South: return {o + Vec3{s.x, 0, 0}, {-s.x, 0, 0}, up, {0, 1, 0}};
    case RoomSurface::North: return {o + Vec3{0, s.y, 0}, {s.x, 0, 0}, up, {0, -1, 0}};
    case RoomSurface::East: return {o + Vec3{s.x, s.y, 0}, {0, -s.y, 0}, up, {-1, 0, 0}};
    case RoomSurface::West: return {o, {0, s.y, 0}, up, {1, 0, 0}};
    case RoomSurface::Floor: return {o, {s.x, 0, 0}, {0, s.y, 0}, {0, 0, 1}};
    case RoomSurface::Ceiling: return {o + up, {s.x, 0, 0}, {0, s.y, 0}, {0, 0, -1}};
  }
  return {o, {s.x, 0, 0}, {0, s.y, 0}, {0, 0, 1}};
}

bool is_wall(RoomSurface s) { return s != RoomSurface::Floor && s != RoomSurface::Ceiling; }

/// Distance in the wall plane from `p` (on the wall) to the window's rectangle, 0 inside.
double distance_to_window_m(const RoomSpec& room, const WindowSpec& window, const Vec3& p) {
  const WallFrame wall = wall_frame(room, window.wall);
  const WallRect r = window_rect(room, window);
  const double u = dot(p - wall.origin, wall.u_axis), v = p.z - room.origin.z;
  const double du = std::max({r.u0 - u, 0.0, u - r.u1}), dv = std::max({r.v0 - v, 0.0, v - r.v1});
  return std::hypot(du, dv);
}

}  // namespace

bool generate_surface_grid(const GridSpec& spec, const std::vector<RoomSpec>& rooms, std::uint64_t max_points,
                           Diagnostics& diag, SensorGrid& out) {
  const std::string what = "grid '" + spec.name + "'";
  bool ok = true;
  if (!check_spacing_and_inset(spec, what, diag)) ok = false;
  if (!std::isfinite(spec.offset_m) || spec.offset_m < 0) {
    report(diag, spec.location_of("offset"), what + ": offset must be >= 0");
    ok = false;
  }

  Frame f;
  const RoomSpec* room = nullptr;
  std::string surface_text;  // for messages
  if (spec.wall) {
    room = find_grid_room(spec.wall->room, rooms, diag, spec.location_of("wall.room"), what);
    if (!room) return false;
    if (!is_finite(room->origin) || !is_finite(room->size_m)) return false;  // reported by the room
    f = surface_frame(*room, spec.wall->surface);
    surface_text = std::string("the ") + room_surface_name(spec.wall->surface) +
                   (is_wall(spec.wall->surface) ? " wall" : "") + " of room '" + room->name + "' (" +
                   format_number(length(f.u)) + " x " + format_number(length(f.v)) + " m)";
  } else {
    const GridSpec::Rectangle& r = *spec.rectangle;
    const char* keys[3] = {"origin", "u", "v"};
    const Vec3* vectors[3] = {&r.origin, &r.u, &r.v};
    for (int i = 0; i < 3; ++i)
      if (!is_finite(*vectors[i])) {
        report(diag, spec.location_of(std::string("rectangle.") + keys[i]),
               what + ": '" + keys[i] + "' is not finite");
        ok = false;
      }
    if (!ok) return false;
    const double lu = length(r.u), lv = length(r.v);
    if (!(lu > MinEdge_m)) {
      report(diag, spec.location_of("rectangle.u"), what + ": edge vector 'u' is zero");
      ok = false;
    }
    if (!(lv > MinEdge_m)) {
      report(diag, spec.location_of("rectangle.v"), what + ": edge vector 'v' is zero");
      ok = false;
    }
    if (ok && !(length(cross(r.u, r.v)) > MinSine * lu * lv)) {
      report(diag, spec.location_of("rectangle.v"),
             what + ": edge vectors 'u' and 'v' are parallel: they span no rectangle");
      ok = false;
    }
    if (!ok) return false;
    f = {r.origin, r.u, r.v, normalize(cross(r.u, r.v))};
    surface_text = "the rectangle (" + format_number(lu) + " x " + format_number(lv) + " m)";
  }
  if (!ok) return false;

  const double lu = length(f.u), lv = length(f.v);
  const Vec3 eu = f.u / lu, ev = f.v / lv;
  const double sine = length(cross(eu, ev));
  const double inset_along_m = spec.inset_m / sine;  // inset perpendicular to the edges
  double u_first = 0, v_first = 0;
  const double nu_count = lattice(lu - 2 * inset_along_m, spec.spacing_m, u_first);
  const double nv_count = lattice(lv - 2 * inset_along_m, spec.spacing_m, v_first);
  if (!(nu_count * nv_count <= static_cast<double>(max_points))) {
    report(diag, spec.spacing_location.known() ? spec.spacing_location : spec.location,
           limit_message(what + " (" + format_number(nu_count) + " x " + format_number(nv_count) + " at spacing " +
                             format_number(spec.spacing_m) + " m over " + surface_text + ")",
                         nu_count * nv_count, max_points));
    return false;
  }
  const int nu = static_cast<int>(nu_count), nv = static_cast<int>(nv_count);
  if (nu <= 0 || nv <= 0) {
    report(diag, spec.location_of("inset"),
           what + " has no points: the inset (" + format_number(spec.inset_m) + " m) leaves nothing of " +
               surface_text);
    return false;
  }

  out = SensorGrid{};
  out.name = spec.name;
  out.location = spec.location;
  out.drop_occluded = spec.drop_occluded;
  out.spacing_m = spec.spacing_m;
  const Vec3 shift = f.normal * spec.offset_m;
  const double tolerance_m = 1e-9 * std::max({1.0, lu, lv});
  std::size_t left_out = 0;
  for (int iv = 0; iv < nv; ++iv)
    for (int iu = 0; iu < nu; ++iu) {
      const Vec3 on_surface = f.origin + eu * (inset_along_m + u_first + iu * spec.spacing_m) +
                              ev * (inset_along_m + v_first + iv * spec.spacing_m);
      bool in_window = false;
      if (spec.wall && is_wall(spec.wall->surface))
        for (const WindowSpec& w : room->windows) {
          if (std::string(wall_name(w.wall)) != room_surface_name(spec.wall->surface)) continue;
          const double d = distance_to_window_m(*room, w, on_surface);
          if (d <= tolerance_m || d < spec.inset_m - tolerance_m) in_window = true;
        }
      if (in_window) {
        ++left_out;
        continue;
      }
      out.points.push_back({on_surface + shift, f.normal});
    }
  if (out.points.empty()) {
    report(diag, spec.location,
           what + " has no points: every lattice point of " + surface_text + " lies in a window or within the inset (" +
               format_number(spec.inset_m) + " m) of one");
    return false;
  }
  if (left_out == 0) {
    out.columns = nu;
    out.rows = nv;
  }
  out.outline = {f.origin + shift, f.origin + f.u + shift, f.origin + f.u + f.v + shift, f.origin + f.v + shift};
  out.planar = false;
  out.plane_normal = f.normal;
  out.plane_height_m = dot(f.normal, f.origin + shift);
  return true;
}

}  // namespace dayphoton::project::detail
