// Sensor placement (engine/sensor_placement.h): sensors outside every room or inside a
// solid are told apart from sensors in a room, without false alarms for the legitimate
// places: on a surface, near a wall, under a thin shelf, in a room of polygons wound either
// way, in front of a window, in the enclosure of an exterior system.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>

#include "dayphoton/engine/scene.h"
#include "dayphoton/engine/sensor_placement.h"
#include "test_scenes.h"

namespace dayphoton::engine {
namespace {

/// The reference office (a glazed window in its south wall y = 0) with a 0.4 x 0.4 m column
/// from floor to ceiling at x, y in [2.8, 3.2] x [3.8, 4.2] (a box: faces wound outward) and
/// a thin shelf polygon at z = 2.
SceneDescription office_with_column() {
  SceneDescription d = test::office_room();
  const int grey = test::add_material(d, "column", MaterialType::Lambertian, 0.5);
  const double x0 = 2.8, x1 = 3.2, y0 = 3.8, y1 = 4.2, z1 = 3;
  auto face = [&](const char* name, std::vector<Vec3> v) {
    test::add_surface(d, name, grey, std::move(v));
    d.surfaces.back().solid_face = true;
  };
  face("column.bottom", {{x0, y0, 0}, {x0, y1, 0}, {x1, y1, 0}, {x1, y0, 0}});
  face("column.top", {{x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}});
  face("column.south", {{x0, y0, 0}, {x1, y0, 0}, {x1, y0, z1}, {x0, y0, z1}});
  face("column.north", {{x0, y1, 0}, {x0, y1, z1}, {x1, y1, z1}, {x1, y1, 0}});
  face("column.west", {{x0, y0, 0}, {x0, y0, z1}, {x0, y1, z1}, {x0, y1, 0}});
  face("column.east", {{x1, y0, 0}, {x1, y1, 0}, {x1, y1, z1}, {x1, y0, z1}});
  test::add_surface(d, "shelf", grey, {{0.5, 6, 2}, {2, 6, 2}, {2, 7.5, 2}, {0.5, 7.5, 2}});
  return d;
}

SensorPlacement placement_of(const Scene& scene, Vec3 position, Vec3 normal = {0, 0, 1}) {
  return test_sensor_placement(scene, SensorPoint{position, normal}).placement;
}

TEST(SensorPlacement, InARoomAnywhereLegitimate) {
  const Scene scene = Scene::build(office_with_column());
  EXPECT_EQ(placement_of(scene, {3, 2, 0.8}), SensorPlacement::InRoom);            // work plane
  EXPECT_EQ(placement_of(scene, {3, 7, 0.8}), SensorPlacement::InRoom);            // back of the room
  EXPECT_EQ(placement_of(scene, {3, 2, 0}), SensorPlacement::InRoom);              // on the floor
  EXPECT_EQ(placement_of(scene, {3, 2, 3}, {0, 0, -1}), SensorPlacement::InRoom);  // on the ceiling
  EXPECT_EQ(placement_of(scene, {3, 8, 1.5}, {0, -1, 0}), SensorPlacement::InRoom);  // on the back wall
  EXPECT_EQ(placement_of(scene, {0.001, 4, 1.5}, {1, 0, 0}), SensorPlacement::InRoom);  // 1 mm from a wall
  EXPECT_EQ(placement_of(scene, {3, 0.01, 1.5}, {0, -1, 0}), SensorPlacement::InRoom);  // facing the window
  EXPECT_EQ(placement_of(scene, {1, 7, 1.99}), SensorPlacement::InRoom);           // under the shelf
  EXPECT_EQ(placement_of(scene, {1, 7, 2}), SensorPlacement::InRoom);              // on the shelf
  EXPECT_EQ(placement_of(scene, {3, 3.8, 1}, {0, -1, 0}), SensorPlacement::InRoom);  // on the column
}

TEST(SensorPlacement, InsideAColumn) {
  const Scene scene = Scene::build(office_with_column());
  const SensorPlacementTest t = test_sensor_placement(scene, {{3, 4, 0.8}, {0, 0, 1}});
  EXPECT_EQ(t.placement, SensorPlacement::InsideSolid);
  EXPECT_EQ(t.through_port, 0);
  ASSERT_GE(t.solid_surface, 0);
  EXPECT_EQ(scene.description().surfaces[static_cast<std::size_t>(t.solid_surface)].name.rfind("column.", 0), 0u);
  // Facing sideways, near a corner of the column: still inside.
  EXPECT_EQ(placement_of(scene, {2.81, 3.81, 2.5}, {1, 0, 0}), SensorPlacement::InsideSolid);
}

TEST(SensorPlacement, OutsideEveryRoom) {
  const Scene scene = Scene::build(office_with_column());
  EXPECT_EQ(placement_of(scene, {3, 4, 10}), SensorPlacement::OutsideRooms);         // open sky
  EXPECT_EQ(placement_of(scene, {3, 4, 3.5}), SensorPlacement::OutsideRooms);        // above the ceiling
  EXPECT_EQ(placement_of(scene, {3, -5, 1.5}, {0, 0, 1}), SensorPlacement::OutsideRooms);  // in front of the facade
  EXPECT_EQ(placement_of(scene, {3, 4, -0.5}, {0, 0, -1}), SensorPlacement::OutsideRooms);  // under the floor
  // A sensor on the ceiling facing up looks out through the roof.
  EXPECT_EQ(placement_of(scene, {3, 2, 3}, {0, 0, 1}), SensorPlacement::OutsideRooms);
}

TEST(SensorPlacement, PolygonsOfEitherWindingAreNotSolids) {
  // The office with every polygon wound outward (back faces toward the room) and marked as
  // solid faces would look like a solid; as polygons (solid_face false) it is a room.
  SceneDescription d = test::office_room();
  for (Surface& s : d.surfaces) std::reverse(s.vertices.begin(), s.vertices.end());
  const Scene scene = Scene::build(d);
  for (double y : {1.0, 4.0, 7.9})
    EXPECT_EQ(placement_of(scene, {3, y, 0.8}), SensorPlacement::InRoom) << "y " << y;
}

TEST(SensorPlacement, AMeshRoomWoundOutwardIsARoom) {
  // The office drawn as a mesh wound outward (every face a solid face, its back toward the
  // room): a sensor facing the back wall sees only the back of solid faces in its
  // hemisphere, but a ray aimed at the window reaches it.
  SceneDescription d = test::office_room();
  for (Surface& s : d.surfaces) {
    std::reverse(s.vertices.begin(), s.vertices.end());
    s.solid_face = !s.port;
  }
  const Scene scene = Scene::build(d);
  const SensorPlacementTest t = test_sensor_placement(scene, {{3, 6, 1.5}, {0, 1, 0}});
  EXPECT_EQ(t.placement, SensorPlacement::InRoom);
  EXPECT_EQ(t.back_of_solid, t.rays);  // every spread ray met the back of a face
}

TEST(SensorPlacement, TenThousandSensorsTakeWellUnderASecond) {
  const Scene scene = Scene::build(office_with_column());
  std::vector<SensorPoint> sensors;
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j < 100; ++j) sensors.push_back({{0.03 + 0.0594 * i, 0.04 + 0.0792 * j, 0.8}, {0, 0, 1}});
  const auto start = std::chrono::steady_clock::now();
  const std::vector<SensorPlacementTest> tests = test_sensor_placements(scene, sensors);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("seconds_for_10000_sensors", std::to_string(seconds));
  EXPECT_LT(seconds, 2.0);
  // The sensors inside the column, and only they, are inside a solid.
  for (std::size_t k = 0; k < sensors.size(); ++k) {
    const Vec3& p = sensors[k].position;
    const bool in_column = p.x > 2.8 && p.x < 3.2 && p.y > 3.8 && p.y < 4.2;
    EXPECT_EQ(tests[k].placement, in_column ? SensorPlacement::InsideSolid : SensorPlacement::InRoom)
        << "sensor " << k << " at " << p.x << ", " << p.y;
  }
}

}  // namespace
}  // namespace dayphoton::engine
