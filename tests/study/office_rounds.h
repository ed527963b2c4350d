// Test support for the accuracy rounds' tests (accuracy_rounds_test.cpp,
// gather_accuracy_rounds_test.cpp, sun_accuracy_rounds_test.cpp): the reference office
// (projects/office) with its work plane at 1 m spacing (6 x 8 = 48 sensors), its scene and
// materials built, one receiver plane per grid, the Tregenza sky bins and the CIE overcast sky
// vector on them (10 000 lx, ground reflectance 0.2), and the two changes some tests make to
// its grids. Each test file adds its own case (the tracing and estimating options).
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/engine/distant_source.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/receiver_plane.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/project/project.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/sky/sky_model.h"

namespace dayphoton::test {

struct OfficeRounds {
  static constexpr double OvercastLux = 10000.0;  ///< the overcast sky's horizontal illuminance
  static constexpr double GroundReflectance = 0.2;

  project::Project project;
  SceneDescription description;
  std::unique_ptr<engine::Scene> scene;
  std::vector<engine::Material> materials;
  engine::SourceSet sources = engine::SourceSet::sky_bins(sky::PatchBasis::tregenza());
  std::vector<engine::ReceiverPlane> planes;
  std::vector<int> plane_of_grid;  ///< receiver plane of each grid, or -1
  RadianceMatrix overcast;         ///< the overcast sky vector on `sources`

  OfficeRounds() : project(project::load_project(std::string(DAYPHOTON_SOURCE_DIR) + "/projects/office/project.yaml")) {
    project.sensors.grids.at(0).spacing_m = 1.0;  // 48 sensors: a quarter of the time
    description = project::build_scene_description(project);
    scene = std::make_unique<engine::Scene>(engine::Scene::build(description));
    for (const MaterialSpec& m : description.materials) materials.push_back(engine::Material::from_spec(m));
    for (const SensorGrid& g : description.grids) {
      plane_of_grid.push_back(static_cast<int>(planes.size()));
      planes.push_back(engine::ReceiverPlane::from_grid(g));
    }
    const double rho = GroundReflectance;
    const auto sky = sky::make_cie_overcast_sky(sky::SkyScale::horizontal_illuminance_lux(OvercastLux));
    overcast = sky::sky_vector(*sky, sky::PatchBasis::tregenza(),
                               sky::ground_radiance_rgb({rho, rho, rho}, OvercastLux, 0, {0, 0, -1}));
  }

  /// The work plane's first 8 sensors again, as a grid "gathered" off every plane: a final gather.
  void add_gathered_grid() {
    SensorGrid g = description.grids.at(0);
    g.name = "gathered";
    g.points.resize(8);
    description.grids.push_back(g);
    plane_of_grid.push_back(-1);
  }

  /// Without the work plane's grid (its receiver plane is kept, and still gets photons).
  void drop_work_plane_grid() {
    description.grids.erase(description.grids.begin());
    plane_of_grid.erase(plane_of_grid.begin());
  }
};

}  // namespace dayphoton::test
