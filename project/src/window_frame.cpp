// Wall and window frames (see window_frame.h): the one place that says where a window is,
// shared by the room generator (which cuts it out) and the daylight-system generators
// (which are placed relative to it).
#include "window_frame.h"

#include <algorithm>

#include "dayphoton/project/window_rectangle.h"

namespace dayphoton::project::detail {

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

WallRect window_rect(const RoomSpec& room, const WindowSpec& w) {
  constexpr double SnapTolerance_m = 1e-6;
  const WallFrame frame = wall_frame(room, w.wall);
  WallRect r;
  r.u0 = w.offset_m ? *w.offset_m : 0.5 * (frame.length_m - w.width_m);
  r.u1 = r.u0 + w.width_m;
  r.v0 = w.sill_m;
  r.v1 = w.sill_m + w.height_m;
  if (r.u0 < 0 && r.u0 >= -SnapTolerance_m) r.u0 = 0;
  if (r.u1 > frame.length_m && r.u1 <= frame.length_m + SnapTolerance_m) r.u1 = frame.length_m;
  if (r.v1 > room.size_m.z && r.v1 <= room.size_m.z + SnapTolerance_m) r.v1 = room.size_m.z;
  return r;
}

WindowFrame window_frame(const RoomSpec& room, const WindowSpec& window) {
  const WallFrame wall = wall_frame(room, window.wall);
  const WallRect r = window_rect(room, window);
  WindowFrame f;
  f.room = &room;
  f.window = &window;
  f.e_w = wall.inward * -1.0;
  f.e_v = {0, 0, 1};
  f.e_u = cross(f.e_v, f.e_w);
  const bool same = dot(f.e_u, wall.u_axis) > 0;
  // The window's left edge seen from outside is its minimum along e_u.
  const double left_wall_u = same ? r.u0 : r.u1;
  f.origin = wall.origin + wall.u_axis * left_wall_u;
  f.width_m = r.u1 - r.u0;
  f.sill_m = r.v0;
  f.head_m = r.v1;
  f.wall_u_min = same ? -r.u0 : r.u1 - wall.length_m;
  f.wall_u_max = same ? wall.length_m - r.u0 : r.u1;
  f.room_height_m = room.size_m.z;
  f.room_depth_m = (window.wall == Wall::South || window.wall == Wall::North) ? room.size_m.y
                                                                               : room.size_m.x;
  return f;
}

}  // namespace dayphoton::project::detail

namespace dayphoton::project {

WindowRectangle window_rectangle(const RoomSpec& room, const WindowSpec& window) {
  const detail::WindowFrame f = detail::window_frame(room, window);
  WindowRectangle r;
  r.along = f.e_u;
  r.outward = f.e_w;
  r.width_m = f.width_m;
  r.sill_m = f.sill_m;
  r.height_m = f.head_m - f.sill_m;
  r.floor_z_m = room.origin.z;
  r.left_bottom_m = f.at(0, f.sill_m, 0);
  return r;
}

}  // namespace dayphoton::project
