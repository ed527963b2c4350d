// The kind of a model's daylight openings (study/daylight_openings.h), which sets EN 17037's
// area rule: the target over 50 % of the reference plane under vertical and inclined openings,
// over 95 % under horizontal ones (EN 17037:2018, Annex A).
#include "dayphoton/study/daylight_openings.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dayphoton/engine/scene.h"
#include "dayphoton/project/project.h"
#include "fresh_run.h"
#include "../temp_folder.h"

namespace dayphoton::study {
namespace {

using Openings = metrics::MetricSettings::Openings;

/// The site, materials and the start of the rooms list of the models below.
const std::string ModelHead =
      "site: {latitude: 50, longitude: 8.5, time_zone: 1}\n"
      "study: daylight_factor\n"
      "materials:\n"
      "  grey: {type: lambertian, reflectance: 0.5}\n"
      "  glass: {type: glass, transmittance: 0.7}\n"
      "geometry:\n"
      "  rooms:\n";

/// A 6 x 6 x 3 m room with `openings` (YAML lines under the room) and `systems`, and a grid.
SceneDescription hall_description(const std::string& room_openings, const std::string& systems = "") {
  const std::string text =
      ModelHead +
      "    - name: hall\n"
      "      size: [6, 6, 3]\n"
      "      materials: {floor: grey, ceiling: grey, walls: grey}\n" +
      room_openings + systems +
      "sensors:\n"
      "  grids: [{name: plane, room: hall, height: 0.85, spacing: 1}]\n";
  const project::Project project =
      project::load_project_from_string(text, std::string(DAYPHOTON_SOURCE_DIR) + "/projects/roof_light/test.yaml");
  return project::build_scene_description(project);
}

DaylightOpenings openings_of(const std::string& room_openings, const std::string& systems = "") {
  return daylight_openings(engine::Scene::build(hall_description(room_openings, systems)));
}

const std::string Window = "      windows: [{name: south, wall: south, width: 3, height: 1.5, sill: 0.9, material: glass}]\n";
const std::string RoofLight = "      roof_lights: [{name: top, width: 1.2, length: 1.2, material: glass}]\n";

TEST(DaylightOpenings, AWindowIsVerticalARoofLightHorizontal) {
  const DaylightOpenings window = openings_of(Window);
  EXPECT_EQ(window.kind, Openings::VerticalOrInclined);
    const DaylightOpenings roof = openings_of(RoofLight);
  EXPECT_EQ(roof.kind, Openings::Horizontal);
  ASSERT_EQ(roof.horizontal.size(), 1u);
  }

TEST(DaylightOpenings, BothKindsInOneModel) {
  const DaylightOpenings both = openings_of(Window + RoofLight);
  EXPECT_EQ(both.kind, Openings::Both);
  ASSERT_EQ(both.port_horizontal.size(), 2u);
  EXPECT_EQ(both.horizontal.size(), 1u);
  EXPECT_EQ(both.vertical_or_inclined.size(), 1u);
}

/// Three 6 x 6 x 3 m rooms side by side, each with its grid: `side` lit by a window alone,
/// `top` by a roof light alone, `mixed` by both; walls between them are opaque.
struct ThreeRooms {
  SceneDescription description;
  std::vector<GridOpenings> per_grid;
  DaylightOpenings model;
};

ThreeRooms three_rooms(const std::string& mixed_window_width = "3") {
  const std::string text =
      ModelHead +
      "    - name: side\n"
      "      size: [6, 6, 3]\n"
      "      materials: {floor: grey, ceiling: grey, walls: grey}\n" + Window +
      "    - name: top\n"
      "      origin: [7, 0, 0]\n"
      "      size: [6, 6, 3]\n"
      "      materials: {floor: grey, ceiling: grey, walls: grey}\n" + RoofLight +
      "    - name: mixed\n"
      "      origin: [14, 0, 0]\n"
      "      size: [6, 6, 3]\n"
      "      materials: {floor: grey, ceiling: grey, walls: grey}\n"
      "      windows: [{name: south_2, wall: south, width: " + mixed_window_width +
      ", height: 1.5, sill: 0.9, material: glass}]\n"
      "      roof_lights: [{name: top_2, width: 1.2, length: 1.2, material: glass}]\n"
      "sensors:\n"
      "  grids:\n"
      "    - {name: side_plane, room: side, height: 0.85, spacing: 1}\n"
      "    - {name: top_plane, room: top, height: 0.85, spacing: 1}\n"
      "    - {name: mixed_plane, room: mixed, height: 0.85, spacing: 1}\n";
  const project::Project project =
      project::load_project_from_string(text, std::string(DAYPHOTON_SOURCE_DIR) + "/projects/roof_light/test.yaml");
  ThreeRooms out;
  out.description = project::build_scene_description(project);
  const engine::Scene scene = engine::Scene::build(out.description);
  out.model = daylight_openings(scene);
  out.per_grid = grid_daylight_openings(scene, engine::materials_of(out.description.materials), out.description.grids, out.model);
  return out;
}

// A model with both kinds is decided per sensor set by the openings it sees the sky through:
// the side-lit room by its window, the roof-lit room by its roof light (the 95 % rule), and
// the room with both keeps the 50 % rule with a warning located at its grid.
TEST(DaylightOpenings, BothKindsAreDecidedPerSensorSetByItsViewOfTheSky) {
  const ThreeRooms rooms = three_rooms();
  ASSERT_EQ(rooms.model.kind, Openings::Both);
  ASSERT_EQ(rooms.per_grid.size(), 3u);
  EXPECT_EQ(rooms.per_grid[0].kind, Openings::VerticalOrInclined);
  EXPECT_EQ(rooms.per_grid[0].horizontal_sky_share, 0.0);
  EXPECT_EQ(rooms.per_grid[1].kind, Openings::Horizontal);
  EXPECT_EQ(rooms.per_grid[1].horizontal_sky_share, 1.0);
  EXPECT_EQ(rooms.per_grid[2].kind, Openings::Both);
  EXPECT_GT(rooms.per_grid[2].horizontal_sky_share, MinorOpeningsSkyShare);
  EXPECT_LT(rooms.per_grid[2].horizontal_sky_share, 1.0 - MinorOpeningsSkyShare);
  for (const GridOpenings& g : rooms.per_grid) EXPECT_TRUE(g.by_view);

  std::vector<Diagnostic> warnings, notes;
  daylight_openings_diagnostics(rooms.description.grids, rooms.model, rooms.per_grid, warnings, notes);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].location.line, rooms.description.grids[2].location.line);
  EXPECT_NE(warnings[0].message.find("sensor set 'mixed_plane'"), std::string::npos) << warnings[0].message;
  EXPECT_NE(warnings[0].message.find("over 95 % of the area"), std::string::npos) << warnings[0].message;
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_NE(notes[1].message.find("'top_plane' sees the sky through horizontal openings (100 %"), std::string::npos)
      << notes[1].message;
  EXPECT_NE(notes[1].message.find("target over 95 %"), std::string::npos) << notes[1].message;
}

