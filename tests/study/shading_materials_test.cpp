// Which materials LM-83's verdicts take as operable shading (study/shading_materials.h): a
// BSDF file's DeviceType that names a shading device, or the material's `shading` key; and the
// case's list that set_building makes from the materials on its surfaces.
#include "dayphoton/study/shading_materials.h"

#include <gtest/gtest.h>

#include <string>

#include "dayphoton/core/bsdf_xml.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/engine/bsdf_material.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/results_model_builder.h"

using namespace dayphoton;
using namespace dayphoton::study;

namespace {

const std::string ExampleFolder = std::string(DAYPHOTON_SOURCE_DIR) + "/projects/bsdf_blind/";

// A room whose window carries `window`; the project file sits in projects/bsdf_blind so that
// its BSDF file is found.
std::string room_with_window(const std::string& window) {
  return "version: 1\n"
         "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"
         "study: daylight_factor\n"
         "materials:\n"
         "  walls: {type: lambertian, reflectance: 0.5}\n"
         "  window: " + window + "\n"
         "geometry:\n"
         "  rooms:\n"
         "    - name: office\n"
         "      size: [4, 5, 3]\n"
         "      materials: {floor: walls, ceiling: walls, walls: walls}\n"
         "      windows:\n"
         "        - {name: w, wall: south, width: 3, height: 1.5, sill: 0.9, material: window}\n"
         "sensors:\n"
         "  grids:\n"
         "    - {name: workplane, room: office, height: 0.8, spacing: 1}\n";
}

std::vector<ShadingMaterialInPlace> in_place(const std::string& window) {
  const project::Project p = project::load_project_from_string(room_with_window(window), ExampleFolder + "test.yaml");
  CaseResult c;
  set_building(c, p, project::build_scene_description(p));
  return c.shading_materials_in_place;
}

std::string load_error(const std::string& window) {
  try {
    project::load_project_from_string(room_with_window(window), ExampleFolder + "test.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(ShadingMaterials, DeviceTypesOfShadingDevicesAreNamedAsSuch) {
  for (const char* shading : {"Venetian blind", "Venetian Blind", "Woven Shade", "Perforated Screen", "Roller shade",
                              "Cellular Shade", "Vertical Louvre", "Exterior louver", "Shutter", "Drapes"})
    EXPECT_TRUE(names_shading_device(shading)) << shading;
  for (const char* glazing : {"", "Integral", "Other", "Laminate", "Coated glass"})
    EXPECT_FALSE(names_shading_device(glazing)) << glazing;
}

TEST(ShadingMaterials, TheExampleBlindIsReadAsAVenetianBlind) {
  const auto data = read_bsdf_xml(ExampleFolder + "blind_45deg.xml", "blind_45deg.xml", SourceLocation{});
  EXPECT_EQ(data->device_type, "Venetian blind");
}

TEST(ShadingMaterials, ABlindBsdfIsOperableShadingUnlessSaidFixed) {
  const std::vector<ShadingMaterialInPlace> blind = in_place("{type: bsdf, file: blind_45deg.xml}");
  ASSERT_EQ(blind.size(), 1u);
  EXPECT_EQ(blind[0].material, "window");
  EXPECT_NE(blind[0].why.find("DeviceType is 'Venetian blind'"), std::string::npos) << blind[0].why;
  EXPECT_NE(blind[0].why.find("`shading: fixed`"), std::string::npos) << blind[0].why;
  EXPECT_TRUE(in_place("{type: bsdf, file: blind_45deg.xml, shading: fixed}").empty());
  EXPECT_EQ(in_place("{type: bsdf, file: blind_45deg.xml, shading: operable}").at(0).why, "`shading: operable`");
}

TEST(ShadingMaterials, ATranslucentIsOperableShadingOnlyWhenSaid) {
  EXPECT_TRUE(in_place("{type: translucent, reflectance: 0.5, transmissivity: 0.4}").empty());
  const auto shade = in_place("{type: translucent, reflectance: 0.5, transmissivity: 0.4, shading: operable}");
  ASSERT_EQ(shade.size(), 1u);
  EXPECT_EQ(shade[0].material, "window");
  EXPECT_TRUE(in_place("{type: glass, transmittance: 0.7}").empty());
  // A shade defined but on no surface of the case is not in place.
  std::string unused = room_with_window("{type: glass, transmittance: 0.7}");
  unused.replace(unused.find("materials:\n"), 11,
                 "materials:\n  shade: {type: translucent, reflectance: 0.5, transmissivity: 0.4, shading: operable}\n");
  const project::Project p = project::load_project_from_string(unused, ExampleFolder + "test.yaml");
  CaseResult c;
  set_building(c, p, project::build_scene_description(p));
  EXPECT_TRUE(c.shading_materials_in_place.empty());
}

TEST(ShadingMaterials, TheKeyIsCheckedAndLocated) {
  const std::string bad = load_error("{type: translucent, reflectance: 0.5, transmissivity: 0.4, shading: sometimes}");
  EXPECT_NE(bad.find("test.yaml:6:"), std::string::npos) << bad;
  EXPECT_NE(bad.find("operable"), std::string::npos) << bad;
  // Glass is glazing: it takes no `shading` key.
  const std::string glass = load_error("{type: glass, transmittance: 0.7, shading: operable}");
  EXPECT_NE(glass.find("shading"), std::string::npos) << glass;
  EXPECT_NE(glass.find("test.yaml:6:"), std::string::npos) << glass;
}
