// Openings of the room generator beyond wall windows (project/src/roof_light_generator.cpp,
// project/src/interior_windows.cpp; docs/daylight-systems.md "Roof lights" and "Interior
// windows"):
// - roof lights: keys and defaults; a flush roof light is a port in the ceiling plane
//   facing down, a roof light with a well has its glazing at the well's top and four well
//   walls facing the well's axis; ceiling pieces, roof-light openings and light-pipe
//   openings cover the ceiling exactly once; every input error has its exact message at
//   the offending key (outside the ceiling, overlapping another roof light or a light pipe,
//   an opaque glazing, a dielectric well, `wall: roof` on a window, a name used twice);
// - interior windows: a window in a wall two rooms share is cut out of both walls and is
//   glazing, not a port (before, the adjoining room's wall was left whole and the glazing
//   was a port: no light reached the other room); defined from either room it is the same
//   opening; a window partly in the other room's wall, or the same opening defined from
//   both rooms, is a located error; a window beside the other room's wall stays a port; a
//   system outside an interior window is a located error;
// - the example projects roof_light and corridor build with their openings.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "dayphoton/core/polygon.h"
#include "dayphoton/project/project.h"
#include "located_errors.h"

namespace dayphoton::project {
namespace {

const std::string FakePath = std::string(DAYPHOTON_SOURCE_DIR) + "/projects/office/openings_snippet.yaml";

// Lines 1-14; a room's roof lights (or more rooms) start at line 15.
const std::string Head =
    "version: 1\n"
    "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"
    "outputs: {annual_illuminance: false, metrics: false}\n"
    "materials:\n"
    "  walls: {type: lambertian, reflectance: 0.5}\n"
    "  ceiling: {type: lambertian, reflectance: 0.8}\n"
    "  glass: {type: glass, transmittance: 0.6}\n"
    "  pmma: {type: dielectric, refractive_index: 1.49}\n"
    "geometry:\n"
    "  rooms:\n"
    "    - name: room\n"
    "      size: [4, 6, 3]\n"
    "      materials: {floor: walls, ceiling: ceiling, walls: walls}\n"
    "      roof_lights:\n";

Project load(const std::string& text) { return load_project_from_string(text, FakePath); }

std::vector<std::string> errors_of(const std::string& text) {
  return test::located_errors([&] { build_scene_description(load(text)); });
}

const Surface* find(const SceneDescription& d, const std::string& name) {
  for (const Surface& s : d.surfaces)
    if (s.name == name) return &s;
  return nullptr;
}

std::vector<const Surface*> with_prefix(const SceneDescription& d, const std::string& prefix) {
  std::vector<const Surface*> out;
  for (const Surface& s : d.surfaces)
    if (s.name.compare(0, prefix.size(), prefix) == 0) out.push_back(&s);
  return out;
}

double area_of(const std::vector<const Surface*>& faces) {
  double a = 0;
  for (const Surface* f : faces) a += polygon_area_m2(f->vertices);
  return a;
}

void expect_near(const Vec3& a, const Vec3& b) {
  EXPECT_NEAR(a.x, b.x, 1e-12);
  EXPECT_NEAR(a.y, b.y, 1e-12);
  EXPECT_NEAR(a.z, b.z, 1e-12);
}

/// Every point of a 200 x 300 grid over the 4 x 6 m ceiling lies in exactly one of `pieces`
/// (projected onto the ceiling plane): no gap, no overlap.
void expect_ceiling_covered_once(const std::vector<const Surface*>& pieces) {
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 300; ++j) {
      const double x = (i + 0.5) * 4 / 200.0, y = (j + 0.5) * 6 / 300.0;
      int inside = 0;
      for (const Surface* s : pieces) inside += polygon_contains(s->vertices, {x, y, s->vertices[0].z});
      ASSERT_EQ(inside, 1) << x << ", " << y;
    }
}

// ---- roof lights ----------------------------------------------------------------------

TEST(RoofLights, LoadWithTheirKeysAndDefaults) {
  const Project p = load(Head +
                         "        - {name: flush, width: 1, length: 2, material: glass}\n"
                         "        - {name: deep, width: 0.8, length: 0.6, offset_x: 0.2, offset_y: 5,\n"
                         "           well_depth: 0.5, well_material: walls, material: glass}\n");
  const auto& lights = p.geometry.rooms[0].roof_lights;
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_EQ(lights[0].name, "flush");
  EXPECT_EQ(lights[0].width_m, 1);
  EXPECT_EQ(lights[0].length_m, 2);
  EXPECT_FALSE(lights[0].offset_x_m);
  EXPECT_FALSE(lights[0].offset_y_m);
  EXPECT_EQ(lights[0].well_depth_m, 0);
  EXPECT_EQ(lights[0].well_material, "");
  EXPECT_EQ(lights[0].material, "glass");
  EXPECT_EQ(*lights[1].offset_x_m, 0.2);
  EXPECT_EQ(*lights[1].offset_y_m, 5);
  EXPECT_EQ(lights[1].well_depth_m, 0.5);
  EXPECT_EQ(lights[1].well_material, "walls");
  EXPECT_EQ(lights[1].location_of("well_depth").line, 17);
}

TEST(RoofLights, AFlushRoofLightIsAPortInTheCeilingFacingDown) {
  const SceneDescription d = build_scene_description(load(Head + "        - {name: sky, width: 1, length: 2, material: glass}\n"));
  const Surface* glazing = find(d, "room.sky");
  ASSERT_NE(glazing, nullptr);
  EXPECT_TRUE(glazing->port);
  EXPECT_EQ(d.materials[glazing->material].name, "glass");
  expect_near(polygon_normal(glazing->vertices), {0, 0, -1});
  EXPECT_NEAR(polygon_area_m2(glazing->vertices), 2.0, 1e-12);
  for (const Vec3& v : glazing->vertices) EXPECT_EQ(v.z, 3.0);
  // Centred: x 1.5..2.5, y 2..4.
  expect_near(polygon_centroid(glazing->vertices), {2, 3, 3});
  EXPECT_TRUE(with_prefix(d, "room.sky.well").empty());
  int ports = 0;
  for (const Surface& s : d.surfaces) ports += s.port;
  EXPECT_EQ(ports, 1);
  auto pieces = with_prefix(d, "room.ceiling.");
  EXPECT_NEAR(area_of(pieces), 24.0 - 2.0, 1e-12);
  for (const Surface* s : pieces) expect_near(polygon_normal(s->vertices), {0, 0, -1});
  pieces.push_back(glazing);
  expect_ceiling_covered_once(pieces);
}

TEST(RoofLights, AWellRisesFromTheCeilingToTheGlazing) {
  const SceneDescription d = build_scene_description(
      load(Head + "        - {name: sky, width: 1, length: 0.5, offset_x: 0.5, offset_y: 1, well_depth: 0.4, material: glass}\n"));
  const Surface* glazing = find(d, "room.sky");
  ASSERT_NE(glazing, nullptr);
  EXPECT_TRUE(glazing->port);
  expect_near(polygon_centroid(glazing->vertices), {1.0, 1.25, 3.4});
  expect_near(polygon_normal(glazing->vertices), {0, 0, -1});
  const auto well = with_prefix(d, "room.sky.well_");
  ASSERT_EQ(well.size(), 4u);
  EXPECT_NEAR(area_of(well), 2 * (1 + 0.5) * 0.4, 1e-12);
  const Vec3 axis{1.0, 1.25, 3.2};
  for (const Surface* w : well) {
    EXPECT_FALSE(w->port);
    EXPECT_EQ(d.materials[w->material].name, "ceiling") << "the well takes the ceiling's material by default";
    // Vertical, facing the well's axis, from the ceiling up to the glazing.
    const Vec3 n = polygon_normal(w->vertices);
    EXPECT_NEAR(n.z, 0, 1e-12);
    EXPECT_GT(dot(n, axis - polygon_centroid(w->vertices)), 0) << w->name;
    double lo = 1e9, hi = -1e9;
    for (const Vec3& v : w->vertices) lo = std::min(lo, v.z), hi = std::max(hi, v.z);
    EXPECT_EQ(lo, 3.0);
    EXPECT_NEAR(hi, 3.4, 1e-12);
  }
  expect_near(polygon_normal(find(d, "room.sky.well_south")->vertices), {0, 1, 0});
  expect_near(polygon_normal(find(d, "room.sky.well_west")->vertices), {1, 0, 0});
  // The ceiling has the opening (the glazing's outline, seen from below).
  auto pieces = with_prefix(d, "room.ceiling.");
  pieces.push_back(glazing);
  expect_ceiling_covered_once(pieces);
}

TEST(RoofLights, RoofLightsAndLightPipesShareTheCeiling) {
  const SceneDescription d = build_scene_description(
      load(Head +
           "        - {name: a, width: 1, length: 1, offset_x: 0, offset_y: 0, material: glass}\n"
           "        - {name: b, width: 1, length: 2, offset_x: 3, offset_y: 4, well_depth: 1, material: glass}\n"
           "  systems:\n"
           "    - {type: light_pipe, name: p, room: room, x: 2, y: 3, diameter: 0.5, length: 1,\n"
           "       tube_material: walls, diffuser_material: glass, collector_material: glass}\n"));
  auto pieces = with_prefix(d, "room.ceiling.");
  pieces.push_back(find(d, "room.a"));
  pieces.push_back(find(d, "room.b"));
  pieces.push_back(find(d, "p.diffuser"));
  for (const Surface* s : pieces) ASSERT_NE(s, nullptr);
  EXPECT_NEAR(area_of(pieces), 24.0, 1e-12);
  expect_ceiling_covered_once(pieces);
}

TEST(RoofLights, EachInputErrorHasItsExactMessageAndLocation) {
  struct Case {
    const char* name;
    std::string text;
    std::vector<std::string> expected;
  };
  const std::vector<Case> cases = {
      {"outside_the_ceiling",
       Head + "        - {name: a, width: 1, length: 1, offset_x: 3.5, material: glass}\n"
              "        - {name: b, width: 1, length: 7, material: glass}\n",
       {"15:52: roof light 'a' of room 'room' does not fit in the ceiling (4 x 6 m): it spans x 3.5 to 4.5 m "
        "and y 2.5 to 3.5 m from the room's corner",
        "16:39: roof light 'b' of room 'room' does not fit in the ceiling (4 x 6 m): it spans x 1.5 to 2.5 m "
        "and y -0.5 to 6.5 m from the room's corner"}},
      {"overlapping_each_other_and_a_pipe",
       Head + "        - {name: a, width: 1, length: 1, offset_x: 0, offset_y: 0, material: glass}\n"
              "        - {name: b, width: 1, length: 1, offset_x: 0.5, offset_y: 0.5, material: glass}\n"
              "        - {name: c, width: 1, length: 1, offset_x: 1.5, offset_y: 2.5, material: glass}\n"
              "  systems:\n"
              "    - {type: light_pipe, name: p, room: room, x: 2, y: 3, diameter: 0.5, length: 1,\n"
              "       tube_material: walls, diffuser_material: glass, collector_material: glass}\n",
       {"16:52: roof light 'b' of room 'room' overlaps roof light 'a' (defined at " + FakePath + ":15:11)",
        "17:52: roof light 'c' of room 'room' overlaps the ceiling opening of light_pipe 'p'"}},
      {"glazing_and_well_materials",
       Head + "        - {name: a, width: 1, length: 1, offset_y: 0, material: walls}\n"
              "        - {name: b, width: 1, length: 1, offset_y: 4, well_depth: 1, well_material: pmma, material: glass}\n",
       {"15:65: roof light 'a' of room 'room': the glazing is the photon port and must let light in (glass, "
        "opening or translucent), but 'walls' is lambertian",
        "16:85: roof light 'b' of room 'room' cannot use the dielectric 'pmma' for its light well (a dielectric "
        "is the surface of a closed solid)"}},
      {"ranges_and_unknown_material",
       Head + "        - {name: a, width: 0, length: 1, well_depth: -1, material: glas}\n",
       {"15:28: 'width' must be > 0, got 0", "15:54: 'well_depth' must be >= 0, got -1",
        "15:68: unknown material 'glas' (did you mean 'glass'?)"}},
      {"a_window_in_the_roof",
       "version: 1\nsite: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"
       "outputs: {annual_illuminance: false, metrics: false}\nmaterials:\n"
       "  walls: {type: lambertian, reflectance: 0.5}\n  glass: {type: glass, transmittance: 0.6}\n"
       "geometry:\n  rooms:\n    - name: room\n      size: [4, 6, 3]\n"
       "      materials: {floor: walls, ceiling: walls, walls: walls}\n"
       "      windows:\n"
       "        - {name: w, wall: roof, width: 1, height: 1, sill: 0, material: glass}\n",
       {"13:27: a window is in a wall (south, north, east or west), not in the roof: an opening in the "
        "ceiling is a roof light (`roof_lights` of the room)"}},
      {"a_name_for_two_openings",
       Head + "        - {name: w, width: 1, length: 1, material: glass}\n"
              "      windows:\n"
              "        - {name: w, wall: south, width: 1, height: 1, sill: 1, material: glass}\n",
       {"15:18: 'w' names both a window and a roof light (each opening needs its own name)"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    EXPECT_EQ(errors_of(c.text), c.expected);
  }
}

// ---- interior windows -----------------------------------------------------------------

// An office (4 x 5 x 3 m) with a south window, and a corridor (4 x 2 x 3 m) north of it:
// the office's north wall and the corridor's south wall are both the plane y = 5.
std::string two_rooms(const std::string& office_windows, const std::string& corridor_windows = "",
                      const std::string& corridor_size = "[4, 2, 3]",
                      const std::string& corridor_origin = "[0, 5, 0]") {
  return "version: 1\n"
         "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"
         "outputs: {annual_illuminance: false, metrics: false}\n"
         "materials:\n"
         "  walls: {type: lambertian, reflectance: 0.5}\n"
         "  glass: {type: glass, transmittance: 0.6}\n"
         "geometry:\n"
         "  rooms:\n"
         "    - name: office\n"
         "      size: [4, 5, 3]\n"
         "      materials: {floor: walls, ceiling: walls, walls: walls}\n"
         "      windows:\n"
         "        - {name: facade, wall: south, width: 3, height: 1.5, sill: 0.9, material: glass}\n" +
         office_windows +
         "    - name: corridor\n"
         "      origin: " + corridor_origin + "\n"
         "      size: " + corridor_size + "\n"
         "      materials: {floor: walls, ceiling: walls, walls: walls}\n" +
         (corridor_windows.empty() ? "" : "      windows:\n" + corridor_windows);
}

double area_with_prefix(const SceneDescription& d, const std::string& prefix) { return area_of(with_prefix(d, prefix)); }

TEST(InteriorWindows, AWindowBetweenTwoRoomsIsCutOutOfBothWallsAndIsNotAPort) {
  const Project p = load(two_rooms("        - {name: internal, wall: north, width: 2, height: 1, sill: 1, offset: 1, material: glass}\n"));
  const SceneDescription d = build_scene_description(p);
  const Surface* glazing = find(d, "office.internal");
  ASSERT_NE(glazing, nullptr);
  EXPECT_FALSE(glazing->port) << "light reaches an interior window through the exterior windows";
  EXPECT_TRUE(find(d, "office.facade")->port);
  expect_near(polygon_normal(glazing->vertices), {0, -1, 0});
  // Both walls in the plane y = 5 have the 2 m^2 opening.
  EXPECT_NEAR(area_with_prefix(d, "office.wall_north"), 12.0 - 2.0, 1e-12);
  EXPECT_NEAR(area_with_prefix(d, "corridor.wall_south"), 12.0 - 2.0, 1e-12);
  for (const Surface* s : with_prefix(d, "corridor.wall_south"))
    for (const Vec3& v : s->vertices) EXPECT_EQ(v.y, 5.0);
  // Nothing but the glazing covers the opening: a point inside it lies in no wall piece.
  for (const Surface& s : d.surfaces) {
    bool in_the_plane = true;
    for (const Vec3& v : s.vertices) in_the_plane = in_the_plane && std::fabs(v.y - 5) < 1e-12;
    if (&s != glazing && in_the_plane) {
      EXPECT_FALSE(polygon_contains(s.vertices, {2, 5, 1.5})) << s.name;
    }
  }
  const std::vector<InteriorWindow> interior = interior_windows(p.geometry);
  ASSERT_EQ(interior.size(), 1u);
  EXPECT_EQ(interior[0].room, "office");
  EXPECT_EQ(interior[0].window, "internal");
  EXPECT_EQ(interior[0].adjoining_room, "corridor");
}

TEST(InteriorWindows, DefinedFromEitherRoomItIsTheSameOpening) {
  const SceneDescription from_office = build_scene_description(
      load(two_rooms("        - {name: internal, wall: north, width: 2, height: 1, sill: 1, offset: 1, material: glass}\n")));
  const Project p = load(two_rooms("", "        - {name: internal, wall: south, width: 2, height: 1, sill: 1, offset: 1, material: glass}\n"));
  const SceneDescription from_corridor = build_scene_description(p);
  const Surface* a = find(from_office, "office.internal");
  const Surface* b = find(from_corridor, "corridor.internal");
  ASSERT_TRUE(a && b);
  EXPECT_FALSE(b->port);
  EXPECT_NEAR(polygon_area_m2(a->vertices), polygon_area_m2(b->vertices), 1e-12);
  expect_near(polygon_centroid(a->vertices), polygon_centroid(b->vertices));
  for (const char* wall : {"office.wall_north", "corridor.wall_south"})
    EXPECT_NEAR(area_with_prefix(from_office, wall), area_with_prefix(from_corridor, wall), 1e-12) << wall;
  ASSERT_EQ(interior_windows(p.geometry).size(), 1u);
  EXPECT_EQ(interior_windows(p.geometry)[0].adjoining_room, "office");
}

TEST(InteriorWindows, AWindowBesideTheOtherRoomStaysAnExteriorPort) {
  // The corridor is 2 m long (x 0..2); a window at x 2.5..3.5 of the office's north wall
  // looks out to the sky.
  const Project p = load(two_rooms("        - {name: north, wall: north, width: 1, height: 1, sill: 1, offset: 2.5, material: glass}\n",
                                   "", "[2, 2, 3]"));
  const SceneDescription d = build_scene_description(p);
  EXPECT_TRUE(find(d, "office.north")->port);
  EXPECT_TRUE(interior_windows(p.geometry).empty());
  EXPECT_NEAR(area_with_prefix(d, "corridor.wall_south"), 6.0, 1e-12);
}

TEST(InteriorWindows, PartlyInTheOtherRoomsWallOrDefinedTwiceAreLocatedErrors) {
  EXPECT_EQ(errors_of(two_rooms("        - {name: straddle, wall: north, width: 1, height: 1, sill: 1, offset: 1.5, material: glass}\n",
                                "", "[2, 2, 3]")),
            (std::vector<std::string>{
                "14:11: window 'straddle' of room 'office' (x 1.5 to 2.5 m, z 1 to 2 m) lies partly in the south wall "
                "of room 'corridor' (x 0 to 2 m, z 0 to 3 m): a window in a wall two rooms share must lie wholly "
                "inside the other room's wall (an interior window) or wholly outside it"}));
  // In height too: a corridor whose floor is 1.5 m above the office's (z 1.5..4.5) holds
  // the upper half of a window at z 1..2.
  EXPECT_EQ(errors_of(two_rooms("        - {name: high, wall: north, width: 1, height: 1, sill: 1, offset: 1, material: glass}\n",
                                "", "[4, 2, 3]", "[0, 5, 1.5]")),
            (std::vector<std::string>{
                "14:11: window 'high' of room 'office' (x 1 to 2 m, z 1 to 2 m) lies partly in the south wall "
                "of room 'corridor' (x 0 to 4 m, z 1.5 to 4.5 m): a window in a wall two rooms share must lie wholly "
                "inside the other room's wall (an interior window) or wholly outside it"}));
  EXPECT_EQ(errors_of(two_rooms("        - {name: a, wall: north, width: 2, height: 1, sill: 1, offset: 1, material: glass}\n",
                                "        - {name: b, wall: south, width: 1, height: 1, sill: 1.5, offset: 2, material: glass}\n")),
            (std::vector<std::string>{
                "20:11: window 'b' of room 'corridor' overlaps window 'a' of room 'office' (defined at " + FakePath +
                ":14:11) in the wall the rooms share: an interior window is defined once, in either room"}));
}

TEST(InteriorWindows, ASystemOutsideAnInteriorWindowIsALocatedError) {
  // Outside the office's interior window is the corridor: an exterior system there is an
  // error; interior blinds (in the office) are fine.
  const std::string rooms =
      two_rooms("        - {name: internal, wall: north, width: 2, height: 1, sill: 1, offset: 1, material: glass}\n");
  EXPECT_EQ(errors_of(rooms +
                      "  systems:\n"
                      "    - {type: blinds, name: b, window: internal, side: exterior, slat_width: 0.05, spacing: 0.04, material: walls}\n"
                      "    - {type: overhang, name: o, window: internal, depth: 0.5, material: walls}\n"),
            (std::vector<std::string>{
                "20:55: blinds 'b' is outside window 'internal', an interior window: outside is room 'corridor'; mount "
                "it inside (side: interior) or model it in that room",
                "21:41: overhang 'o' is outside window 'internal', an interior window: outside is room 'corridor'; mount "
                "it inside (side: interior) or model it in that room"}));
  EXPECT_TRUE(errors_of(rooms +
                        "  systems:\n"
                        "    - {type: blinds, name: b, window: internal, slat_width: 0.05, spacing: 0.04, material: walls}\n")
                  .empty());
}

// Work planes over a room whose daylight all comes through interior windows are estimated
// by final gather (not planar), with a located note at the grid's `room`; a room with a port
// of its own keeps its receiver plane; with point_estimate: surface the plane stays, with a
// located warning (docs/photon-map.md, "Rooms lit only through interior windows"). Before,
// every room grid was a receiver plane: the corridor read -11 to +6 % against a backward
// reference (docs/validation.md, cli_borrowed_light_reference).
const SensorGrid& grid_named(const SceneDescription& d, const std::string& name) {
  for (const SensorGrid& g : d.grids)
    if (g.name == name) return g;
  throw std::runtime_error("no grid " + name);
}

std::string with_grids(const std::string& rooms, const std::string& simulation = "") {
  return rooms +
         "sensors:\n"
         "  grids:\n"
         "    - {name: office, room: office, spacing: 1}\n"
         "    - {name: corridor, room: corridor, spacing: 1}\n" +
         simulation;
}

TEST(InteriorWindows, AGridOverARoomLitOnlyThroughThemIsGathered) {
  const std::string internal =
      "        - {name: internal, wall: north, width: 2, height: 1, sill: 1, offset: 1, material: glass}\n";
  const SceneDescription d = build_scene_description(load(with_grids(two_rooms(internal))));
  EXPECT_TRUE(grid_named(d, "office").planar) << "the office has its facade port";
  const SensorGrid& corridor = grid_named(d, "corridor");
  EXPECT_FALSE(corridor.planar) << "the corridor's light all comes through the interior window";
  EXPECT_EQ(corridor.plane_normal.z, 1.0);
  ASSERT_EQ(d.warnings.size(), 1u);
  EXPECT_EQ(d.warnings[0].severity, Severity::Note);
  EXPECT_EQ(d.warnings[0].location.line, 22);
  EXPECT_EQ(d.warnings[0].message,
            "grid 'corridor' covers room 'corridor', whose daylight all comes through interior windows: its sensors "
            "are estimated by final gather, not as a receiver plane (a plane's kernel blurs those windows' light)");

  // The same opening defined from the corridor: the same rule.
  const SceneDescription from_corridor = build_scene_description(load(with_grids(two_rooms(
      "", "        - {name: internal, wall: south, width: 2, height: 1, sill: 1, offset: 1, material: glass}\n"))));
  EXPECT_TRUE(grid_named(from_corridor, "office").planar);
  EXPECT_FALSE(grid_named(from_corridor, "corridor").planar);

  // A port of the corridor's own (an east window, a roof light, a port polygon in it): planes.
  for (const std::string& own : {
           std::string("        - {name: small, wall: east, width: 0.6, height: 0.6, sill: 1.2, material: glass}\n"),
       }) {
    const SceneDescription d2 = build_scene_description(load(with_grids(two_rooms(internal, own))));
    EXPECT_TRUE(grid_named(d2, "corridor").planar);
    EXPECT_TRUE(d2.warnings.empty());
  }
  const std::string roof = two_rooms(internal) +
                           "      roof_lights:\n"
                           "        - {name: top, width: 0.5, length: 0.5, material: glass}\n";
  EXPECT_TRUE(grid_named(build_scene_description(load(with_grids(roof))), "corridor").planar);
  const std::string polygon_port = two_rooms(internal) +
                                   "  polygons:\n"
                                   "    - {name: hatch, port: true, material: glass, vertices: [[1, 5.5, 3], [2, 5.5, 3], "
                                   "[2, 6.5, 3], [1, 6.5, 3]]}\n";
  EXPECT_TRUE(grid_named(build_scene_description(load(with_grids(polygon_port))), "corridor").planar);

  // A polygon grid with sensors in the corridor (across both rooms) is gathered too; one over
  // the office alone is not.
  const std::string polygons = two_rooms(internal) +
                               "sensors:\n"
                               "  grids:\n"
                               "    - {name: across, polygon: [[0, 0, 0], [4, 0, 0], [4, 7, 0], [0, 7, 0]], spacing: 1}\n"
                               "    - {name: office_only, polygon: [[0, 0, 0], [4, 0, 0], [4, 5, 0], [0, 5, 0]], spacing: 1}\n";
  const SceneDescription across = build_scene_description(load(polygons));
  EXPECT_FALSE(grid_named(across, "across").planar);
  EXPECT_TRUE(grid_named(across, "office_only").planar);
  ASSERT_EQ(across.warnings.size(), 1u);
  EXPECT_EQ(across.warnings[0].location.line, 21);
  EXPECT_EQ(across.warnings[0].message.substr(0, 67),
            "grid 'across' has sensors in room 'corridor', whose daylight all co");

  // point_estimate: surface cannot gather mid-air sensors: the plane, and a located warning.
  const SceneDescription surface = build_scene_description(
      load(with_grids(two_rooms(internal), "simulation: {point_estimate: surface}\n")));
  EXPECT_TRUE(grid_named(surface, "corridor").planar);
  ASSERT_EQ(surface.warnings.size(), 1u);
  EXPECT_EQ(surface.warnings[0].severity, Severity::Warning);
  EXPECT_EQ(surface.warnings[0].location.line, 22);
  EXPECT_NE(surface.warnings[0].message.find("remove point_estimate: surface"), std::string::npos)
      << surface.warnings[0].message;
}

TEST(RoomOpenings, ExampleProjectsLoadAndBuild) {
  const std::string projects = std::string(DAYPHOTON_SOURCE_DIR) + "/projects/";
  const SceneDescription roof = build_scene_description(load_project(projects + "roof_light/project.yaml"));
  int ports = 0;
  for (const Surface& s : roof.surfaces) ports += s.port;
  EXPECT_EQ(ports, 2);
  EXPECT_TRUE(find(roof, "hall.flush")->port);
  EXPECT_EQ(with_prefix(roof, "hall.well.well_").size(), 4u);
  const Project corridor = load_project(projects + "corridor/project.yaml");
  const SceneDescription d = build_scene_description(corridor);
  EXPECT_TRUE(find(d, "office.facade")->port);
  EXPECT_FALSE(find(d, "office.internal")->port);
  ASSERT_EQ(interior_windows(corridor.geometry).size(), 1u);
  EXPECT_EQ(interior_windows(corridor.geometry)[0].adjoining_room, "corridor");
  EXPECT_TRUE(grid_named(d, "office").planar);
  EXPECT_FALSE(grid_named(d, "corridor").planar) << "lit only through the internal window";
}

}  // namespace
}  // namespace dayphoton::project
