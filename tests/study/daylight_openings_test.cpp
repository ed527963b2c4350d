// The kind of a model's daylight openings (study/daylight_openings.h), which sets EN 17037's
// area rule: the target over 50 % of the reference plane under vertical and inclined openings,
// over 95 % under horizontal ones (EN 17037:2018, Annex A).
#include "dayphoton/study/daylight_openings.h"

#include <gtest/gtest.h>

#include <string>

#include "dayphoton/engine/scene.h"
#include "dayphoton/project/project.h"

namespace dayphoton::study {
namespace {

using Openings = metrics::MetricSettings::Openings;

/// A 6 x 6 x 3 m room with `openings` (YAML lines under the room) and `systems`.
DaylightOpenings openings_of(const std::string& room_openings, const std::string& systems = "") {
  const std::string text =
      "site: {latitude: 50, longitude: 8.5, time_zone: 1}\n"
      "study: daylight_factor\n"
      "materials:\n"
      "  grey: {type: lambertian, reflectance: 0.5}\n"
      "  glass: {type: glass, transmittance: 0.7}\n"
      "geometry:\n"
      "  rooms:\n"
      "    - name: hall\n"
      "      size: [6, 6, 3]\n"
      "      materials: {floor: grey, ceiling: grey, walls: grey}\n" +
      room_openings + systems +
      "sensors:\n"
      "  grids: [{name: plane, room: hall, height: 0.85, spacing: 1}]\n";
  const project::Project project =
      project::load_project_from_string(text, std::string(DAYPHOTON_SOURCE_DIR) + "/projects/roof_light/test.yaml");
  const SceneDescription description = project::build_scene_description(project);
  return daylight_openings(engine::Scene::build(description));
}

const std::string Window = "      windows: [{name: south, wall: south, width: 3, height: 1.5, sill: 0.9, material: glass}]\n";
const std::string RoofLight = "      roof_lights: [{name: top, width: 1.2, length: 1.2, material: glass}]\n";

TEST(DaylightOpenings, AWindowIsVerticalARoofLightHorizontal) {
  const DaylightOpenings window = openings_of(Window);
  EXPECT_EQ(window.kind, Openings::VerticalOrInclined);
  EXPECT_FALSE(daylight_openings_warning(window));
  const DaylightOpenings roof = openings_of(RoofLight);
  EXPECT_EQ(roof.kind, Openings::Horizontal);
  ASSERT_EQ(roof.horizontal.size(), 1u);
  EXPECT_FALSE(daylight_openings_warning(roof));
}

TEST(DaylightOpenings, BothKindsAreALocatedWarningAtTheRoofLight) {
  const DaylightOpenings both = openings_of(Window + RoofLight);
  EXPECT_EQ(both.kind, Openings::Both);
  const std::optional<Diagnostic> w = daylight_openings_warning(both);
  ASSERT_TRUE(w);
  EXPECT_EQ(w->location.line, 12);  // the roof_lights line
  EXPECT_NE(w->message.find("over 95 % of the area"), std::string::npos) << w->message;
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

}  // namespace
}  // namespace dayphoton::study
