// Variants that remove and add geometry (project/src/load_project.cpp, variant_checks.cpp,
// apply_variant.cpp; docs/project-format.md `variants`):
// - removing each kind (polygon, box, mesh, system, window) gives the scene of the base
//   project written without it: the same surfaces, in the same order, with the same
//   materials and ports;
// - adding each kind gives the scene of the base written with it at the end of its list;
//   remove + add of one name replaces the element; a system may be mounted on a window the
//   same variant adds;
// - every error (unknown or repeated removals, names the base already has, a system left on
//   a removed window, a window in a wall a wall grid covers, bad definitions, bad lists) has
//   its exact message at the exact line:column, and added geometry is validated when the
//   variant's scene is built, located in the variant.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dayphoton/project/project.h"
#include "located_errors.h"

namespace dayphoton::project {
namespace {

const std::string ProjectsDir = std::string(DAYPHOTON_SOURCE_DIR) + "/projects";
const std::string FakePath = ProjectsDir + "/office/snippet.yaml";

// Lines 1-27; variant snippets start at line 28.
const std::string Base =
    "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"                      // 1
    "outputs: {annual_illuminance: false, metrics: false}\n"
    "materials:\n"
    "  glazing: {type: glass, transmittance: 0.6}\n"
    "  walls: {type: lambertian, reflectance: 0.5}\n"                                    // 5
    "geometry:\n"
    "  rooms:\n"
    "    - name: office\n"
    "      size: [6, 8, 3]\n"
    "      materials: {floor: walls, ceiling: walls, walls: walls}\n"                    // 10
    "      windows:\n"
    "        - {name: south, wall: south, width: 4, height: 1.5, sill: 0.9, material: glazing}\n"
    "        - {name: east, wall: east, width: 2, height: 1, sill: 1, material: glazing}\n"
    "  polygons:\n"
    "    - {name: screen, vertices: [[0, -2, 0], [6, -2, 0], [6, -2, 3]], material: walls}\n"  // 15
    "  boxes:\n"
    "    - {name: column, origin: [1, 1, 0], size: [0.3, 0.3, 3], material: walls}\n"
    "  meshes:\n"
    "    - {name: furniture, file: ../obj_mesh/furniture.obj, default_material: walls}\n"
    "  systems:\n"                                                                       // 20
    "    - {type: overhang, name: canopy, window: south, depth: 1, material: walls}\n"
    "    - {type: blinds, name: venetian, window: east, slat_width: 0.05, spacing: 0.045, material: walls}\n"
    "sensors:\n"
    "  grids:\n"
    "    - {name: floor, room: office}\n"                                                // 25
    "    - {name: north_wall, wall: {room: office, wall: north}, spacing: 1}\n"
    "variants:\n";

/// `text` with `from` (which must occur once) replaced by `to`.
std::string replaced(const std::string& text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << from;
  if (at == std::string::npos) return text;
  return text.substr(0, at) + to + text.substr(at + from.size());
}

/// The base's line that starts with `start` (whole line, with its newline).
std::string line_of(const std::string& start) {
  const std::size_t at = Base.find(start);
  EXPECT_NE(at, std::string::npos) << start;
  return Base.substr(at, Base.find('\n', at) + 1 - at);
}

std::vector<std::string> errors_of(const std::string& text) {
  return test::located_errors([&] { load_project_from_string(text, FakePath); });
}

/// Same surfaces (names, vertices, material indices, ports), in the same order, and materials.
void expect_same_scene(const SceneDescription& a, const SceneDescription& b) {
  ASSERT_EQ(a.materials.size(), b.materials.size());
  for (std::size_t i = 0; i < a.materials.size(); ++i) EXPECT_EQ(a.materials[i].name, b.materials[i].name);
  ASSERT_EQ(a.surfaces.size(), b.surfaces.size());
  for (std::size_t i = 0; i < a.surfaces.size(); ++i) {
    SCOPED_TRACE(a.surfaces[i].name);
    EXPECT_EQ(a.surfaces[i].name, b.surfaces[i].name);
    EXPECT_EQ(a.surfaces[i].material, b.surfaces[i].material);
    EXPECT_EQ(a.surfaces[i].port, b.surfaces[i].port);
    EXPECT_EQ(a.surfaces[i].vertices, b.surfaces[i].vertices);
  }
  ASSERT_EQ(a.grids.size(), b.grids.size());
  for (std::size_t i = 0; i < a.grids.size(); ++i) EXPECT_EQ(a.grids[i].points.size(), b.grids[i].points.size());
}

struct SameAs {
  const char* name;
  std::string variant;   // one variant, appended to Base
  std::string written;   // the base project written with the change (variants: [])
};

std::vector<SameAs> same_as_cases() {
  const std::string none = Base + "  []\n";
  return {
      {"remove_polygon", "  - {name: v, remove: {polygons: [screen]}}\n",
       replaced(none, "  polygons:\n" + line_of("    - {name: screen"), "")},
      {"remove_box", "  - {name: v, remove: {boxes: [column]}}\n",
       replaced(none, "  boxes:\n" + line_of("    - {name: column"), "")},
      {"remove_mesh", "  - {name: v, remove: {meshes: [furniture]}}\n",
       replaced(none, "  meshes:\n" + line_of("    - {name: furniture"), "")},
      {"remove_system", "  - {name: v, remove: {systems: [canopy]}}\n",
       replaced(none, line_of("    - {type: overhang"), "")},
      {"remove_window_and_its_system", "  - {name: v, remove: {windows: [east], systems: [venetian]}}\n",
       replaced(replaced(none, line_of("        - {name: east"), ""), line_of("    - {type: blinds"), "")},
      {"add_polygon",
       "  - name: v\n"
       "    add:\n"
       "      polygons: [{name: fin, vertices: [[0, -1, 0], [0, -1, 3], [0, -2, 3]], material: walls, port: false}]\n",
       replaced(none, line_of("    - {name: screen"),
                line_of("    - {name: screen") +
                    "    - {name: fin, vertices: [[0, -1, 0], [0, -1, 3], [0, -2, 3]], material: walls, port: false}\n")},
      {"add_box",
       "  - {name: v, add: {boxes: [{name: desk, origin: [3, 3, 0], size: [1.6, 0.8, 0.75], rotation: 30, material: walls}]}}\n",
       replaced(none, line_of("    - {name: column"),
                line_of("    - {name: column") +
                    "    - {name: desk, origin: [3, 3, 0], size: [1.6, 0.8, 0.75], rotation: 30, material: walls}\n")},
      {"add_mesh",
       "  - {name: v, add: {meshes: [{name: more, file: ../obj_mesh/furniture.obj, translate: [2, 4, 0], default_material: walls}]}}\n",
       replaced(none, line_of("    - {name: furniture"),
                line_of("    - {name: furniture") +
                    "    - {name: more, file: ../obj_mesh/furniture.obj, translate: [2, 4, 0], default_material: walls}\n")},
      {"add_system",
       "  - name: v\n"
       "    add:\n"
       "      systems:\n"
       "        - {type: light_shelf, name: shelf, window: south, height: 2.1, depth: 0.5, material: walls}\n",
       replaced(none, line_of("    - {type: blinds"),
                line_of("    - {type: blinds") +
                    "    - {type: light_shelf, name: shelf, window: south, height: 2.1, depth: 0.5, material: walls}\n")},
      {"add_window_with_a_system_on_it",
       "  - name: v\n"
       "    add:\n"
       "      windows: [{room: office, name: west, wall: west, width: 1, height: 1, sill: 1.2, material: glazing}]\n"
       "      systems: [{type: fins, name: fins, window: west, depth: 0.4, material: walls}]\n",
       replaced(replaced(none, line_of("        - {name: east"),
                         line_of("        - {name: east") +
                             "        - {name: west, wall: west, width: 1, height: 1, sill: 1.2, material: glazing}\n"),
                line_of("    - {type: blinds"),
                line_of("    - {type: blinds") + "    - {type: fins, name: fins, window: west, depth: 0.4, material: walls}\n")},
      {"remove_and_add_replaces",
       "  - name: v\n"
       "    remove: {polygons: [screen]}\n"
       "    add: {polygons: [{name: screen, vertices: [[0, -3, 0], [6, -3, 0], [6, -3, 2]], material: glazing, port: true}]}\n",
       replaced(none, line_of("    - {name: screen"),
                "    - {name: screen, vertices: [[0, -3, 0], [6, -3, 0], [6, -3, 2]], material: glazing, port: true}\n")},
  };
}

TEST(VariantGeometry, RemovingOrAddingGivesTheSceneOfTheProjectWrittenThatWay) {
  for (const SameAs& c : same_as_cases()) {
    SCOPED_TRACE(c.name);
    const Project p = load_project_from_string(Base + c.variant, FakePath);
    ASSERT_EQ(p.variants.size(), 1u);
    const SceneDescription variant = build_scene_description(apply_variant(p, p.variants[0]));
    const SceneDescription written = build_scene_description(load_project_from_string(c.written, FakePath));
    expect_same_scene(variant, written);
    // The base itself is another scene.
    const SceneDescription base = build_scene_description(p);
    bool same = base.surfaces.size() == variant.surfaces.size();
    for (std::size_t i = 0; same && i < base.surfaces.size(); ++i)
      same = base.surfaces[i].vertices == variant.surfaces[i].vertices && base.surfaces[i].port == variant.surfaces[i].port &&
             base.surfaces[i].material == variant.surfaces[i].material;
    EXPECT_FALSE(same);
  }
}

TEST(VariantGeometry, RemovalsAndAdditionsLoadWithTheirLocations) {
  const Project p = load_project_from_string(
      Base +
          "  - name: v\n"                                                                         // 28
          "    remove: {polygons: [screen], boxes: [column], meshes: [furniture],\n"              // 29
          "             systems: [venetian], windows: [east]}\n"                                  // 30
          "    add:\n"
          "      windows: [{room: office, name: west, wall: west, width: 1, height: 1, sill: 1.2, material: glazing}]\n",
      FakePath);
  const VariantSpec& v = p.variants.at(0);
  ASSERT_EQ(v.remove.polygons.size(), 1u);
  EXPECT_EQ(v.remove.polygons[0].value, "screen");
  EXPECT_EQ(v.remove.polygons[0].location.line, 29);
  EXPECT_EQ(v.remove.polygons[0].location.column, 25);
  EXPECT_EQ(v.remove.boxes.at(0).value, "column");
  EXPECT_EQ(v.remove.meshes.at(0).value, "furniture");
  EXPECT_EQ(v.remove.systems.at(0).value, "venetian");
  EXPECT_EQ(v.remove.windows.at(0).value, "east");
  EXPECT_EQ(v.remove.windows[0].location.line, 30);
  ASSERT_EQ(v.add.windows.size(), 1u);
  EXPECT_EQ(v.add.windows[0].room.value, "office");
  EXPECT_EQ(v.add.windows[0].window.name, "west");
  EXPECT_EQ(v.add.windows[0].window.wall, Wall::West);
  EXPECT_EQ(v.add.windows[0].window.sill_m, 1.2);
  EXPECT_EQ(variant_changes(v),
            (std::vector<std::string>{"polygon screen removed", "box column removed", "mesh furniture removed",
                                      "system venetian removed", "window east removed",
                                      "window west added to room office"}));
  const Project applied = apply_variant(p, v);
  EXPECT_TRUE(applied.geometry.polygons.empty());
  EXPECT_TRUE(applied.geometry.boxes.empty());
  EXPECT_TRUE(applied.geometry.meshes.empty());
  ASSERT_EQ(applied.geometry.systems.size(), 1u);
  EXPECT_EQ(applied.geometry.systems[0].name, "canopy");
  ASSERT_EQ(applied.geometry.rooms.at(0).windows.size(), 2u);
  EXPECT_EQ(applied.geometry.rooms[0].windows[0].name, "south");
  EXPECT_EQ(applied.geometry.rooms[0].windows[1].name, "west");
  // The base keeps everything.
  EXPECT_EQ(p.geometry.polygons.size(), 1u);
  EXPECT_EQ(p.geometry.rooms.at(0).windows.size(), 2u);
  EXPECT_EQ(p.geometry.systems.size(), 2u);
}

struct BadCase {
  const char* name;
  std::string snippet;                // appended to Base (first line is line 28)
  std::vector<std::string> expected;  // "line:col: message", in order
};

TEST(VariantGeometry, EachErrorHasItsExactMessageAndLocation) {
  const std::vector<BadCase> cases = {
      {"removes_what_the_base_lacks",
       "  - {name: v, remove: {polygons: [screan], meshes: [chair], windows: [north]}}\n",
       {"28:35: variant 'v' removes polygon 'screan', which the project does not have (did you mean 'screen'?)",
        "28:53: variant 'v' removes mesh 'chair', which the project does not have",
        "28:71: variant 'v' removes window 'north', which the project does not have"}},
      {"removes_twice",
       "  - name: v\n"
       "    remove:\n"
       "      boxes: [column, column]\n",
       {"30:23: variant 'v' removes box 'column' twice (first at line 30)"}},
      {"adds_a_name_the_base_has",
       "  - name: v\n"
       "    add:\n"
       "      boxes: [{name: column, size: [1, 1, 1], material: walls}]\n"
       "      systems: [{type: overhang, name: venetian, window: east, depth: 0.5, material: walls}]\n",
       {"30:22: variant 'v' adds box 'column', which the project already has (to replace it, remove it in the same "
        "variant)",
        "31:40: variant 'v' adds system 'venetian', which the project already has (to replace it, remove it in the "
        "same variant)"}},
      {"adds_a_name_twice",
       "  - name: v\n"
       "    add:\n"
       "      polygons:\n"
       "        - {name: a, vertices: [[0, 0, 4], [1, 0, 4], [1, 1, 4]], material: walls}\n"
       "        - {name: a, vertices: [[0, 0, 5], [1, 0, 5], [1, 1, 5]], material: walls}\n",
       {"32:18: duplicate polygon name 'a' (first defined at line 31)"}},
      {"removes_a_window_a_system_is_mounted_on",
       "  - {name: v, remove: {windows: [east]}}\n",
       {"28:34: variant 'v' removes window 'east', on which system 'venetian' (line 22) is mounted: remove the "
        "system too"}},
      {"adds_a_system_on_a_removed_window",
       "  - name: v\n"
       "    remove: {windows: [south], systems: [canopy]}\n"
       "    add:\n"
       "      systems: [{type: overhang, name: o, window: south, depth: 1, material: walls}]\n",
       {"31:51: system 'o' of variant 'v' is mounted on window 'south', which the variant removes"}},
      {"moves_a_system_onto_a_removed_window",
       "  - name: v\n"
       "    remove: {windows: [south], systems: [canopy]}\n"
       "    systems: {venetian: {window: south}}\n",
       {"30:34: system 'venetian' of variant 'v' is mounted on window 'south', which the variant removes"}},
      {"adds_a_system_on_an_unknown_window",
       "  - {name: v, add: {systems: [{type: overhang, name: o, window: soth, depth: 1, material: walls}]}}\n",
       {"28:65: unknown window 'soth' in variant 'v' (did you mean 'south'?)"}},
      {"changes_and_removes_a_system",
       "  - name: v\n"
       "    systems: {canopy: {depth: 2}}\n"
       "    remove: {systems: [canopy]}\n",
       {"30:24: variant 'v' both changes (under 'systems') and removes system 'canopy'"}},
      {"window_in_a_wall_a_grid_covers",
       "  - name: v\n"
       "    add:\n"
       "      windows: [{room: office, name: north, wall: north, width: 1, height: 1, sill: 1, material: glazing}]\n",
       {"30:38: variant 'v' adds window 'north' in the north wall of room 'office', which grid 'north_wall' "
        "(line 26) covers: the grid leaves windows out, so its sensors would change, and every case has the "
        "base's sensors"}},
      {"bad_added_definitions",
       "  - name: v\n"
       "    add:\n"
       "      polygons: [{name: p, vertices: [[0, 0, 0], [1, 0, 0]], material: wals}]\n"
       "      windows:\n"
       "        - {room: ofice, name: w, wall: up, width: 1, height: 1, sill: 1, material: glazing}\n"
       "        - {name: x, wall: west, width: 1, height: 1, sill: 1, material: glazing, colour: red}\n",
       {"30:38: 'vertices' needs at least 3 points, got 2",
        "32:40: unknown value 'up' for 'wall': expected one of south, north, east, west",
        "33:11: missing required key 'room' in added window",
        "33:82: unknown key 'colour' in added window",
        "30:72: unknown material 'wals' (did you mean 'walls'?)",
        "32:18: unknown room 'ofice' (did you mean 'office'?)"}},
      {"bad_lists",
       "  - name: v\n"
       "    remove: {polygons: screen, boxes: [], systems: [[canopy]], window: [east]}\n"
       "    add: {polygon: []}\n",
       {"29:24: expected a list of one or more names for 'polygons', got 'screen'",
        "29:39: expected a list of one or more names for 'boxes', got an empty list",
        "29:53: expected a name in 'systems', got a list",
        "29:64: unknown key 'window' in variant remove (did you mean 'windows'?)",
        "30:11: unknown key 'polygon' in variant add (did you mean 'polygons'?)"}},
      {"removes_nothing",
       "  - {name: v, remove: {}}\n",
       {"28:23: variant 'v' changes nothing (replace a material or system, or remove or add an element)"}},
  };
  for (const BadCase& c : cases) {
    SCOPED_TRACE(c.name);
    EXPECT_EQ(errors_of(Base + c.snippet), c.expected);
  }
}

TEST(VariantGeometry, AddedGeometryIsValidatedWhereTheVariantWroteIt) {
  // A non-planar polygon and a window wider than its wall: found when the variant's scene is
  // built, located at the variant's lines.
  const Project p = load_project_from_string(
      Base +
          "  - name: v\n"                                                                               // 28
          "    add:\n"
          "      polygons: [{name: warped, vertices: [[0, -1, 0], [2, -1, 0], [2, -1, 2], [0, -0.5, 2]], material: walls}]\n"
          "      windows: [{room: office, name: wide, wall: west, width: 9, height: 1, sill: 1, material: glazing}]\n",
      FakePath);
  const std::vector<std::string> errors =
      test::located_errors([&] { build_scene_description(apply_variant(p, p.variants.at(0))); }, FakePath);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0].substr(0, 6), "31:17:") << errors[0];
  EXPECT_NE(errors[0].find("'wide'"), std::string::npos) << errors[0];
  EXPECT_EQ(errors[1].substr(0, 6), "30:18:") << errors[1];
  EXPECT_NE(errors[1].find("not planar"), std::string::npos) << errors[1];
  // The base alone builds.
  EXPECT_NO_THROW(build_scene_description(p));
}

TEST(VariantGeometry, ApplyVariantRefusesHandMadeRemovalsOfMissingElements) {
  const Project p = load_project_from_string(Base + "  []\n", FakePath);
  VariantSpec v;
  v.name = "v";
  v.remove.polygons.push_back({"nothing", {}});
  EXPECT_THROW(apply_variant(p, v), std::invalid_argument);
  VariantSpec w;
  w.name = "w";
  w.remove.windows.push_back({"nowhere", {}});
  EXPECT_THROW(apply_variant(p, w), std::invalid_argument);
  VariantSpec x;
  x.name = "x";
  AddedWindow added;
  added.room.value = "attic";
  added.window.name = "dormer";
  x.add.windows.push_back(added);
  EXPECT_THROW(apply_variant(p, x), std::invalid_argument);
}

}  // namespace
}  // namespace dayphoton::project
