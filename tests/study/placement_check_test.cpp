// Placement checks (study/placement_check.h), from project text to located errors: sensors
// inside a column or outside every room, a project without ports or sensors, ports whose room
// side cannot be told or is declared wrong; and drop_occluded, which drops and counts
// instead. `check` (app/model_summary.cpp) and `run` (study_runner.cpp) call the same check.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/placement_check.h"
#include "placement_project_text.h"
#include "../temp_folder.h"

namespace dayphoton::study {
namespace {

const std::string& Head = PlacementHead;
const std::string& Office = PlacementOffice;

struct Outcome {
  std::vector<std::string> errors;  ///< "line:col: message"
  PlacementCheck check;
  std::vector<SensorGrid> grids;
};

Outcome check_text(const std::string& text) {
  Outcome out;
  try {
    const project::Project p = project::load_project_from_string(text, "placement.yaml");
    SceneDescription d = project::build_scene_description(p);
    const engine::Scene scene = engine::Scene::build(d);
    out.check = check_placement(scene, d.grids, p);
    out.grids = d.grids;
  } catch (const InputError& e) {
    for (const Diagnostic& d : e.diagnostics())
      out.errors.push_back(std::to_string(d.location.line) + ":" + std::to_string(d.location.column) + ": " +
                           d.message);
  }
  return out;
}

TEST(PlacementCheck, SensorsInsideAColumnAreALocatedError) {
  // A grid through a 0.6 x 0.6 m column: room grid points x = 0.5 .. 5.5, y = 0.5 .. 7.5
  // every 0.5 m; the column covers x, y in (2.7, 3.3) x (3.7, 4.3): the sensor at (3, 4),
  // column 5 of row 7, index 5 + 7 x 11 = 82, only.
  const Outcome o = check_text(Head + Office + R"(  boxes:
    - {name: column, origin: [2.7, 3.7, 0], size: [0.6, 0.6, 3], material: walls}
sensors:
  grids:
    - {name: workplane, room: office, height: 0.8, spacing: 0.5, inset: 0.5}
)");
  ASSERT_EQ(o.errors.size(), 1u);
  EXPECT_EQ(o.errors[0].rfind("17:7: sensor set 'workplane': 1 of 165 sensors lie inside a solid (sensor 82 at (3, 4, "
                              "0.8) m sees only the back of 'column.",
                              0),
            0u)
      << o.errors[0];
  EXPECT_NE(o.errors[0].find("drop_occluded: true"), std::string::npos);
}

TEST(PlacementCheck, DropOccludedDropsAndCountsThem) {
  const Outcome o = check_text(Head + Office + R"(  boxes:
    - {name: column, origin: [2.7, 3.7, 0], size: [0.6, 0.6, 3], material: walls}
sensors:
  grids:
    - {name: workplane, room: office, height: 0.8, spacing: 0.5, inset: 0.5, drop_occluded: true}
  points:
    - name: probes
      drop_occluded: true
      points: [[3, 2, 0.8, 0, 0, 1], [3, 4, 10, 0, 0, 1], [3, 5, 1, 0, 0, 1]]
)");
  ASSERT_TRUE(o.errors.empty()) << o.errors[0];
  ASSERT_EQ(o.check.sets.size(), 2u);
  EXPECT_TRUE(o.check.sets[0].dropped);
  EXPECT_EQ(o.check.sets[0].inside_solid, 1u);
  EXPECT_EQ(o.grids[0].points.size(), 164u);
  EXPECT_EQ(o.grids[0].columns, 0);  // no longer a full lattice
  EXPECT_EQ(o.check.sets[1].outside, 1u);
  ASSERT_EQ(o.grids[1].points.size(), 2u);
  EXPECT_EQ(o.grids[1].points[1].position.y, 5.0);
  EXPECT_EQ(o.check.dropped(), 2u);
}

// Sensors on a column's faces (engine::OnCut_m): the placement rays see the room from there,
// but half of what such a sensor sees is the column's inside, so it is refused as one inside
// the column is. A 1 m column at x, y 2.5-3.5 x 3.5-4.5 and a grid every 0.5 m from 0.5 m: the
// sensors of columns 4-6 (x 2.5, 3, 3.5) and rows 6-8 (y 3.5, 4, 4.5) lie on its faces (8,
// the first, index 4 + 6 x 11 = 70, at its corner (2.5, 3.5)), the one at (3, 4) inside it.
std::string column_with_face_sensors(const std::string& grid_extra) {
  return Head + Office + R"(  boxes:
    - {name: column, origin: [2.5, 3.5, 0], size: [1, 1, 3], material: walls}
sensors:
  grids:
    - {name: workplane, room: office, height: 0.8, spacing: 0.5, inset: 0.5)" + grid_extra + "}\n";
}

TEST(PlacementCheck, SensorsOnAColumnsFaceAreRefusedAsInsideOnes) {
  const Outcome o = check_text(column_with_face_sensors(""));
  ASSERT_EQ(o.errors.size(), 1u);
  EXPECT_EQ(o.errors[0].rfind("17:7: sensor set 'workplane': 9 of 165 sensors lie inside a solid (1) or on a surface "
                              "that crosses the work plane (8) (sensor 70 at (2.5, 3.5, 0.8) m lies on a column's or a "
                              "partition's face;",
                              0),
            0u)
      << o.errors[0];
  EXPECT_NE(o.errors[0].find("no illuminance of its own"), std::string::npos) << o.errors[0];
  EXPECT_NE(o.errors[0].find("drop_occluded: true"), std::string::npos) << o.errors[0];

  // With drop_occluded they are dropped and counted, and a located warning names them.
  const Outcome d = check_text(column_with_face_sensors(", drop_occluded: true"));
  ASSERT_TRUE(d.errors.empty()) << d.errors[0];
  ASSERT_EQ(d.check.sets.size(), 1u);
  EXPECT_TRUE(d.check.sets[0].dropped);
  EXPECT_EQ(d.check.sets[0].inside_solid, 1u);
  EXPECT_EQ(d.check.sets[0].on_cut, 8u);
  EXPECT_EQ(d.check.dropped(), 9u);
  EXPECT_EQ(d.grids[0].points.size(), 156u);
  for (const SensorPoint& p : d.grids[0].points)
    EXPECT_FALSE(p.position.x >= 2.5 && p.position.x <= 3.5 && p.position.y >= 3.5 && p.position.y <= 4.5);
  ASSERT_EQ(d.check.warnings.size(), 1u);
  EXPECT_EQ(d.check.warnings[0].location.line, 17);
  EXPECT_NE(d.check.warnings[0].message.find("sensor 70 at (2.5, 3.5, 0.8) m lies on a column's or a partition's face"),
            std::string::npos)
      << d.check.warnings[0].message;
  EXPECT_NE(d.check.warnings[0].message.find("dropped (drop_occluded)"), std::string::npos);

  // 2 mm inside the faces (the column 4 mm narrower) they are sensors in the room next to a cut.
  const Outcome off = check_text(Head + Office + R"(  boxes:
    - {name: column, origin: [2.502, 3.502, 0], size: [0.996, 0.996, 3], material: walls}
sensors:
  grids:
    - {name: workplane, room: office, height: 0.8, spacing: 0.5, inset: 0.5, drop_occluded: true}
)");
  ASSERT_TRUE(off.errors.empty()) << off.errors[0];
  EXPECT_EQ(off.check.sets[0].on_cut, 0u);
  EXPECT_EQ(off.check.sets[0].inside_solid, 1u);
}

// A column drawn from four polygons (as models from other tools draw one) is no solid, but a
// sensor inside it is in a closed volume no light enters (engine/sensor_placement.h): refused,
// or dropped and counted apart. Before, it read DF 0.0004 % without a word.
std::string polygon_column(const std::string& grid_extra) {
  return Head + Office + R"(  polygons:
    - {name: col_s, vertices: [[2.7, 3.7, 0], [3.3, 3.7, 0], [3.3, 3.7, 3], [2.7, 3.7, 3]], material: walls}
    - {name: col_e, vertices: [[3.3, 3.7, 0], [3.3, 4.3, 0], [3.3, 4.3, 3], [3.3, 3.7, 3]], material: walls}
    - {name: col_n, vertices: [[3.3, 4.3, 0], [2.7, 4.3, 0], [2.7, 4.3, 3], [3.3, 4.3, 3]], material: walls}
    - {name: col_w, vertices: [[2.7, 4.3, 0], [2.7, 3.7, 0], [2.7, 3.7, 3], [2.7, 4.3, 3]], material: walls}
sensors:
  grids:
    - {name: workplane, room: office, height: 0.8, spacing: 0.5, inset: 0.5)" + grid_extra + "}\n";
}