// The share is the sky component's, so a room with a wide window and a small roof light far
// from most of its sensors still counts both only when the roof light gives a tenth of it; a
// thin window slot beside the roof light is a glimpse, and the roof light's rule applies.
TEST(DaylightOpenings, AGlimpseOfTheOtherKindDoesNotChangeTheRule) {
  const ThreeRooms slot = three_rooms("0.1");
  ASSERT_EQ(slot.per_grid.size(), 3u);
  EXPECT_LT(1.0 - slot.per_grid[2].horizontal_sky_share, MinorOpeningsSkyShare);
  EXPECT_GT(1.0 - slot.per_grid[2].horizontal_sky_share, 0.0);
  EXPECT_EQ(slot.per_grid[2].kind, Openings::Horizontal);
}

// One kind in the model: every set takes it, with no view traced and no message.
TEST(DaylightOpenings, OneKindInTheModelDecidesEverySet) {
  const SceneDescription description = hall_description(RoofLight);
  const engine::Scene scene = engine::Scene::build(description);
  const DaylightOpenings model = daylight_openings(scene);
  const std::vector<GridOpenings> per_grid =
      grid_daylight_openings(scene, engine::materials_of(description.materials), description.grids, model);
  ASSERT_EQ(per_grid.size(), 1u);
  EXPECT_EQ(per_grid[0].kind, Openings::Horizontal);
  EXPECT_FALSE(per_grid[0].by_view);
  std::vector<Diagnostic> warnings, notes;
  daylight_openings_diagnostics(description.grids, model, per_grid, warnings, notes);
  EXPECT_TRUE(warnings.empty());
  EXPECT_TRUE(notes.empty());
}

