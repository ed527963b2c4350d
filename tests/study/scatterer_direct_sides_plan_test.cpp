// The plan's side of the rule that stores an outdoor scatterer's Direct photons only where a
// final gather can read them (engine/gathered_scatterer_sides.h): a case with a gathered grid
// decides the sides once, from its scene and every grid's sensors (CaseLayout), its tracing
// options carry them (SimulationPlan::tracing_for), and they enter the photon cache key.
#include <gtest/gtest.h>

#include "dayphoton/engine/gathered_scatterer_sides.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/cache_keys.h"
#include "dayphoton/study/simulation_plan.h"
#include "side_lit_room.h"

namespace dayphoton::study {
namespace {

// A side-lit room (window head at 2.4 m) with an exterior overhang at 2.5 m (its parts
// outdoor scatterers); `grid` its sensors.
std::string overhang_room_yaml(const std::string& grid) {
  return test::side_lit_room_yaml(
      "[4, 5, 3]", "3", 1000, grid,
      "{type: overhang, name: overhang, window: w, height: 2.5, depth: 0.6, thickness: 0.1, material: walls}");
}

struct Case {
  explicit Case(const std::string& grid)
      : project(project::load_project_from_string(overhang_room_yaml(grid), "room.yaml")),
        plan(SimulationPlan::of(project)),
        d(project::build_scene_description(project)),
        scene(engine::Scene::build(d)) {
    for (const MaterialSpec& m : d.materials) materials.push_back(engine::Material::from_spec(m));
    layout = CaseLayout::of(d.grids, scene, materials);
  }
  project::Project project;
  SimulationPlan plan;
  SceneDescription d;
  engine::Scene scene;
  std::vector<engine::Material> materials;
  CaseLayout layout;
};

TEST(ScattererDirectSidesPlan, AGatheredGridGetsTheSidesItsGatherCanRead) {
  const Case c("{name: back, wall: {room: office, wall: north}, spacing: 1, inset: 0.5}");
  ASSERT_GT(c.scene.outdoor_scatterers().size(), 0u);
  ASSERT_EQ(c.layout.gathered_scatterer_sides.size(), c.scene.outdoor_scatterers().size());
  // The overhang's top faces the sky only: no window corner or sensor lies above it.
  std::size_t unread = 0;
  for (const std::uint8_t s : c.layout.gathered_scatterer_sides)
    if (s != engine::ScattererBothSides) ++unread;
  EXPECT_GT(unread, 0u);
  const engine::TracingOptions tracing = c.plan.tracing_for(c.plan.sky_tracing, c.layout);
  EXPECT_TRUE(tracing.store_direct_on_surfaces);
  EXPECT_EQ(tracing.scatterer_direct_sides, c.layout.gathered_scatterer_sides);
  // Photons traced with the rule are not those traced without it: different cache keys.
  engine::TracingOptions without = tracing;
  without.scatterer_direct_sides.clear();
  EXPECT_NE(photon_source_key(scene_key(c.d), planes_key(c.d.grids), c.plan.basis, 3, tracing),
            photon_source_key(scene_key(c.d), planes_key(c.d.grids), c.plan.basis, 3, without));
}

TEST(ScattererDirectSidesPlan, AWorkPlaneGridStoresNoDirectPhotons) {
  const Case c("{name: workplane, room: office, height: 0.8, spacing: 1}");
  const engine::TracingOptions tracing = c.plan.tracing_for(c.plan.sky_tracing, c.layout);
  EXPECT_FALSE(tracing.store_direct_on_surfaces);
  EXPECT_TRUE(tracing.scatterer_direct_sides.empty());
}

}  // namespace
}  // namespace dayphoton::study
