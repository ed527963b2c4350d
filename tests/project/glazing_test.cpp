// Glazing systems and window factors in the project file (project/src/load_project.cpp,
// project/src/window_factors.cpp; docs/materials.md "Glazing systems", "Frame and maintenance
// factors"): panes read from the outside in, the one-of-three pane forms as located errors,
// a plastic keeps its name, and a window's frame and maintenance factors become a derived
// material whose transmittance factor is their product.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/project/project.h"
#include "located_errors.h"

namespace dayphoton::project {
namespace {

const std::string FakePath = std::string(DAYPHOTON_SOURCE_DIR) + "/projects/office/snippet.yaml";

// Two valid lines every snippet starts with; snippet lines are numbered from 3.
const std::string Head =
    "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"
    "outputs: {annual_illuminance: false, metrics: false}\n";

std::vector<std::string> errors_of(const std::string& text) {
  return test::located_errors([&] { build_scene_description(load_project_from_string(text, FakePath)); }, FakePath);
}

TEST(Glazing, PanesAreReadFromTheOutsideIn) {
  const Project p = load_project_from_string(
      Head +
          "materials:\n"
          "  low_e:\n"
          "    type: glazing\n"
          "    panes:\n"
          "      - {thickness: 4, transmittance: 0.89}\n"
          "      - {thickness: 4, coating: {face: outer, transmittance: 0.82, reflectance: 0.04, glass_side_reflectance: 0.06}}\n"
          "      - {thickness: 6, absorption: [20, 10, 12], refractive_index: 1.5}\n"
          "      - {coating: {face: inner, transmittance: [0.5, 0.6, 0.7], reflectance: 0.2}}\n"
          "  pl: {type: plastic, reflectance: 0.5, specularity: 0.04}\n"
          "  lam: {type: lambertian, reflectance: 0.5}\n"
          "geometry: {}\n",
      FakePath);
  const MaterialSpec& m = p.materials.at(0);
  EXPECT_EQ(m.type, MaterialType::Glazing);
  ASSERT_EQ(m.panes.size(), 4u);
  EXPECT_EQ(m.panes[0].optics, GlazingPaneSpec::Optics::Transmittance);
  EXPECT_EQ(m.panes[0].transmittance, Vec3(0.89, 0.89, 0.89));
  EXPECT_DOUBLE_EQ(m.panes[0].thickness_m, 0.004);
  EXPECT_EQ(m.panes[0].refractive_index, 1.52);
  EXPECT_EQ(m.panes[1].optics, GlazingPaneSpec::Optics::Coated);
  EXPECT_FALSE(m.panes[1].coating_on_inner_face);
  EXPECT_EQ(m.panes[1].outer_reflectance, Vec3(0.04, 0.04, 0.04));  // the coated face
  EXPECT_EQ(m.panes[1].inner_reflectance, Vec3(0.06, 0.06, 0.06));
  EXPECT_EQ(m.panes[2].optics, GlazingPaneSpec::Optics::Absorption);
  EXPECT_EQ(m.panes[2].absorption_per_m, Vec3(20, 10, 12));
  EXPECT_DOUBLE_EQ(m.panes[2].thickness_m, 0.006);
  EXPECT_EQ(m.panes[2].refractive_index, 1.5);
  EXPECT_TRUE(m.panes[3].coating_on_inner_face);
  EXPECT_EQ(m.panes[3].inner_reflectance, Vec3(0.2, 0.2, 0.2));  // coated face, inner
  EXPECT_EQ(m.panes[3].outer_reflectance, Vec3(0.2, 0.2, 0.2));  // glass side defaults to it
  // A plastic is the Lambertian model but keeps its name for messages and `check`.
  EXPECT_EQ(p.materials.at(1).type, MaterialType::Lambertian);
  EXPECT_EQ(p.materials.at(1).type_as_written, "plastic");
  EXPECT_EQ(p.materials.at(2).type_as_written, "");
}

TEST(Glazing, PaneFormsAreLocatedErrors) {
  const std::string geometry = "geometry: {}\n";
  EXPECT_EQ(errors_of(Head +
                      "materials:\n"
                      "  g:\n"
                      "    type: glazing\n"
                      "    panes:\n"
                      "      - {thickness: 4}\n"
                      "      - {transmittance: 0.8, absorption: 20, thickness: 4}\n"
                      "      - {absorption: 20}\n"
                      "      - {coating: {face: outer, transmittance: 0.8, reflectance: 0.05}, refractive_index: 1.5}\n"
                      "      - {coating: {transmittance: 0.8, reflectance: 0.05}}\n" +
                      geometry),
            (std::vector<std::string>{
                "7:9: a glazing pane needs one of 'transmittance', 'absorption' or 'coating'",
                "8:9: a glazing pane takes only one of 'transmittance', 'absorption' and 'coating', got 'transmittance' and 'absorption'",
                "9:22: a glazing pane's 'absorption' needs its 'thickness'",
                "10:91: a coated pane's optics are its coating's transmittance and reflectance; 'refractive_index' does not apply",
                "11:19: missing required key 'face' in glazing coating",
            }));
  EXPECT_EQ(errors_of(Head +
                      "materials:\n"
                      "  g: {type: glazing, panes: []}\n" +
                      geometry),
            (std::vector<std::string>{"4:29: material 'g': a glazing needs at least one pane"}));
}

const std::string RoomWith(const std::string& window_extra, const std::string& material = "dbl") {
  return Head +
         "materials:\n"
         "  walls: {type: lambertian, reflectance: 0.5}\n"
         "  shiny: {type: plastic, reflectance: 0.5, specularity: 0.05}\n"
         "  dbl:\n"
         "    type: glazing\n"
         "    panes: [{transmittance: 0.89}, {transmittance: 0.89}]\n"
         "geometry:\n"
         "  rooms:\n"
         "    - name: office\n"
         "      size: [6, 8, 3]\n"
         "      materials: {floor: walls, ceiling: walls, walls: walls}\n"
         "      windows:\n"
         "        - {name: w, wall: south, width: 4, height: 1.5, sill: 0.9, material: " +
         material + window_extra + "}\n";
}

const Surface& window_surface(const SceneDescription& scene) {
  for (const Surface& s : scene.surfaces)
    if (s.name == "office.w") return s;
  throw std::runtime_error("no window");
}

TEST(WindowFactors, FrameAndMaintenanceFactorsMultiplyTheWindowsTransmittance) {
  const SceneDescription plain = build_scene_description(load_project_from_string(RoomWith(""), FakePath));
  const SceneDescription framed = build_scene_description(
      load_project_from_string(RoomWith(", frame_factor: 0.8, maintenance_factor: 0.9"), FakePath));
  const MaterialSpec& a = plain.materials.at(static_cast<std::size_t>(window_surface(plain).material));
  const MaterialSpec& b = framed.materials.at(static_cast<std::size_t>(window_surface(framed).material));
  EXPECT_EQ(a.name, "dbl");
  EXPECT_EQ(a.transmittance_factor, 1.0);
  EXPECT_EQ(plain.materials.size(), 3u);  // no derived material without factors
  EXPECT_EQ(b.name, "dbl x 0.72");
  EXPECT_DOUBLE_EQ(b.transmittance_factor, 0.72);
  EXPECT_EQ(b.panes.size(), 2u);
  EXPECT_EQ(framed.materials.size(), 4u);
  // Everything else about the scene is the same.
  EXPECT_EQ(window_surface(plain).vertices, window_surface(framed).vertices);
  EXPECT_TRUE(window_surface(framed).port);
}

TEST(WindowFactors, NeedATransmittingMaterialAndARange) {
  EXPECT_EQ(errors_of(RoomWith(", frame_factor: 0.8", "walls")),
            (std::vector<std::string>{
                "15:11: window 'w' of room 'office': frame_factor and maintenance_factor scale straight-through "
                "transmission; material 'walls' is lambertian (use glass, glazing or opening)"}));
  // A plastic is named as the file wrote it.
  EXPECT_EQ(errors_of(RoomWith(", frame_factor: 0.8", "shiny")),
            (std::vector<std::string>{
                "15:11: window 'w' of room 'office': frame_factor and maintenance_factor scale straight-through "
                "transmission; material 'shiny' is plastic (use glass, glazing or opening)"}));
  EXPECT_EQ(errors_of(RoomWith(", maintenance_factor: 0")),
            (std::vector<std::string>{"15:103: 'maintenance_factor' must be in (0, 1], got 0"}));
}

}  // namespace
}  // namespace dayphoton::project
