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
#pragma once

#include <vector>

#include "dayphoton/engine/receiver_plane.h"
#include "dayphoton/engine/scene.h"

namespace dayphoton::engine {

/// How close to an outline edge both ends of a cut may lie for it to count as that edge
/// (a wall along the outline), metres.
constexpr double OnOutline_m = 1e-3;

/// The interior cuts of `plane` by `scene`'s surfaces, in triangle order (header comment).
std::vector<PlaneSegment> interior_plane_cuts(const Scene& scene, const ReceiverPlane& plane);

}  // namespace dayphoton::engine
