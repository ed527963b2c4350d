// Placement check: what `check` and `run` refuse before anything is traced, because it would
// give plausible-looking but wrong numbers without a word:
//   - a project with no photon port (no window, no port polygon: no light can enter) or no
//     sensor;
//   - a port whose room side cannot be told (engine/port_facing.h: both sides see the sky or
//     neither) or whose declared `facing` puts the room on the side that sees the sky;
//   - sensors outside every room or inside a solid (engine/sensor_placement.h), and receiver-
//     plane sensors on an opaque surface crossing their plane (within engine::OnCut_m of a cut:
//     on a column's or partition's face, which the placement rays call in a room; part of what
//     such a sensor sees is the surface's inside, and its final gather next to the cut read
//     about 21 % relative standard error at a 0.4 m column's face), unless their set says
//     `drop_occluded: true`: then they are dropped and counted, and those on a surface named
//     in a located warning too.
// Every error is located (the project file, the port's polygon or OBJ face, the sensor set)
// and names the first offending sensors by index (0-based, as in sensors.csv) and position.
//
// And it warns (located, printed by `check`, written to run.log and the report's notes) where
// the numbers would be low without an error:
//   - sensors in a room (below the "outside every room" share) from which some placement
//     rays reach the sky without crossing a port: light enters only through ports, so what
//     comes through such a gap (a RADIANCE or OBJ room with an opening left as a hole, a
//     Honeybee face hole without an aperture, a leaky model) is not counted. A sensor facing
//     a 2 x 1 m gap in a black room (sky component 5.8 % through it) read only the window's
//     light. Named once per set, with its count and the sensor seeing most sky that way; a
//     gap under about one placement ray's share (1/64 of the hemisphere) can go unseen;
//   - a receiver-plane grid (horizontal room or polygon grid) whose outline reaches outside
//     every room: the plane counts the photons crossing it inside the outline, and none cross
//     beyond the walls, so the sensors within a kernel radius of that part read low (an
//     outline drawn 0.3 m past the walls of the reference office: 4-6.5 % at the sensors
//     0.5 m from them). Probes OutlineProbeInset_m inside the outline, every
//     OutlineProbeSpacing_m along it, are tested as sensors (engine/sensor_placement.h);
//   - geometry outside the ports that is not an outdoor scatterer and takes at least
//     ExteriorViewWarnFraction of an opening's outward view (an opening: the ports written as
//     one element, a window or a light pipe's collector of dome facets, their views weighted
//     by area): only its shadow is traced, not the light it reflects toward the window (a
//     0.4 m window reveal of reflectance 0.8 on the reference office: DF 12.7 % low).
//     Cosine-distributed rays from each port's outside; the
//     first surface hit is judged by its origin (Surface::origin): every input element is
//     named (a polygon, box or mesh without `outdoor: true`, a RADIANCE primitive whose
//     modifier is not listed under `outdoor`, a room of the generator seen from another's
//     port, a Honeybee face), located where it is written, with what makes its light traced;
//     only a daylight system's parts are not (their `port` says how their light is traced);
//   - a receiver-plane grid with glazing that is no port (glass, glazing, an opening, a
//     dielectric) inside its outline, some of it on the side its sensors face, tilted more
//     than 30 degrees from the plane (a pane lying over it, a light pipe's diffuser, sends a
//     smooth field down and is not named): an interior
//     glazed partition drawn as polygons, boxes, a mesh or an imported scene. The light the
//     rooms' surfaces send through it reaches the plane as photons alone, and the plane's
//     kernel blurs its sharp footprint (0.5 m behind a 1 m clear pane over a wall: 6-7 % low).
//     A room's own interior windows lie on its grid's outline (within GlazingOverPlaneEdge_m)
//     and are not named; a room lit only through them is gathered (project/scene_builder.cpp).
//
// And it notes (located, printed by `check`, written to run.log) the receiver-plane sensors
// nearer than engine::NearCutGather_m to a surface that crosses the work plane inside its
// outline (a column, a partition, tall furniture: engine/plane_cuts.h): there the light on the
// plane changes faster than the photon estimate's disc can follow, so those sensors are
// estimated by final gather inside their grid (engine/plane_cuts.h, "Sensors next to a cut"),
// unless the case would keep its surface photons for them alone and they are fewer than
// NearCutGatherMinShare (1 %) of every planar set (simulation_plan.h, near_cut_gathered): then it
// warns instead, with the remedies.
// The room's walls are not cuts (0.1 m from them the plane's estimate is right).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/source_location.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/daylight_openings.h"

