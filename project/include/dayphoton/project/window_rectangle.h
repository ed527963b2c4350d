// Where a window of the room generator lies, for code outside the project library (the
// EN 17037 sunlight exposure, study/sunlight_exposure.h): its rectangle in model coordinates,
// as the room generator cuts it (project/src/window_frame.h, the one place that says so).
#pragma once

#include "dayphoton/core/vec3.h"
#include "dayphoton/project/project.h"

namespace dayphoton::project {

/// A window's rectangle in model coordinates: the points left_bottom_m + u * along +
/// v * (0, 0, 1) for u in [0, width_m] and v in [0, height_m], in the wall's plane (the walls
/// of the room generator have no thickness, so the glazing lies in that plane).
struct WindowRectangle {
  Vec3 left_bottom_m;  ///< the window's left edge seen from outside, at its sill
  Vec3 along;          ///< unit, horizontal, to the right seen from outside
  Vec3 outward;        ///< unit, horizontal, out of the room
  double width_m = 0, height_m = 0;
  double sill_m = 0;   ///< above the room's floor
  double floor_z_m = 0;  ///< the room's floor, model z
};

/// The rectangle of `window` of `room` (offset or centred, snapped to the wall's ends).
WindowRectangle window_rectangle(const RoomSpec& room, const WindowSpec& window);

}  // namespace dayphoton::project