TEST(PlacementCheck, SensorsInAColumnOfPolygonsAreRefusedAsEnclosed) {
  const Outcome o = check_text(polygon_column(""));
  ASSERT_EQ(o.errors.size(), 1u);
  EXPECT_EQ(o.errors[0].rfind("20:7: sensor set 'workplane': 1 of 165 sensors lie in a closed volume no light enters "
                              "(a column or solid drawn from polygons, or a room whose openings are opaque, missing or not "
                              "ports) (sensor 82 at (3, 4, 0.8) m reaches no port by 1024 random paths",
                              0),
            0u)
      << o.errors[0];
  EXPECT_NE(o.errors[0].find("drop_occluded: true"), std::string::npos) << o.errors[0];

  const Outcome d = check_text(polygon_column(", drop_occluded: true"));
  ASSERT_TRUE(d.errors.empty()) << d.errors[0];
  EXPECT_EQ(d.check.sets[0].enclosed, 1u);
  EXPECT_EQ(d.check.sets[0].inside_solid, 0u);
  EXPECT_EQ(d.check.dropped(), 1u);
  ASSERT_EQ(d.grids[0].points.size(), 164u);
  for (const SensorPoint& p : d.grids[0].points) EXPECT_FALSE(p.position.x == 3 && p.position.y == 4);
}

TEST(PlacementCheck, ARoomWithoutOpeningsIsEnclosed) {
  // A store room beside the office with no window: its sensors can receive no daylight.
  const Outcome o = check_text(Head + Office + R"(    - name: store
      origin: [6, 0, 0]
      size: [2, 2, 3]
      materials: {floor: walls, ceiling: walls, walls: walls}
sensors:
  grids:
    - {name: office_plane, room: office, height: 0.8, spacing: 1, inset: 0.5}
    - {name: store_plane, room: store, height: 0.8, spacing: 1, inset: 0.5}
)");
  ASSERT_EQ(o.errors.size(), 1u);
  EXPECT_NE(o.errors[0].find("sensor set 'store_plane': 4 of 4 sensors lie in a closed volume no light enters"),
            std::string::npos)
      << o.errors[0];
}

TEST(PlacementCheck, SensorsOutsideEveryRoomAreALocatedError) {
  const Outcome o = check_text(Head + Office + R"(sensors:
  points:
    - name: probes
      points: [[3, 2, 0.8, 0, 0, 1], [3, 4, 10, 0, 0, 1], [3, -2, 1, 0, 0, 1]]
)");
  ASSERT_EQ(o.errors.size(), 1u);
  // Sensor 2, 2 m in front of the facade, sees the building in a fifth of its hemisphere.
  EXPECT_EQ(o.errors[0], "15:7: sensor set 'probes': 2 of 3 sensors lie outside every room (sensor 1 at (3, 4, 10) m "
                         "sees the sky without a port in 100 % of its hemisphere; sensor 2 at (3, -2, 1) m sees the "
                         "sky without a port in 80 % of its hemisphere); they would read (almost) no light. Move "
                         "them into a room, or give the set 'drop_occluded: true' to leave them out");
}