namespace dayphoton::engine {
class Scene;
}

namespace dayphoton::study {

/// Offending sensors named in a message (the rest are counted).
constexpr std::size_t PlacementExamples = 3;
/// Outline probes: this far inside a receiver plane's outline, this far apart along it.
constexpr double OutlineProbeInset_m = 0.02;
constexpr double OutlineProbeSpacing_m = 0.1;
/// Glazing over a receiver plane (no port, passing light straight through): its centroid
/// farther than this inside the outline, and some of it farther than this on the side the
/// sensors face, is an interior glazed partition (a warning); nearer the outline it is a
/// room's own interior window.
constexpr double GlazingOverPlaneEdge_m = 0.01;
/// ... and standing across the plane: |cos| of the angle between their normals below this
/// (tilted more than 30 degrees from the plane); a pane lying over the plane is not named.
constexpr double GlazingOverPlaneMaxCos = 0.866;
/// Exterior geometry: rays per port (points x directions, both square lattices) and the share
/// of an opening's cosine-weighted outward view above which an element that only shades is named.
constexpr int ExteriorViewPoints = 16;
constexpr int ExteriorViewDirections = 256;
constexpr double ExteriorViewWarnFraction = 0.01;

struct SensorSetPlacement {
  std::string name;
  std::size_t sensors = 0;       ///< before dropping
  std::size_t outside = 0;       ///< outside every room
  std::size_t inside_solid = 0;  ///< inside a solid
  std::size_t on_cut = 0;        ///< on a surface crossing a receiver plane (engine::OnCut_m)
  std::size_t enclosed = 0;      ///< enclosed: no path reaches a port or the sky (engine::SensorPlacement)
  bool dropped = false;          ///< drop_occluded: the offending sensors were removed
  std::string description;       ///< one line for the log, the report and check
};

struct PlacementCheck {
  std::vector<SensorSetPlacement> sets;  ///< in the order of the grids
  std::vector<Diagnostic> warnings;      ///< located (header comment), in a fixed order
  std::vector<Diagnostic> notes;         ///< located, Severity::Note: sensors gathered next to a cut
  /// Per grid, EN 17037's openings (daylight_openings.h); empty unless the project computes
  /// annual metrics.
  std::vector<GridOpenings> openings;
  std::size_t dropped() const;
};

/// Run the checks on `scene` (built from `project`'s scene description, whose sensor sets are
/// `grids`). Sets with drop_occluded lose their offending sensors (a full lattice then stops
/// being one: columns = rows = 0). Throws InputError with every problem found; the
/// project-wide ones (no ports, no sensors) are located at the project file's first line, and
/// sensor positions are printed in model coordinates, as written.
PlacementCheck check_placement(const engine::Scene& scene, std::vector<SensorGrid>& grids,
                               const project::Project& project);

/// The checks for the base case and every variant of `project`, building each scene (and
/// everything build_scene_description and Scene::build validate) and discarding it: `run` calls
/// this for every project before it writes anything. Throws InputError.
void check_project_placement(const project::Project& project);

/// How port `port` of `scene` faces and why, for `check` ("into the room: the other side sees
/// the sky (62 % of the test rays, this side 0 %)").
std::string describe_port_facing(const engine::Scene& scene, std::size_t port);

}  // namespace dayphoton::study
