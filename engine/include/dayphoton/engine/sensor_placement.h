// Sensor placement: whether a sensor lies in a room (where light from the ports can reach
// it), outside every room, or inside a solid. Photons enter only through the ports, so a
// sensor in open air outside gets almost nothing (a daylight factor of 0.0001 %) and one
// inside a column only what leaks through its faces (0.8 %), both without a word; `check`
// and `run` refuse them (study/placement_check.h).
//
// Test: SensorPlacementRays well-spread directions over the hemisphere the sensor faces
// (spread_directions.h; the whole sphere for a sensor without a normal) are cast from the
// sensor's position moved 10 ray epsilons along its normal (so a sensor on a surface,
// facing away from it, does not see that surface). Each ray passes through ports and
// transparent surfaces (glass, openings, dielectrics), noting whether it crossed a port,
// and stops at the first other surface or escapes to the sky.
//   - outside every room: at least SensorOutsideSkyFraction of the rays escape to the sky
//     without crossing a port (in a closed room none does: every way out is a port or a
//     wall);
//   - inside a solid: no ray reaches a port or the sky, and at least SensorInsideSolidFraction
//     of the rays stop at the back of a solid's face (Surface::solid_face: boxes and OBJ
//     meshes, wound outward), and then a ray aimed at each port's centroid does not reach it
//     either (a room drawn as a mesh wound outward sees its windows). Polygons count as thin,
//     two-sided sheets (shelves, slats, walls of either winding), so the back of a polygon
//     never means "inside";
//   - enclosed: no spread ray reaches a port or the sky, no ray aimed at a port's centroid
//     reaches it, and none of SensorEnclosureWalks walks of up to SensorEnclosureBounces
//     bounces crosses a port. That is a sensor inside a closed volume drawn from polygons (a
//     column of four faces meeting the floor and the ceiling), or in a room whose openings
//     are all opaque, missing or not ports: photons enter only through the ports, so such a
//     sensor reads only what leaks through the faces' joints (measured inside a 0.6 m polygon
//     column of the office: DF 0.0004 %). A walk goes where light could come from: straight on
//     through ports and transparent surfaces, mirror-like off mirrors and metals (a light
//     pipe's tube), straight on or diffusely back with even odds off surfaces that may
//     transmit (translucent, glazing systems, registered and BSDF models), diffusely
//     (cosine-distributed, on the side it came from) off every other surface, whatever its
//     reflectance. Only a port crossing counts: a walk out through a gap in the drawing has
//     found no way for photons to come in. The walks stop at the first that crosses a port.
//     test_sensor_placements walks from a sensor only when it sees none of the last
//     SensorEnclosureNeighbours sensors so tested (no surface between them): one it sees is in
//     the same volume and shares that one's verdict (SensorPlacementTest::same_volume_as), so
//     a grid in one closed room walks once;
//   - in a room otherwise.
// Cost: SensorPlacementRays rays (plus one per transparent surface crossed) per sensor, one per
// port for a sensor that looks inside a solid or sees no port, and for those that still see
// none up to SensorEnclosureNeighbours visibility rays and, where none is shared, the walks
// until one crosses a port (behind a partition: a few walks; enclosed: all of them, about
// SensorEnclosureWalks x SensorEnclosureBounces rays, spread over the threads).
//
// Why the walks cannot miss a real way out in practice: with albedo ignored, a walk in a room
// of surface area A meets an opening of area a at each bounce with a probability of about
// a / A, so the walks' SensorEnclosureWalks x SensorEnclosureBounces bounces meet a 1 m^2 roof
// light in a 20 x 20 x 3 m hall (a / A = 1 / 1040) about 31 times on average; the chance that
// none does is e^-31.
#pragma once

#include <cstddef>
#include <vector>

#include "dayphoton/core/scene_description.h"

namespace dayphoton::engine {

class Scene;

constexpr int SensorPlacementRays = 64;
/// "Most rays escape" (the least share that means outside): a quarter, since a sensor outside
/// a facade and facing it sees the building in much of its hemisphere.
constexpr double SensorOutsideSkyFraction = 0.25;
/// A sensor inside a box sees the back of its faces in every direction; where the solid
/// touches another surface (a column under the ceiling) a few rays may stop there first.
constexpr double SensorInsideSolidFraction = 0.75;
/// Transparent surfaces a placement ray passes through before it gives up (counted as
/// stopped at a surface).
constexpr int SensorPlacementMaxCrossings = 32;
/// The enclosure test's walks and bounces per walk (header comment).
constexpr int SensorEnclosureWalks = 1024;
constexpr int SensorEnclosureBounces = 32;
/// The sensors already tested a sensor that needs walks looks at first (header comment).
constexpr std::size_t SensorEnclosureNeighbours = 8;

enum class SensorPlacement { InRoom, OutsideRooms, InsideSolid, Enclosed };

struct SensorPlacementTest {
  SensorPlacement placement = SensorPlacement::InRoom;
  int rays = 0;
  int sky_without_port = 0;   ///< rays escaping to the sky without crossing a port
  int through_port = 0;       ///< rays that crossed a port (escaping or not)
  int back_of_solid = 0;      ///< rays stopped at the back of a solid's face
  int solid_surface = -1;     ///< inside a solid: the surface most rays stopped at the back of
  int enclosure_walks = 0;    ///< walks traced (0: it saw a port or the sky, or shares a verdict)
  int same_volume_as = -1;    ///< test_sensor_placements: the walked sensor whose verdict it shares
};

SensorPlacementTest test_sensor_placement(const Scene& scene, const SensorPoint& sensor);

/// test_sensor_placement for every sensor, in parallel; results in the sensors' order.
std::vector<SensorPlacementTest> test_sensor_placements(const Scene& scene, const std::vector<SensorPoint>& sensors);

}  // namespace dayphoton::engine