TEST(PlacementCheck, SensorsAreNamedInModelCoordinates) {
  // A site rotated 30 degrees: the scene is in world coordinates, the message in the
  // coordinates the user wrote.
  std::string rotated = Head;
  rotated.replace(rotated.find("time_zone: -8}"), 14, "time_zone: -8, north: 30}");
  const Outcome o = check_text(rotated + Office + R"(sensors:
  points:
    - name: probes
      points: [[3, 4, 10, 0, 0, 1]]
)");
  ASSERT_EQ(o.errors.size(), 1u);
  EXPECT_NE(o.errors[0].find("(sensor 0 at (3, 4, 10) m sees the sky"), std::string::npos) << o.errors[0];
}

TEST(PlacementCheck, AProjectWithoutPortsOrSensorsIsAnError) {
  const Outcome o = check_text(Head + R"(geometry:
  rooms:
    - {name: office, size: [6, 8, 3], materials: {floor: walls, ceiling: walls, walls: walls}}
)");
  ASSERT_EQ(o.errors.size(), 2u);
  EXPECT_EQ(o.errors[0].rfind("1:1: the project has no photon port", 0), 0u) << o.errors[0];
  EXPECT_EQ(o.errors[1].rfind("1:1: the project has no sensors", 0), 0u) << o.errors[1];
}

/// A 4 x 4 x 3 m room of polygons with a 1 x 1 m roof light drawn facing the sky, with
/// `facing` as given (empty: none). Nothing above the roof.
std::string roof_light(const std::string& facing, bool through_floor = false) {
  return Head + R"(geometry:
  polygons:
    - {name: floor, material: walls, vertices: [[0, 0, 0], [4, 0, 0], [4, 4, 0], [0, 4, 0]]}
    - {name: wall_w, material: walls, vertices: [[0, 0, 0], [0, 4, 0], [0, 4, 3], [0, 0, 3]]}
    - {name: wall_e, material: walls, vertices: [[4, 0, 0], [4, 0, 3], [4, 4, 3], [4, 4, 0]]}
    - {name: wall_s, material: walls, vertices: [[0, 0, 0], [0, 0, 3], [4, 0, 3], [4, 0, 0]]}
    - {name: wall_n, material: walls, vertices: [[0, 4, 0], [4, 4, 0], [4, 4, 3], [0, 4, 3]]}
    - {name: ceiling_s, material: walls, vertices: [[0, 0, 3], [0, 1.5, 3], [4, 1.5, 3], [4, 0, 3]]}
    - {name: ceiling_n, material: walls, vertices: [[0, 2.5, 3], [0, 4, 3], [4, 4, 3], [4, 2.5, 3]]}
    - {name: ceiling_w, material: walls, vertices: [[0, 1.5, 3], [0, 2.5, 3], [1.5, 2.5, 3], [1.5, 1.5, 3]]}
    - {name: ceiling_e, material: walls, vertices: [[2.5, 1.5, 3], [2.5, 2.5, 3], [4, 2.5, 3], [4, 1.5, 3]]}
    - name: roof_light
      material: glazing
      port: true
      vertices: [[1.5, 1.5, 3], [2.5, 1.5, 3], [2.5, 2.5, 3], [1.5, 2.5, 3]]
)" + (facing.empty() ? "" : "      facing: " + facing + "\n") +
         (through_floor ? "    - {name: free, material: glazing, port: true, vertices: [[10, 0, 0], [11, 0, 0], [11, 1, 0]]}\n"
                        : "") +
         R"(sensors:
  grids:
    - {name: workplane, polygon: [[0, 0, 0], [4, 0, 0], [4, 4, 0], [0, 4, 0]], height: 0.8, spacing: 0.5, inset: 0.5}
)";
}

TEST(PlacementCheck, ARoofLightFacingTheSkyIsFine) {
  for (const std::string facing : {"", "auto", "out"}) {
    const Outcome o = check_text(roof_light(facing));
    EXPECT_TRUE(o.errors.empty()) << facing << ": " << o.errors[0];
  }
}

TEST(PlacementCheck, APortDeclaredTheWrongWayIsALocatedError) {
  const Outcome o = check_text(roof_light("in"));
  ASSERT_EQ(o.errors.size(), 1u);
  EXPECT_EQ(o.errors[0], "17:7: port 'roof_light': 'facing: in' puts the room on the side that sees the sky (sky "
                         "seen by 100 % of the test rays on the side its vertex order faces, 0 % on the other); use "
                         "'facing: out' or 'facing: auto'");
}

TEST(PlacementCheck, APortWhoseRoomSideCannotBeToldIsALocatedError) {
  const Outcome o = check_text(roof_light("", /*through_floor=*/true));
  ASSERT_EQ(o.errors.size(), 1u);
  // A pane 6 m east of the room, on the ground: the room hides a little of its upper side's sky.
  EXPECT_EQ(o.errors[0], "21:7: port 'free': cannot tell which side is the room: both sides see the sky (sky seen "
                         "by 96 % of the test rays on the side its vertex order faces, 100 % on the other); say "
                         "'facing: in' (its normal by the vertex order points into the room) or 'facing: out'");
}

std::string warning_text(const Diagnostic& d) {
  return std::to_string(d.location.line) + ":" + std::to_string(d.location.column) + ": " + d.message;
}