// A polygon port drawn by a user: horizontal within 15 degrees of horizontal, inclined beyond.
TEST(DaylightOpenings, APolygonPortCountsByItsTilt) {
  auto tilted = [](double rise_m) {
    // A 1 x 1 m port over the room whose far edge is `rise_m` higher (tilt atan(rise)).
    const std::string z0 = "3.2", z1 = std::to_string(3.2 + rise_m);
    return "  polygons:\n"
           "    - {name: tilted, material: glass, port: true, vertices: [[2, 2, " + z0 + "], [3, 2, " + z0 +
           "], [3, 3, " + z1 + "], [2, 3, " + z1 + "]]}\n";
  };
  // tan(10 deg) = 0.176, tan(20 deg) = 0.364.
  EXPECT_EQ(openings_of(RoofLight, tilted(0.176)).kind, Openings::Horizontal);
  EXPECT_EQ(openings_of(RoofLight, tilted(0.364)).kind, Openings::Both);
}

// Facets that share vertices and all rise from the vertical count by the plane of their rim:
// a pyramid of four 45-degree triangles and a ridge of two 30-degree panes over a flat roof are
// horizontal openings, though each facet alone is inclined; a conservatory's vertical pane
// joined to its sloped roof pane is not a cap, and each counts by its own plane.
TEST(DaylightOpenings, ACapOfFacetsCountsByItsRim) {
  auto polygon = [](const std::string& name, const std::string& vertices) {
    return "    - {name: " + name + ", material: glass, port: true, vertices: [" + vertices + "]}\n";
  };
  const std::string pyramid =
      "  polygons:\n" + polygon("p1", "[2, 2, 3.2], [3, 2, 3.2], [2.5, 2.5, 3.7]") +
      polygon("p2", "[3, 2, 3.2], [3, 3, 3.2], [2.5, 2.5, 3.7]") +
      polygon("p3", "[3, 3, 3.2], [2, 3, 3.2], [2.5, 2.5, 3.7]") +
      polygon("p4", "[2, 3, 3.2], [2, 2, 3.2], [2.5, 2.5, 3.7]");
  const DaylightOpenings p = openings_of("", pyramid);
  EXPECT_EQ(p.kind, Openings::Horizontal);
  EXPECT_EQ(p.horizontal.size(), 4u);
  // tan(30 deg) = 0.57735: a ridge along y at x = 2.5 over the 1 m wide opening.
  const std::string ridge = "  polygons:\n" + polygon("west", "[2, 2, 3.2], [2.5, 2, 3.48868], [2.5, 3, 3.48868], [2, 3, 3.2]") +
                            polygon("east", "[2.5, 2, 3.48868], [3, 2, 3.2], [3, 3, 3.2], [2.5, 3, 3.48868]");
  EXPECT_EQ(openings_of("", ridge).kind, Openings::Horizontal);
  // One slope alone is an inclined opening (a roof window in a pitched roof).
  EXPECT_EQ(openings_of("", "  polygons:\n" + polygon("west", "[2, 2, 3.2], [2.5, 2, 3.48868], [2.5, 3, 3.48868], [2, 3, 3.2]"))
                .kind,
            Openings::VerticalOrInclined);
  // A vertical pane joined to a roof pane at 20 degrees (tan 0.364): each by its own plane.
  const std::string conservatory = "  polygons:\n" + polygon("front", "[2, 2, 3.2], [3, 2, 3.2], [3, 2, 4.2], [2, 2, 4.2]") +
                                   polygon("roof", "[2, 2, 4.2], [3, 2, 4.2], [3, 3, 4.564], [2, 3, 4.564]");
  const DaylightOpenings c = openings_of("", conservatory);
  EXPECT_EQ(c.kind, Openings::VerticalOrInclined);
  EXPECT_TRUE(c.horizontal.empty());
  const std::string flat_conservatory = "  polygons:\n" + polygon("front", "[2, 2, 3.2], [3, 2, 3.2], [3, 2, 4.2], [2, 2, 4.2]") +
                                        polygon("roof", "[2, 2, 4.2], [3, 2, 4.2], [3, 3, 4.2], [2, 3, 4.2]");
  EXPECT_EQ(openings_of("", flat_conservatory).kind, Openings::Both);
}

