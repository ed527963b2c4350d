// Port facing: which side of a port polygon is the room.
//
// Port emission (port_emission.h) sends photons from a port into the room along
// Port::normal, so that normal must point into the room whichever way the polygon was
// drawn: a roof light drawn facing the sky (the natural choice) would otherwise emit only
// the part of each sky patch that reaches it from below, 15 to 50 % too little light.
// Generated ports (room windows, enclosures, collectors) are wound into the room by
// construction. A polygon or mesh port says `facing: auto` (the default), `in` or `out`.
//
// Test: from PortFacingPoints points spread over the port (a 4 x 4 stratified lattice),
// PortFacingDirections well-spread directions over each side's hemisphere (spread_directions.h)
// are cast; a ray that hits nothing, not even another port, escapes to the sky. The sky
// fraction of a side is its share of escaping rays. The side that sees the sky is outside
// when it is decisive: its sky fraction is at least PortFacingMinSkyFraction and at least
// PortFacingSkyRatio times the other side's. Otherwise the rays cannot tell: both sides see
// the sky alike (a free-standing port) or neither does (a port between two rooms, a deep
// well).
//   Auto: decisive -> that side is outside (Sky); else the winding is kept (Ambiguous).
//   In/Out: the declared side; Contradicted when the rays decisively say it sees the sky.
// The project's placement check (study/placement_check.h) turns Ambiguous and Contradicted
// into located errors.
#pragma once

#include "dayphoton/core/scene_description.h"
#include "dayphoton/engine/port_set.h"

namespace dayphoton::engine {

class Scene;

constexpr int PortFacingPoints = 16;       ///< points on the port (4 x 4 strata)
constexpr int PortFacingDirections = 64;   ///< directions per point and side
/// Least sky fraction of the outside: 1 % (from the bottom of a 1 x 1 m roof-light well 1.5 m
/// deep, about 4 % of the directions reach the sky; a closed room's inside sees none).
constexpr double PortFacingMinSkyFraction = 0.01;
/// The outside must see at least this many times the inside's sky fraction.
constexpr double PortFacingSkyRatio = 2.0;

struct PortSideTest {
  double sky_fraction_winding = 0;   ///< from the side the winding normal points to
  double sky_fraction_opposite = 0;  ///< from the other side
};

/// The facing test of port `port` of `scene` (the port's current normal is ignored).
PortSideTest test_port_sides(const Scene& scene, const Port& port);

struct PortSideDecision {
  bool against_winding = false;
  PortSideReason reason = PortSideReason::Generated;
};

/// The decision for a port declared `facing` with test result `test` (header comment).
PortSideDecision decide_port_side(PortFacing facing, const PortSideTest& test);

}  // namespace dayphoton::engine