TEST(PlacementCheck, AnOutlineDrawnPastTheWallsIsALocatedWarning) {
  // The office's floor drawn 0.3 m past its walls (at the outer face of 0.3 m walls): the
  // probes 2 cm inside that outline lie outside the room along the whole of it (edges of 6.6
  // and 8.6 m, ceil(length / 0.1 m) probes each in floating point: 67 + 86 + 67 + 86); the
  // same outline along the inside faces gives no warning, nor does the room grid.
  const std::string grids = R"(sensors:
  grids:
    - {name: room, room: office, height: 0.8, spacing: 0.5, inset: 0.5}
    - {name: inner, polygon: [[0, 0, 0], [6, 0, 0], [6, 8, 0], [0, 8, 0]], height: 0.8, spacing: 0.5, inset: 0.5}
    - {name: outer, polygon: [[-0.3, -0.3, 0], [6.3, -0.3, 0], [6.3, 8.3, 0], [-0.3, 8.3, 0]], height: 0.8, spacing: 0.5, inset: 0.8}
)";
  const Outcome o = check_text(Head + Office + grids);
  ASSERT_TRUE(o.errors.empty()) << o.errors[0];
  ASSERT_EQ(o.check.warnings.size(), 1u);
  EXPECT_EQ(o.check.warnings[0].severity, Severity::Warning);
  EXPECT_EQ(warning_text(o.check.warnings[0]).rfind(
                "17:7: sensor set 'outer': its outline reaches outside every room (306 of 306 points 0.02 m inside it, "
                "first at (",
                0),
            0u)
      << warning_text(o.check.warnings[0]);
  EXPECT_NE(o.check.warnings[0].message.find("Draw the outline along the room's inside faces"), std::string::npos);
}

TEST(PlacementCheck, AnOutlineReachingPastOneWallIsNamedToo) {
  // Only the east edge lies 0.2 m past the wall (x = 6.2): its 80 probes and the two probes of
  // the north and south edges that lie beyond x = 6.
  const Outcome o = check_text(Head + Office + R"(sensors:
  grids:
    - {name: wide, polygon: [[0, 0, 0], [6.2, 0, 0], [6.2, 8, 0], [0, 8, 0]], height: 0.8, spacing: 0.5, inset: 0.5}
)");
  ASSERT_TRUE(o.errors.empty()) << o.errors[0];
  ASSERT_EQ(o.check.warnings.size(), 1u);
  EXPECT_NE(o.check.warnings[0].message.find("its outline reaches outside every room (8"), std::string::npos)
      << o.check.warnings[0].message;
}

TEST(PlacementCheck, GlazingThatIsNoPortInsideAPlanesOutlineIsALocatedWarning) {
  // A glazed partition drawn as two boxes and a clear pane across the office at y 3.9-4.0 m:
  // the light through the pane reaches the plane as photons alone and the kernel blurs it
  // (measured 6-7 % low 0.5 m behind it: docs/validation.md). Named once, at the grid. The same
  // pane of a diffusing material (no straight transmission), or lying flat over the plane (a
  // light pipe's diffuser), is not named.
  auto project = [](const std::string& pane_material, const std::string& pane) {
    return Head + "  frosted: {type: translucent, reflectance: 0.3, transmissivity: 0.6}\n" + Office +
           "  boxes:\n"
           "    - {name: low, origin: [0, 3.9, 0], size: [6, 0.1, 1], material: walls}\n"
           "    - {name: high, origin: [0, 3.9, 2], size: [6, 0.1, 1], material: walls}\n"
           "  polygons:\n"
           "    - {name: pane, material: " + pane_material + ", vertices: " + pane + "}\n"
           "sensors:\n  grids:\n    - {name: workplane, room: office, height: 0.8, spacing: 1, inset: 0.5}\n";
  };
  const std::string upright = "[[0, 3.95, 1], [6, 3.95, 1], [6, 3.95, 2], [0, 3.95, 2]]";
  const Outcome clear = check_text(project("glazing", upright));
  ASSERT_TRUE(clear.errors.empty()) << clear.errors[0];
  ASSERT_EQ(clear.check.warnings.size(), 1u);
  EXPECT_EQ(warning_text(clear.check.warnings[0]).rfind(
                "21:7: sensor set 'workplane': glazing 'pane' at (3, 3.95, 1.5) m is no port and stands inside the "
                "grid's outline (an interior glazed partition): the light that comes through it reaches the work plane "
                "as photons alone, and the plane's kernel blurs its footprint",
                0),
            0u)
      << warning_text(clear.check.warnings[0]);
  const Outcome frosted = check_text(project("frosted", upright));
  ASSERT_TRUE(frosted.errors.empty()) << frosted.errors[0];
  EXPECT_TRUE(frosted.check.warnings.empty()) << frosted.check.warnings[0].message;
  const Outcome flat = check_text(project("glazing", "[[2, 5, 2.5], [3, 5, 2.5], [3, 6, 2.5], [2, 6, 2.5]]"));
  ASSERT_TRUE(flat.errors.empty()) << flat.errors[0];
  EXPECT_TRUE(flat.check.warnings.empty()) << flat.check.warnings[0].message;
}

