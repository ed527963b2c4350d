// geometry.radiance in a project file: the keys, the files read when the scene is built, the
// ports (auto: candidates; a list: ports), project materials replacing imported ones, and the
// located errors of the YAML side.
#include <gtest/gtest.h>

#include <string>

#include "dayphoton/project/project.h"
#include "located_errors.h"

namespace dayphoton::project {
namespace {

const std::string Data = std::string(DAYPHOTON_TEST_DATA_DIR) + "/radiance";
// The project file lives (virtually) beside the scene files, so they are named relatively.
const std::string ProjectPath = Data + "/imported.yaml";

std::string project_text(const std::string& radiance_entry, const std::string& materials = "") {
  return "version: 1\n"
         "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n" +
         (materials.empty() ? std::string() : "materials:\n" + materials) +
         "geometry:\n"
         "  radiance:\n" +
         radiance_entry +
         "sensors:\n"
         "  grids:\n"
         "    - {name: workplane, polygon: [[0, 0, 0], [6, 0, 0], [6, 8, 0], [0, 8, 0]], height: 0.8}\n"
         "outputs: {annual_illuminance: false, metrics: false}\n";
}

const Surface& surface_named(const SceneDescription& scene, const std::string& name) {
  for (const Surface& s : scene.surfaces)
    if (s.name == name) return s;
  throw std::runtime_error("no surface " + name);
}

TEST(RadianceImport, AutoPortsMarkTheGlazingAsCandidates) {
  const Project p = load_project_from_string(
      project_text("    - files: [materials.rad, office.rad]\n"), ProjectPath);
  ASSERT_EQ(p.geometry.radiance.size(), 1u);
  const RadianceSceneSpec& spec = p.geometry.radiance[0];
  EXPECT_TRUE(spec.ports_auto);
  EXPECT_FALSE(spec.skip_unsupported);
  ASSERT_EQ(spec.files.size(), 2u);
  EXPECT_EQ(spec.files[1].value, Data + "/office.rad");
  EXPECT_EQ(spec.files[1].location.line, 5);

  const SceneDescription scene = build_scene_description(p);
  ASSERT_EQ(scene.surfaces.size(), 10u);
  ASSERT_EQ(scene.materials.size(), 4u);
  for (const Surface& s : scene.surfaces) {
    EXPECT_FALSE(s.port) << s.name;
    EXPECT_EQ(s.port_if_outdoors, s.name == "window") << s.name;
  }
  const Surface& window = surface_named(scene, "window");
  EXPECT_EQ(scene.materials[static_cast<std::size_t>(window.material)].type, MaterialType::Glass);
  EXPECT_NEAR(scene.materials[static_cast<std::size_t>(window.material)].transmittance.x, 0.60, 1e-4);
  EXPECT_EQ(window.location.file, Data + "/office.rad");
  EXPECT_TRUE(scene.warnings.empty());
  // The polygon grid over the floor outline is the office's work plane: 11 x 15 sensors.
  ASSERT_EQ(scene.grids.size(), 1u);
  EXPECT_EQ(scene.grids[0].points.size(), 165u);
  EXPECT_TRUE(scene.grids[0].planar);
}

TEST(RadianceImport, ListedModifiersArePorts) {
  const Project p = load_project_from_string(
      project_text("    - files: [materials.rad, office.rad]\n      ports: [glass_mat]\n"), ProjectPath);
  const SceneDescription scene = build_scene_description(p);
  for (const Surface& s : scene.surfaces) {
    EXPECT_FALSE(s.port_if_outdoors);
    EXPECT_EQ(s.port, s.name == "window") << s.name;
  }
  EXPECT_EQ(surface_named(scene, "window").facing, PortFacing::Auto);
  // An empty list: no port at all.
  const Project none = load_project_from_string(
      project_text("    - files: [materials.rad, office.rad]\n      ports: []\n"), ProjectPath);
  for (const Surface& s : build_scene_description(none).surfaces) EXPECT_FALSE(s.port || s.port_if_outdoors);
}

TEST(RadianceImport, AProjectMaterialReplacesTheImportedOne) {
  const Project p = load_project_from_string(
      project_text("    - files: [materials.rad, office.rad]\n",
                   "  glass_mat: {type: glazing, panes: [{transmittance: 0.89}, {transmittance: 0.89}]}\n"),
      ProjectPath);
  const SceneDescription scene = build_scene_description(p);
  const Surface& window = surface_named(scene, "window");
  EXPECT_EQ(scene.materials[static_cast<std::size_t>(window.material)].type, MaterialType::Glazing);
  EXPECT_TRUE(window.port_if_outdoors);  // a glazing transmits: still a candidate
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_NE(scene.warnings[0].message.find("the project's material 'glass_mat' (glazing) replaces"),
            std::string::npos);
  EXPECT_EQ(scene.warnings[0].location.file, Data + "/materials.rad");
}

TEST(RadianceImport, OutdoorModifiersMakeOutdoorScatterers) {
  // `outdoor` takes modifiers as `ports` does; their surfaces are outdoor scatterers (their
  // light traced, placement_check.h names the others outside a port) and never ports, even
  // of glass under `ports: auto`. Every imported surface says where it comes from.
  const Project p = load_project_from_string(
      project_text("    - files: [materials.rad, office.rad]\n      outdoor: [wall_mat, glass_mat]\n"), ProjectPath);
  ASSERT_EQ(p.geometry.radiance[0].outdoor_modifiers.size(), 2u);
  EXPECT_EQ(p.geometry.radiance[0].outdoor_modifiers[1].location.line, 6);
  const SceneDescription scene = build_scene_description(p);
  for (const Surface& s : scene.surfaces) {
    const std::string& material = scene.materials[static_cast<std::size_t>(s.material)].name;
    EXPECT_EQ(s.outdoor_scatterer, material == "wall_mat" || material == "glass_mat") << s.name;
    EXPECT_FALSE(s.port || s.port_if_outdoors) << s.name;
    EXPECT_EQ(s.origin, SurfaceOrigin::Radiance) << s.name;
  }
  EXPECT_TRUE(surface_named(scene, "wall_north").outdoor_scatterer);
  EXPECT_FALSE(surface_named(scene, "floor").outdoor_scatterer);
}

TEST(RadianceImport, OutdoorErrorsAreLocated) {
  const Project misspelt = load_project_from_string(
      project_text("    - files: [materials.rad, office.rad]\n      outdoor: [wal_mat]\n"), ProjectPath);
  EXPECT_EQ(test::located_errors([&] { build_scene_description(misspelt); }),
            std::vector<std::string>{
                "6:17: outdoor: modifier 'wal_mat' is not defined in the RADIANCE scene's files (did you mean "
                "'wall_mat'?)"});
  const Project both = load_project_from_string(
      project_text("    - files: [materials.rad, office.rad]\n      ports: [glass_mat]\n      outdoor: [glass_mat]\n"),
      ProjectPath);
  EXPECT_EQ(test::located_errors([&] { build_scene_description(both); }),
            std::vector<std::string>{"7:17: outdoor: modifier 'glass_mat' is also listed under 'ports' (at " +
                                     ProjectPath + ":6:15): light enters the room through a port; an outdoor "
                                     "surface sends light toward the ports"});
  EXPECT_EQ(test::located_errors([&] {
              load_project_from_string(project_text("    - files: [office.rad]\n      outdoor: []\n"), ProjectPath);
            }),
            std::vector<std::string>{"6:16: expected a list of one or more names for 'outdoor', got an empty list"});
}

TEST(RadianceImport, YamlSideErrorsAreLocated) {
  EXPECT_EQ(test::located_errors([&] {
              load_project_from_string(project_text("    - files: [materials.rad, offfice.rad]\n"), ProjectPath);
            }),
            std::vector<std::string>{"5:30: RADIANCE scene file 'offfice.rad' not found (looked for '" + Data +
                                     "/offfice.rad')"});
  EXPECT_EQ(test::located_errors([&] {
              load_project_from_string(project_text("    - files: [office.rad]\n      ports: yes\n"), ProjectPath);
            }),
            std::vector<std::string>{"6:14: expected 'auto' or a list of modifier names for 'ports', got 'yes'"});
  EXPECT_EQ(test::located_errors([&] {
              load_project_from_string(project_text("    - files: [office.rad]\n      unsupported: ignore\n"),
                                       ProjectPath);
            }).size(),
            1u);
  // Found when the scene is built: a ports list naming no modifier of the files.
  const Project p = load_project_from_string(
      project_text("    - files: [materials.rad, office.rad]\n      ports: [glas_mat]\n"), ProjectPath);
  EXPECT_EQ(test::located_errors([&] { build_scene_description(p); }),
            std::vector<std::string>{
                "6:15: ports: modifier 'glas_mat' is not defined in the RADIANCE scene's files (did you mean "
                "'glass_mat'?)"});
  // A modifier used before it is defined (files in the wrong order) points into the .rad file.
  const Project reversed =
      load_project_from_string(project_text("    - files: [office.rad, materials.rad]\n"), ProjectPath);
  const std::vector<std::string> errors = test::located_errors([&] { build_scene_description(reversed); },
                                                               Data + "/office.rad");
  ASSERT_EQ(errors.size(), 10u);
  EXPECT_EQ(errors[0], "7:1: polygon 'floor': modifier 'floor_mat' is not defined before it is used (files are "
                       "read in order, as oconv reads them)");
}

}  // namespace
}  // namespace dayphoton::project
