// Port candidates (Surface::port_if_outdoors, an imported scene's glazing under `ports: auto`):
// Scene::build makes a candidate a port when its facing test finds the sky decisively on one
// side, and leaves it an ordinary surface otherwise.
#include <gtest/gtest.h>

#include "dayphoton/engine/port_facing.h"
#include "dayphoton/engine/scene.h"
#include "test_scenes.h"

namespace dayphoton::engine {
namespace {

TEST(PortCandidate, OutdoorGlazingBecomesAPortTheRestStaysGlazing) {
  SceneDescription d = test::office_room();
  const int glass = d.surfaces[test::OfficeWindowSurface].material;
  // The office window a candidate, drawn facing outside (against the file's winding).
  Surface& window = d.surfaces[test::OfficeWindowSurface];
  window.port = false;
  window.port_if_outdoors = true;
  std::reverse(window.vertices.begin(), window.vertices.end());
  // A glass partition across the room (neither side sees the sky) and a free-standing pane
  // outside (both sides see it alike): candidates too.
  test::add_surface(d, "partition", glass, {{0, 4, 0}, {6, 4, 0}, {6, 4, 3}, {0, 4, 3}});
  d.surfaces.back().port_if_outdoors = true;
  test::add_surface(d, "balustrade", glass, {{0, -3, 0}, {0, -3, 1}, {6, -3, 1}, {6, -3, 0}});
  d.surfaces.back().port_if_outdoors = true;

  const Scene scene = Scene::build(d);
  ASSERT_EQ(scene.ports().size(), 1u);
  const Port& port = scene.ports()[0];
  EXPECT_EQ(port.surface, test::OfficeWindowSurface);
  EXPECT_EQ(port.side_reason, PortSideReason::Sky);
  EXPECT_TRUE(port.against_winding);
  EXPECT_NEAR(port.normal.y, 1.0, 1e-12);  // into the room
  // The description the scene keeps says what was decided; no candidate is left.
  const SceneDescription& decided = scene.description();
  EXPECT_TRUE(decided.surfaces[test::OfficeWindowSurface].port);
  EXPECT_EQ(decided.surfaces[test::OfficeWindowSurface].facing, PortFacing::Auto);
  for (std::size_t i = 0; i < decided.surfaces.size(); ++i) {
    EXPECT_FALSE(decided.surfaces[i].port_if_outdoors);
    if (static_cast<int>(i) != test::OfficeWindowSurface) {
      EXPECT_FALSE(decided.surfaces[i].port);
    }
  }
  EXPECT_FALSE(scene.is_port(static_cast<int>(decided.surfaces.size()) - 1));
}

TEST(PortCandidate, AScenewithoutCandidatesIsBuiltAsBefore) {
  const SceneDescription d = test::office_room();
  const Scene scene = Scene::build(d);
  ASSERT_EQ(scene.ports().size(), 1u);
  EXPECT_EQ(scene.ports()[0].side_reason, PortSideReason::Generated);
}

}  // namespace
}  // namespace dayphoton::engine