TEST(PlacementCheck, SensorsNearAColumnAreALocatedNote) {
  // A 0.3 m column at x 2.6-2.9, y 3.6-3.9 and a grid every 1 m from 0.5 m (6 x 8 sensors):
  // the sensor at (2.5, 3.5), index 2 + 3 x 6 = 20, lies 0.141 m from the column's corner and is
  // named, as estimated by final gather (engine/plane_cuts.h); the next ones are 0.6 m away. The
  // column moved to x 2.85-3.15, y 3.85-4.15 is 0.49 m from every sensor: no note. The room's
  // walls are not named (sensors 0.1 m from them read right: placement_check.h): the second grid
  // has sensors 0.1 m from them, every 2 m. Nothing of it is a warning any more.
  auto project = [](const std::string& origin) {
    return Head + Office + "  boxes:\n    - {name: column, origin: " + origin +
           ", size: [0.3, 0.3, 3], material: walls}\nsensors:\n  grids:\n"
           "    - {name: workplane, room: office, height: 0.8, spacing: 1, inset: 0.5}\n"
           "    - {name: edge, room: office, height: 0.8, spacing: 2, inset: 0.1}\n";
  };
  const Outcome near = check_text(project("[2.6, 3.6, 0]"));
  ASSERT_TRUE(near.errors.empty()) << near.errors[0];
  EXPECT_TRUE(near.check.warnings.empty()) << near.check.warnings[0].message;
  ASSERT_EQ(near.check.notes.size(), 1u);
  EXPECT_EQ(near.check.notes[0].severity, Severity::Note);
  EXPECT_EQ(near.check.notes[0].location.line, 17);
  EXPECT_EQ(near.check.notes[0].message.rfind(
                "sensor set 'workplane': 1 of 48 sensors lie within 0.3 m of a surface that crosses the work plane "
                "(a column, a partition, furniture), the nearest, sensor 20 at (2.5, 3.5, 0.8) m, 0.141 m from it;",
                0),
            0u)
      << near.check.notes[0].message;
  EXPECT_NE(near.check.notes[0].message.find("estimated by final gather from their own position"), std::string::npos);
  const Outcome clear = check_text(project("[2.85, 3.85, 0]"));
  ASSERT_TRUE(clear.errors.empty()) << clear.errors[0];
  EXPECT_TRUE(clear.check.warnings.empty()) << clear.check.warnings[0].message;
  EXPECT_TRUE(clear.check.notes.empty()) << clear.check.notes[0].message;
}

// Fewer than NearCutGatherMinShare of a case of planar grids alone next to a cut: not worth
// keeping every surface photon for (simulation_plan.h), so they keep the plane's estimate and
// a located warning says so, with the remedies. A 0.1 m post at x, y 0.55-0.65 and a grid every
// 0.5 m from 0.5 m (11 x 15 = 165 sensors): sensor 0 at (0.5, 0.5) lies 0.071 m from it, the
// next ones 0.35 m away; 1 of 165 is 0.6 %.
TEST(PlacementCheck, AFewSensorsNearAPostAreALocatedWarning) {
  const Outcome o = check_text(Head + Office +
                               "  boxes:\n    - {name: post, origin: [0.55, 0.55, 0], size: [0.1, 0.1, 3], material: walls}\n"
                               "sensors:\n  grids:\n    - {name: workplane, room: office, height: 0.8, spacing: 0.5, inset: 0.5}\n");
  ASSERT_TRUE(o.errors.empty()) << o.errors[0];
  EXPECT_TRUE(o.check.notes.empty()) << o.check.notes[0].message;
  ASSERT_EQ(o.check.warnings.size(), 1u);
  EXPECT_EQ(o.check.warnings[0].location.line, 17);
  const std::string& m = o.check.warnings[0].message;
  EXPECT_EQ(m.rfind("sensor set 'workplane': 1 of 165 sensors lie within 0.3 m of a surface that crosses the work "
                    "plane (a column, a partition, furniture), the nearest, sensor 0 at (0.5, 0.5, 0.8) m, 0.071 m from it;",
                    0),
            0u)
      << m;
  EXPECT_NE(m.find("They are fewer than 1 % of the set"), std::string::npos) << m;
  EXPECT_NE(m.find("list those points as a point set"), std::string::npos) << m;
}

const std::string Reveal = R"(  boxes:
    - {name: sill, origin: [1, -0.4, 0.6], size: [4, 0.399, 0.3], material: walls%s}
    - {name: far_away, origin: [1, -400, 0], size: [4, 1, 0.1], material: walls}
sensors:
  grids:
    - {name: workplane, room: office, height: 0.8, spacing: 0.5, inset: 0.5}
)";

std::string reveal(const std::string& extra) {
  std::string text = Reveal;
  text.replace(text.find("%s"), 2, extra);
  return Head + Office + text;
}

TEST(PlacementCheck, GeometryThatOnlyShadesAPortIsALocatedWarning) {
  // A 0.4 m deep sill box in front of the window (x 1 .. 5 of a 4 m window centred at x 1 .. 5,
  // sill 0.9): its top face fills about a tenth of the window's outward view. A low slab
  // 400 m away fills none of it (below 1 %): not named.
  const Outcome o = check_text(reveal(""));
  ASSERT_TRUE(o.errors.empty()) << o.errors[0];
  ASSERT_EQ(o.check.warnings.size(), 1u);
  const std::string w = warning_text(o.check.warnings[0]);
  EXPECT_EQ(w.rfind("14:7: 'sill.top' lies outside port 'office.south' and fills ", 0), 0u) << w;
  EXPECT_NE(w.find("give the polygon, box or mesh 'outdoor: true'"), std::string::npos) << w;
}

TEST(PlacementCheck, AnOutdoorBoxIsTracedAndNotNamed) {
  const Outcome o = check_text(reveal(", outdoor: true"));
  ASSERT_TRUE(o.errors.empty()) << o.errors[0];
  EXPECT_TRUE(o.check.warnings.empty()) << warning_text(o.check.warnings[0]);
}

