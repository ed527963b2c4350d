// Plane cuts: where the scene's surfaces cross a receiver plane inside its outline.
//
// A work plane at 0.8 m is not a surface, but a partition, a column or a tall cabinet
// crosses it. The light on the plane is discontinuous there (the lit side of a partition
// against its shadow), and a kernel disc that spans the cut would average the two: a bias
// that no number of photons removes, only a smaller disc. The cuts are found once per plane
// and the estimates keep to the part of each disc a sensor's position sees across them
// (plane_visibility.h).
//
// A cut is the segment where a triangle with vertices strictly on both sides of the plane
// crosses it (a triangle that only touches the plane, e.g. furniture whose top lies at the
// plane's height, blocks no photon crossing it), and an edge lying in the plane that
// triangles above and below it share (a partition of two panels meeting at the plane's
// height, a column mesh with a ring of vertices there). The room's own walls cut the plane along
// the outline, which the outline clip already handles: segments lying on the outline (both
// ends within OnOutline_m of one edge) or outside it are left out, and so are the openings
// (ports), which light passes. A segment that crosses the outline (a partition that runs on
// out of a grid outline smaller than the room) is split where it crosses, and the pieces
// inside are kept.
//
// Sensors next to a cut. Within a kernel disc's reach of a cut the light on the plane changes
// faster than the disc follows (the lit face's reflection in front of a column, the column's
// own shade behind it), even with the disc clipped to what the sensor sees: against a backward
// path-tracing reference, 0.1 m from a 0.4 m column the plane's estimate read -9 % in front
// and +19 % behind it, at 0.3 m within 2 %, from 0.5 m within the noise, while a final gather
// from the same points (final_gather.h) read within 1.8 % (docs/validation.md). So receiver-
// plane sensors nearer than NearCutGather_m to an interior cut are estimated by final gather
// (daylight_coefficients.h, GridPhotons::set_near_cut_gather); the room's walls are not cuts
// (0.1 m from them the plane's estimate is right: the outline clip and the local-linear fit).
#pragma once

#include <cstddef>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/engine/receiver_plane.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/engine/sensor_range.h"

namespace dayphoton::engine {

/// How close to an outline edge both ends of a cut may lie for it to count as that edge
/// (a wall along the outline), metres.
constexpr double OnOutline_m = 1e-3;

/// Receiver-plane sensors nearer than this to an interior cut of their plane are estimated
/// by final gather (header comment, "Sensors next to a cut"), metres.
constexpr double NearCutGather_m = 0.3;
/// A sensor counts as nearer than NearCutGather_m only by more than this, metres: on a grid
/// whose spacing divides the distance (sensors every 0.5 m, a cut 0.3 m from two of them on
/// either side) the rounding of the cut's and the sensor's coordinates would otherwise gather
/// one and not its mirror image.
constexpr double NearCutMargin_m = 1e-9;

/// A sensor nearer than this to an interior cut lies on it, metres: on a column's or a
/// partition's face, or on a thin partition itself. It has no illuminance of its own (half
/// of what it sees is the surface's inside: a final gather there reads the column's inside,
/// about 21 % relative standard error at a 0.4 m column's face), and `check` and `run` refuse
/// it as one inside a solid (study/placement_check.h). A millimetre: above the rounding of a
/// grid's and a face's coordinates and the ray offset of a room's scene (scene.h: 1e-5 of its
/// extent), below any spacing a grid is drawn at.
constexpr double OnCut_m = 1e-3;

/// The interior cuts of `plane` by `scene`'s surfaces, in triangle order (header comment).
/// `opaque_only`: by the surfaces light does not pass (not glass, openings or dielectrics, as
/// sensor_placement.h), for whether a sensor lies on one (OnCut_m): a sensor on a glass
/// partition or under a glass paperweight sees through it.
std::vector<PlaneSegment> interior_plane_cuts(const Scene& scene, const ReceiverPlane& plane, bool opaque_only = false);

/// The distance in the plane from (x, y) to the nearest of `plane`'s interior cuts, metres;
/// infinity without cuts.
double distance_to_interior_cut_m(const ReceiverPlane& plane, double x, double y);

/// The indices (ascending) of the sensors within `rows` whose position (x, y) lies nearer than
/// NearCutGather_m to one of `plane`'s interior cuts (set_interior_cuts), by more than
/// NearCutMargin_m.
std::vector<std::size_t> sensors_near_cuts(const ReceiverPlane& plane, const std::vector<SensorPoint>& sensors,
                                           SensorRange rows = {});

/// The indices (ascending) of the sensors whose position (x, y) lies nearer than OnCut_m to
/// one of `plane`'s interior cuts (set_interior_cuts): on the cut.
std::vector<std::size_t> sensors_on_cuts(const ReceiverPlane& plane, const std::vector<SensorPoint>& sensors);

}  // namespace dayphoton::engine
