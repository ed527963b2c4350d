// A `bsdf` material in a project file (docs/materials.md, "Measured BSDF (Klems)"): the file
// relative to the project file, the up vector turned by the site's north angle, and its
// errors located at their keys.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "../tensor_tree_xml_writer.h"

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/engine/bsdf_material.h"
#include "dayphoton/project/project.h"

namespace dayphoton::project {
namespace {

const std::string FakePath = std::string(DAYPHOTON_SOURCE_DIR) + "/projects/bsdf_blind/test.yaml";

std::string text(const std::string& material, double north_deg = 0) {
  return "version: 1\n"
         "site: {latitude: 37.72, longitude: -122.22, time_zone: -8, north: " + std::to_string(north_deg) + "}\n"
         "study: daylight_factor\n"
         "materials:\n"
         "  walls: {type: lambertian, reflectance: 0.5}\n"
         "  blind: " + material + "\n"
         "geometry:\n"
         "  rooms:\n"
         "    - name: office\n"
         "      size: [4, 5, 3]\n"
         "      materials: {floor: walls, ceiling: walls, walls: walls}\n"
         "      windows:\n"
         "        - {name: w, wall: south, width: 3, height: 1.5, sill: 0.9, material: blind}\n"
         "sensors:\n"
         "  grids:\n"
         "    - {name: workplane, room: office, height: 0.8, spacing: 1}\n";
}

std::string load_error(const std::string& yaml) {
  try {
    build_scene_description(load_project_from_string(yaml, FakePath));
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(BsdfProject, FileIsRelativeToTheProjectAndUpTurnsWithNorth) {
  const SceneDescription d =
      build_scene_description(load_project_from_string(text("{type: bsdf, file: blind_45deg.xml, up: [1, 0, 0]}", 90), FakePath));
  const int m = d.find_material("blind");
  ASSERT_GE(m, 0);
  const engine::BsdfMaterialParameters* bsdf = engine::bsdf_parameters(d.materials[static_cast<std::size_t>(m)]);
  ASSERT_NE(bsdf, nullptr);
  EXPECT_EQ(bsdf->data->basis.size(), 145);
  // The model's x axis is east after a rotation of 0; the site's north angle turns the model.
  const SceneDescription d0 =
      build_scene_description(load_project_from_string(text("{type: bsdf, file: blind_45deg.xml, up: [1, 0, 0]}"), FakePath));
  const auto* bsdf0 = engine::bsdf_parameters(d0.materials[static_cast<std::size_t>(d0.find_material("blind"))]);
  EXPECT_NEAR(length(bsdf0->up - Vec3(1, 0, 0)), 0, 1e-12);
  EXPECT_NEAR(std::fabs(bsdf->up.z), 0, 1e-12);
  EXPECT_NEAR(std::fabs(bsdf->up.y), 1, 1e-12);  // a quarter turn: x goes to +-y
}

TEST(BsdfProject, ErrorsAreLocatedAtTheirKeys) {
  EXPECT_NE(load_error(text("{type: bsdf, file: nope.xml}")).find("test.yaml:6:29: error: file 'nope.xml' not found"),
            std::string::npos)
      << load_error(text("{type: bsdf, file: nope.xml}"));
  EXPECT_NE(load_error(text("{type: bsdf, file: blind_45deg.xml, up: [0, 0, 0]}"))
                .find("test.yaml:6:50: error: material 'blind': the up vector is zero"),
            std::string::npos)
      << load_error(text("{type: bsdf, file: blind_45deg.xml, up: [0, 0, 0]}"));
  EXPECT_NE(load_error(text("{type: bsdf}")).find("error:"), std::string::npos);
}

TEST(BsdfProject, AnErrorInsideTheBsdfFileShowsTheFilesOwnLine) {
  // The XML's line under the caret, not the project file's line of the same number (before,
  // the project's line 7 was shown under "bad_tt.xml:7:1").
  const std::string dir = testing::TempDir();
  std::ofstream(dir + "bad_tt.xml") << dayphoton::test::tensor_tree_xml({"{ 0.1 }", "{ 0.1 }", "{ 0.01 }", ""});
  std::string e;
  try {
    build_scene_description(load_project_from_string(text("{type: bsdf, file: bad_tt.xml}"), dir + "p.yaml"));
  } catch (const InputError& error) {
    e = error.what();
  }
  EXPECT_NE(e.find("bad_tt.xml:5:1: error: the Visible data has no 'Reflection Back' block\n    <Layer>\n    ^"),
            std::string::npos)
      << e;
}

}  // namespace
}  // namespace dayphoton::project