TEST(PlacementCheck, ABlackBoxOutsideIsNotNamed) {
  // Nothing to trace: a black surface reflects nothing toward the window.
  std::string text = reveal("");
  text.replace(text.find("material: walls}\n    - {name: far_away"), 15, "material: black");
  text.replace(text.find("materials:\n"), 11, "materials:\n  black: {type: lambertian, reflectance: 0}\n");
  const Outcome o = check_text(text);
  ASSERT_TRUE(o.errors.empty()) << o.errors[0];
  EXPECT_TRUE(o.check.warnings.empty()) << warning_text(o.check.warnings[0]);
}

// ---- every origin of outdoor geometry: rooms, RADIANCE primitives, Honeybee objects -----------
//
// A facade across a 6 m courtyard, 14 m wide and 9 m high (x -4 .. 10, y -6, z 0 .. 9), fills
// about a third of the south window's outward view, whatever made it.

const std::string Sensors = R"(sensors:
  grids:
    - {name: workplane, room: office, height: 0.8, spacing: 1, inset: 0.5}
)";

std::string written(const std::string& name, const std::string& text) {
  const std::string path = (test::process_temp_dir() / name).string();
  std::ofstream(path) << text;
  return path;
}

TEST(PlacementCheck, AnotherRoomOfTheGeneratorSeenFromAPortIsNamed) {
  // The wing's walls and roof are the room generator's: their outside only shades. The
  // office's own walls, coplanar with its window, are never in its outward view.
  const Outcome o = check_text(Head + Office + R"(    - name: wing
      origin: [-4, -10, 0]
      size: [14, 4, 9]
      materials: {floor: walls, ceiling: walls, walls: walls}
)" + Sensors);
  ASSERT_TRUE(o.errors.empty()) << o.errors[0];
  ASSERT_EQ(o.check.warnings.size(), 1u);
  const std::string w = warning_text(o.check.warnings[0]);
  EXPECT_EQ(w.rfind("13:7: 'wing.", 0), 0u) << w;
  EXPECT_NE(w.find("lies outside port 'office.south'"), std::string::npos) << w;
  EXPECT_NE(w.find("The room generator's walls, floor and ceiling only shade from outside"), std::string::npos) << w;
}

TEST(PlacementCheck, ALightPipesDomeFacetsAreOneOpening) {
  // The roof around a dome collector 1.5 m up: the lowest ring's facets see it, the upper
  // ones hardly; the share is of the whole dome's view, weighted by the facets' areas, and
  // the warning names the dome's first facet and counts the others.
  const Outcome o = check_text(Head + R"(  mirror: {type: mirror, reflectance: 0.95}
geometry:
  rooms:
    - name: core
      size: [4, 6, 2.7]
      materials: {floor: walls, ceiling: walls, walls: walls}
  systems:
    - {type: light_pipe, name: pipe, room: core, x: 2, y: 3, diameter: 0.35, length: 1.5, sides: 8,
       collector: dome, dome_rings: 2, tube_material: mirror, diffuser_material: glazing,
       collector_material: glazing}
)" + R"(sensors:
  grids:
    - {name: workplane, room: core, height: 0.8, spacing: 1, inset: 0.5}
)");
  ASSERT_TRUE(o.errors.empty()) << o.errors[0];
  ASSERT_EQ(o.check.warnings.size(), 1u);
  const std::string w = warning_text(o.check.warnings[0]);
  EXPECT_EQ(w.rfind("9:7: 'core.ceiling.1' lies outside port 'pipe.collector.1.1' and the 15 others written with it "
                    "and fills ",
                    0),
            0u)
      << w;
  EXPECT_NE(w.find("of their outward view (cosine-weighted, by area)"), std::string::npos) << w;
}

const std::string WingRad = R"(void plastic facade
0
0
5 0.5 0.5 0.5 0 0

facade polygon wing.north
0
0
12  -4 -6 0   10 -6 0   10 -6 9   -4 -6 9
)";

TEST(PlacementCheck, ARadiancePrimitiveSeenFromAPortIsNamedUnlessOutdoor) {
  const std::string rad = written("wing.rad", WingRad);
  const std::string entry = "  radiance:\n    - files: [" + rad + "]\n";
  const Outcome shading = check_text(Head + Office + entry + Sensors);
  ASSERT_TRUE(shading.errors.empty()) << shading.errors[0];
  ASSERT_EQ(shading.check.warnings.size(), 1u);
  const Diagnostic& w = shading.check.warnings[0];
  EXPECT_EQ(w.location.file, rad);
  EXPECT_EQ(w.location.line, 6);  // the polygon's line in wing.rad
  EXPECT_EQ(w.message.rfind("'wing.north' lies outside port 'office.south' and fills ", 0), 0u) << w.message;
  EXPECT_NE(w.message.find("list its modifier 'facade' under the RADIANCE scene's 'outdoor'"), std::string::npos)
      << w.message;

  const Outcome traced = check_text(Head + Office + entry + "      outdoor: [facade]\n" + Sensors);
  ASSERT_TRUE(traced.errors.empty()) << traced.errors[0];
  EXPECT_TRUE(traced.check.warnings.empty()) << warning_text(traced.check.warnings[0]);
}

std::string hb_face(const std::string& id, const std::string& points, const std::string& extra = "") {
  return R"({"type": "Face", "identifier": ")" + id + R"(", "face_type": "Wall", "boundary_condition": )"
         R"({"type": "Outdoors"}, "geometry": {"type": "Face3D", "boundary": )" + points + "}" + extra + "}";
}