// The box of openings around a window's exterior system stands for the window: its top and
// bottom faces are horizontal, but the opening is the window in the wall.
TEST(DaylightOpenings, AnEnclosureOfOpeningsStandsForItsWindow) {
  const std::string systems =
      "  systems:\n"
      "    - {type: light_shelf, name: outer, window: south, side: exterior, port: enclosure, height: 2.4, depth: 0.8,\n"
      "       thickness: 0.02, material: grey}\n";
  const DaylightOpenings enclosed = openings_of(Window, systems);
  EXPECT_EQ(enclosed.kind, Openings::VerticalOrInclined);
  EXPECT_TRUE(enclosed.horizontal.empty());
  EXPECT_GE(enclosed.vertical_or_inclined.size(), 4u);
}

// A light pipe's collector stands for the opening the pipe cuts in a flat roof, whatever its
// facets' tilts: a dome of two facet rings (every facet tilted 22.5 degrees or more) is a
// horizontal opening, like a flat collector.
TEST(DaylightOpenings, ALightPipesDomeIsAHorizontalOpening) {
  auto pipe = [](const std::string& collector) {
    return "  systems:\n"
           "    - {type: light_pipe, name: pipe, room: hall, x: 3, y: 3, diameter: 0.35, length: 1.0, sides: 8,\n"
           "       collector: " + collector + ", tube_material: grey, diffuser_material: glass, "
           "collector_material: glass}\n";
  };
  for (const std::string collector : {"dome, dome_rings: 2", "flat"}) {
    const DaylightOpenings openings = openings_of("", pipe(collector));
    EXPECT_EQ(openings.kind, Openings::Horizontal) << collector;
    EXPECT_TRUE(openings.vertical_or_inclined.empty()) << collector;
  }
}

// Through a run: an office lit by its window and a hall lit by its roof light, in one model,
// each assessed with its own rule in summary.json (before, both took the 50 % rule).
TEST(DaylightOpenings, ARunAssessesEachSensorSetByItsOwnOpenings) {
  namespace fs = std::filesystem;
  const fs::path dir = test::process_temp_dir() / "daylight_openings_run";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "project.yaml")
      << "version: 1\n"
         "site: {latitude: 37.72, longitude: -122.22, time_zone: -8, elevation: 2, north: 0}\n"
         "weather: " DAYPHOTON_SOURCE_DIR "/projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw\n"
         "materials:\n"
         "  grey: {type: lambertian, reflectance: 0.5}\n"
         "  glazing: {type: glass, transmittance: 0.7}\n"
         "geometry:\n"
         "  rooms:\n"
         "    - name: office\n"
         "      size: [6, 6, 3]\n"
         "      materials: {floor: grey, ceiling: grey, walls: grey}\n"
         "      windows: [{name: south, wall: south, width: 3, height: 1.5, sill: 0.9, material: glazing}]\n"
         "    - name: hall\n"
         "      origin: [7, 0, 0]\n"
         "      size: [6, 6, 3]\n"
         "      materials: {floor: grey, ceiling: grey, walls: grey}\n"
         "      roof_lights: [{name: top, width: 1.2, length: 1.2, material: glazing}]\n"
         "sensors:\n"
         "  grids:\n"
         "    - {name: office_plane, room: office, height: 0.8, spacing: 1, inset: 0.5}\n"
         "    - {name: hall_plane, room: hall, height: 0.8, spacing: 1, inset: 0.5}\n"
         "simulation: {basis: tregenza, photons_per_bin: 200, bandwidth: 20, seed: 3}\n"
         "outputs: {folder: results, images: false, report: false, matrix_format: float}\n";
  test::run_file_in_fresh_folder(dir / "project.yaml", dir / "out");
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(dir / "out" / "summary.json"));
  std::map<std::string, nlohmann::json> en17037;
  for (const nlohmann::json& g : summary.at("grids")) en17037[g.at("name")] = g.at("annual").at("en17037");
  ASSERT_EQ(en17037.size(), 2u);
  EXPECT_EQ(en17037["office_plane"].at("openings"), "vertical or inclined");
  EXPECT_EQ(en17037["office_plane"].at("target_area_required_percent"), 50.0);
  EXPECT_EQ(en17037["hall_plane"].at("openings"), "horizontal");
  EXPECT_EQ(en17037["hall_plane"].at("target_area_required_percent"), 95.0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace dayphoton::study
