// Window frames: where a window lies in its room's wall, and the local frame in which the
// daylight systems attached to it are built (docs/daylight-systems.md, "Coordinates").
//
// Wall frame (the room generator's): a wall is origin + u * u_axis + v * (0, 0, 1) with u
// from the wall's lower-coordinate end (min x for south/north walls, min y for east/west)
// and v above the floor; `inward` is its normal into the room. A window's rectangle in it
// is [offset, offset + width] x [sill, sill + height] (centred when offset is absent),
// snapped to the wall's ends.
//
// Window frame (the systems'): right-handed, with e_w the wall's OUTWARD normal, e_v = +Z
// and e_u = e_v x e_w, which points to the right as seen from outside looking at the
// window. Its origin is the window's left edge (seen from outside) at floor level in the
// wall plane, so the window is u in [0, width], v in [sill, head], w = 0; heights in a
// system's keys are v directly, w > 0 is outside and w < 0 inside the room.
#pragma once

#include <string>
#include <vector>

#include "dayphoton/core/vec3.h"
#include "dayphoton/project/project.h"

namespace dayphoton::project::detail {

/// A wall in model space: p(u, v) = origin + u * u_axis + v * (0, 0, 1).
struct WallFrame {
  Vec3 origin;
  Vec3 u_axis;
  Vec3 inward;
  double length_m = 0;
};

WallFrame wall_frame(const RoomSpec& room, Wall wall);

/// A window's rectangle in wall coordinates.
struct WallRect {
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
};

/// The window's rectangle as the room generator cuts it (offset or centred; snapped to the
/// wall's ends within 1e-6 m). Does not validate (the room generator reports bad windows).
WallRect window_rect(const RoomSpec& room, const WindowSpec& window);

/// The frame of one window (see the header comment).
struct WindowFrame {
  const RoomSpec* room = nullptr;
  const WindowSpec* window = nullptr;
  Vec3 origin;              ///< model point of u = v = w = 0
  Vec3 e_u, e_v{0, 0, 1}, e_w;
  double width_m = 0;       ///< window: u in [0, width_m]
  double sill_m = 0, head_m = 0;  ///< window: v in [sill_m, head_m]
  double wall_u_min = 0, wall_u_max = 0;  ///< the wall's extent in u
  double room_height_m = 0;
  double room_depth_m = 0;  ///< wall to the opposite wall, along -e_w

  Vec3 at(double u, double v, double w) const { return origin + e_u * u + e_v * v + e_w * w; }
  /// Frame coordinates (u, v, w) of a model point.
  Vec3 local(const Vec3& p) const {
    const Vec3 d = p - origin;
    return {dot(d, e_u), dot(d, e_v), dot(d, e_w)};
  }
};

WindowFrame window_frame(const RoomSpec& room, const WindowSpec& window);

}  // namespace dayphoton::project::detail