/// A Honeybee room (the office's box, faces outward, a 4 x 1.5 m south window) and, across
/// the courtyard, the facade as an orphaned face (`shade` false) or a detached orphaned shade.
std::string hb_model(bool shade) {
  const std::string window =
      R"(, "apertures": [{"type": "Aperture", "identifier": "window", "boundary_condition": {"type": "Outdoors"}, )"
      R"("geometry": {"type": "Face3D", "boundary": [[1, 0, 0.9], [5, 0, 0.9], [5, 0, 2.4], [1, 0, 2.4]]}}])";
  const std::string faces =
      hb_face("south", "[[0, 0, 0], [6, 0, 0], [6, 0, 3], [0, 0, 3]]", window) + ", " +
      hb_face("north", "[[6, 8, 0], [0, 8, 0], [0, 8, 3], [6, 8, 3]]") + ", " +
      hb_face("west", "[[0, 8, 0], [0, 0, 0], [0, 0, 3], [0, 8, 3]]") + ", " +
      hb_face("east", "[[6, 0, 0], [6, 8, 0], [6, 8, 3], [6, 0, 3]]") + ", " +
      hb_face("floor", "[[0, 0, 0], [0, 8, 0], [6, 8, 0], [6, 0, 0]]") + ", " +
      hb_face("roof", "[[0, 0, 3], [6, 0, 3], [6, 8, 3], [0, 8, 3]]");
  const std::string facade_points = "[[-4, -6, 0], [10, -6, 0], [10, -6, 9], [-4, -6, 9]]";
  const std::string facade =
      shade ? R"("orphaned_shades": [{"type": "Shade", "identifier": "facade", "is_detached": true, )"
              R"("geometry": {"type": "Face3D", "boundary": )" + facade_points + "}}]"
            : R"("orphaned_faces": [)" + hb_face("facade", facade_points) + "]";
  return R"({"type": "Model", "identifier": "courtyard", "units": "Meters", "rooms": [{"type": "Room", )"
         R"("identifier": "office", "faces": [)" + faces + "]}],\n" + facade + "}";
}

TEST(PlacementCheck, AHoneybeeFaceSeenFromAPortIsNamedAContextShadeIsNot) {
  const std::string yaml = R"(site: {latitude: 37.72, longitude: -122.22, time_zone: -8}
outputs: {annual_illuminance: false, metrics: false}
materials: {}
sensors:
  points:
    - {name: desk, points: [[3, 2, 0.8, 0, 0, 1]]}
geometry:
  honeybee: )";
  const Outcome face = check_text(yaml + written("courtyard_face.hbjson", hb_model(false)) + "\n");
  ASSERT_TRUE(face.errors.empty()) << face.errors[0];
  ASSERT_EQ(face.check.warnings.size(), 1u);
  const Diagnostic& w = face.check.warnings[0];
  EXPECT_EQ(w.location.file, (test::process_temp_dir() / "courtyard_face.hbjson").string());
  EXPECT_EQ(w.location.line, 2);  // the orphaned face's object
  EXPECT_EQ(w.message.rfind("'facade' lies outside port 'window' and fills ", 0), 0u) << w.message;
  EXPECT_NE(w.message.find("A Honeybee face, aperture, door or indoor shade only shades from outside"),
            std::string::npos)
      << w.message;

  const Outcome shade = check_text(yaml + written("courtyard_shade.hbjson", hb_model(true)) + "\n");
  ASSERT_TRUE(shade.errors.empty()) << shade.errors[0];
  EXPECT_TRUE(shade.check.warnings.empty()) << warning_text(shade.check.warnings[0]);
}

// A room drawn from polygons with a 2 x 1 m gap in its east wall and a glazed south window:
// light enters only through ports, so the gap's light is not counted. A sensor facing the
// gap (its sky component through it under the CIE overcast sky, by quadrature: 5.8 %)
// read only the window's light, with no word (RADIANCE scenes and OBJ rooms with an opening
// left as a hole did the same); now a located warning at the set. The same room with the
// gap closed gives none.
std::string room_with_east_gap(bool gap) {
  std::string text = Head + R"(geometry:
  polygons:
    - {name: floor, material: walls, vertices: [[0, 0, 0], [6, 0, 0], [6, 8, 0], [0, 8, 0]]}
    - {name: ceiling, material: walls, vertices: [[0, 0, 3], [6, 0, 3], [6, 8, 3], [0, 8, 3]]}
    - {name: west, material: walls, vertices: [[0, 0, 0], [0, 8, 0], [0, 8, 3], [0, 0, 3]]}
    - {name: north, material: walls, vertices: [[0, 8, 0], [6, 8, 0], [6, 8, 3], [0, 8, 3]]}
    - {name: south_low, material: walls, vertices: [[0, 0, 0], [6, 0, 0], [6, 0, 0.9], [0, 0, 0.9]]}
    - {name: south_high, material: walls, vertices: [[0, 0, 2.4], [6, 0, 2.4], [6, 0, 3], [0, 0, 3]]}
    - {name: south_left, material: walls, vertices: [[0, 0, 0.9], [1, 0, 0.9], [1, 0, 2.4], [0, 0, 2.4]]}
    - {name: south_right, material: walls, vertices: [[5, 0, 0.9], [6, 0, 0.9], [6, 0, 2.4], [5, 0, 2.4]]}
    - {name: window, material: glazing, port: true, vertices: [[1, 0, 0.9], [5, 0, 0.9], [5, 0, 2.4], [1, 0, 2.4]]}
    - {name: east_low, material: walls, vertices: [[6, 0, 0], [6, 8, 0], [6, 8, 1], [6, 0, 1]]}
    - {name: east_high, material: walls, vertices: [[6, 0, 2], [6, 8, 2], [6, 8, 3], [6, 0, 3]]}
    - {name: east_left, material: walls, vertices: [[6, 0, 1], [6, 3, 1], [6, 3, 2], [6, 0, 2]]}
    - {name: east_right, material: walls, vertices: [[6, 5, 1], [6, 8, 1], [6, 8, 2], [6, 5, 2]]}
)";
  if (!gap) text += "    - {name: east_gap, material: walls, vertices: [[6, 3, 1], [6, 5, 1], [6, 5, 2], [6, 3, 2]]}\n";
  text += R"(sensors:
  points:
    - name: probes
      points: [[3, 6, 0.8, 0, 0, 1], [4.5, 4, 1.5, 1, 0, 0]]
)";
  return text;
}

