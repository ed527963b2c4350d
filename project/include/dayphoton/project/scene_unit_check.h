// Is an imported scene plausible in metres? A cheap test of the heights of its lit rooms, for
// a scene read without a `units` key (docs/radiance-import.md, "Units").
//
// A scene's unit cannot be read from its shape (a room 10 x 12 x 9 units is a room in feet or
// a hall in metres); it can be read from what people use: the height between a floor and the
// ceiling above it. The test:
//   1. Horizontal facets (|n_z| >= UnitCheckHorizontalCos of the Newell normal), at most
//      UnitCheckMaxHorizontalFacets of them, the largest first.
//   2. Each one's clearance: from its centroid (if inside it) straight up to the nearest
//      horizontal facet above that covers that point (a floor to its ceiling, a ceiling to the
//      slab above, a desk to the ceiling).
//   3. Only lit clearances count: some glazed facet's bounding box meets the space between the
//      two (the facet's extent, widened by UnitCheckLitMargin of the clearance, from its height
//      to the one above). A room has windows or roof lights; the massing of a neighbouring
//      block, a column or a desk away from the windows has none.
//   4. Each lit clearance c, weighted by its facet's area, is plausible in a unit of f metres
//      if c f lies in [PlausibleRoomHeightMin_m, PlausibleRoomHeightMax_m], from a low attic
//      room to a double-height space.
//   5. A unit is suggested when its plausible area is more than UnitCheckDominance times the
//      metre's: rooms 9.8 units high (a 3 m room in feet), 3000 (in millimetres), 118 (in
//      inches). A metric building with ordinary rooms anywhere in it, a 30 m atrium, a
//      50 x 50 m floor, context massing and a scene without rooms are not flagged. Not told
//      apart: a building of metric halls 7 to 20 m high and nothing lower, which reads as feet;
//      writing `units: Meters` says so and silences the warning.
// The cost: a few point-in-polygon tests per pair of horizontal facets whose bounding boxes
// overlap, once per scene.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dayphoton/core/vec3.h"

namespace dayphoton::project {

/// Room heights taken as plausible, metres: a low attic room to a double-height space.
constexpr double PlausibleRoomHeightMin_m = 2.1;
constexpr double PlausibleRoomHeightMax_m = 7.0;
/// A facet is horizontal when its unit normal's |z| is at least this (2.6 degrees).
constexpr double UnitCheckHorizontalCos = 0.999;
/// Horizontal facets examined, the largest first (the test is quadratic in them).
constexpr std::size_t UnitCheckMaxHorizontalFacets = 2000;
/// A glazed facet lights a clearance when its box meets the facet's widened by this share of
/// the clearance (a window in the wall at the floor's edge).
constexpr double UnitCheckLitMargin = 0.02;
/// Another unit is suggested when its plausible area exceeds the metre's this many times.
constexpr double UnitCheckDominance = 4.0;

/// One facet of the scene as read, coordinates taken as metres.
struct UnitCheckFacet {
  std::vector<Vec3> vertices;
  bool glazed = false;  ///< lets light through (a port candidate)
};

/// What the test found when another unit fits the rooms better.
struct SceneUnitSuggestion {
  std::string units;          ///< a length_units.h name: Feet, Inches, Millimeters, Centimeters
  double metres_per_unit = 1;
  double room_height_as_read = 0;  ///< area-weighted median of the lit clearances it explains, as read
  double room_height_m = 0;        ///< the same in that unit, metres
  double share = 0;                ///< its plausible area over all lit clearances' area
};

/// The unit the rooms of `facets` suggest, if not the metre (header); nothing when the scene
/// is plausible in metres, or has no lit rooms to judge by.
std::optional<SceneUnitSuggestion> suggest_scene_units(const std::vector<UnitCheckFacet>& facets);

}  // namespace dayphoton::project