TEST(PlacementCheck, SensorsSeeingTheSkyThroughAGapThatIsNoPortAreALocatedWarning) {
  const Outcome o = check_text(room_with_east_gap(true));
  ASSERT_TRUE(o.errors.empty()) << o.errors[0];
  ASSERT_EQ(o.check.warnings.size(), 1u);
  EXPECT_EQ(o.check.warnings[0].severity, Severity::Warning);
  const std::string text = warning_text(o.check.warnings[0]);
  EXPECT_EQ(text.rfind("23:7: sensor set 'probes': ", 0), 0u) << text;
  EXPECT_NE(text.find("sensors see the sky through an opening that is no port (sensor 1 at (4.5, 4, 1.5) m in "),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("the light through that gap is not counted"), std::string::npos) << text;

  const Outcome closed = check_text(room_with_east_gap(false));
  ASSERT_TRUE(closed.errors.empty()) << closed.errors[0];
  EXPECT_TRUE(closed.check.warnings.empty()) << closed.check.warnings[0].message;
}

TEST(PlacementCheck, AGatheredSetReachingPastTheRegionOfInterestIsALocatedWarning) {
  // Points in the office's back half with the region of interest on that half: their gather
  // rays reach the front half's floor, walls and ceiling, where no photon is stored (measured
  // on a 4 x 4 x 3 m room of reflectance 0.7 under a clear roof light, the region its half:
  // points 7-19 % low, with nothing said). The region around the whole room, or the same half
  // with only a work-plane grid (its estimate counts the plane's own photons), say nothing.
  const std::string points = R"(sensors:
  points: [{name: back, points: [[3, 6, 0.8, 0, 0, 1], [1, 7, 1.2, 1, 0, 0]]}]
)";
  const Outcome half = check_text(Head + Office + points +
                                  "simulation: {region_of_interest: {origin: [0, 4, 0], size: [6, 4, 3]}}\n");
  ASSERT_TRUE(half.errors.empty()) << half.errors[0];
  ASSERT_EQ(half.check.warnings.size(), 1u);
  EXPECT_EQ(warning_text(half.check.warnings[0]).rfind(
                "15:34: simulation.region_of_interest: sensor set 'back' is estimated by final gather, and ", 0),
            0u)
      << warning_text(half.check.warnings[0]);
  EXPECT_NE(half.check.warnings[0].message.find("of its gather rays reach surfaces outside the box"), std::string::npos);
  const Outcome whole = check_text(Head + Office + points +
                                   "simulation: {region_of_interest: {origin: [0, 0, 0], size: [6, 8, 3]}}\n");
  ASSERT_TRUE(whole.errors.empty()) << whole.errors[0];
  EXPECT_TRUE(whole.check.warnings.empty()) << whole.check.warnings[0].message;
  const Outcome plane = check_text(Head + Office +
                                   "sensors:\n  grids: [{name: g, polygon: [[0, 4, 0], [6, 4, 0], [6, 8, 0], [0, 8, 0]], "
                                   "height: 0.8, spacing: 0.5, inset: 0.5}]\n"
                                   "simulation: {region_of_interest: {origin: [0, 4, 0], size: [6, 4, 3]}}\n");
  ASSERT_TRUE(plane.errors.empty()) << plane.errors[0];
  EXPECT_TRUE(plane.check.warnings.empty()) << plane.check.warnings[0].message;
}

TEST(PlacementCheck, APlanesGatheredRowsNextToACutReachingPastTheRegionOfInterestAreALocatedWarning) {
  // The same back half as a work-plane grid with a 0.3 m column in it: the sensors within 0.3 m
  // of the column are estimated by final gather (docs/photon-map.md, "Sensors next to a cut"),
  // and their rays reach the front half, where no photon is stored. Before, only point and
  // surface sets were probed, and these rows read low with nothing said. The region around the
  // whole room says nothing.
  const std::string column_grid = R"(  boxes:
    - {name: column, origin: [2.6, 5.6, 0], size: [0.3, 0.3, 3], material: walls}
sensors:
  grids: [{name: g, polygon: [[0, 4, 0], [6, 4, 0], [6, 8, 0], [0, 8, 0]], height: 0.8, spacing: 0.5, inset: 0.5}]
)";
  const Outcome half = check_text(Head + Office + column_grid +
                                  "simulation: {region_of_interest: {origin: [0, 4, 0], size: [6, 4, 3]}}\n");
  ASSERT_TRUE(half.errors.empty()) << half.errors[0];
  ASSERT_EQ(half.check.notes.size(), 1u);  // the rows are gathered
  ASSERT_EQ(half.check.warnings.size(), 1u);
  const std::string text = warning_text(half.check.warnings[0]);
  EXPECT_EQ(text.rfind("17:34: simulation.region_of_interest: sensor set 'g': its ", 0), 0u) << text;
  EXPECT_NE(text.find(" sensors next to a surface that crosses the work plane are estimated by final gather, and "),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("of their gather rays reach surfaces outside the box"), std::string::npos) << text;
  const Outcome whole = check_text(Head + Office + column_grid +
                                   "simulation: {region_of_interest: {origin: [0, 0, 0], size: [6, 8, 3]}}\n");
  ASSERT_TRUE(whole.errors.empty()) << whole.errors[0];
  EXPECT_TRUE(whole.check.warnings.empty()) << whole.check.warnings[0].message;
}

}  // namespace
}  // namespace dayphoton::study
