// Sensor grids and point files:
// - the office work-plane grid equals tests/data/radiance/grid_0p8m.pts (165 points,
//   11 x 15, y rows outer, x inner, first (0.5, 0.5, 0.8), last (5.5, 7.5, 0.8));
// - floating error never drops the last row (0.7 / 0.1 = 6.999999999999999);
// - lattices are centred when the span is not a multiple of the spacing;
// - polygon grids keep the lattice points inside with distance to the boundary >= inset
//   (hand-counted L-shapes);
// - grids without points and unknown rooms are located errors;
// - .pts files: comments, normalisation, located errors for every malformed line.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "dayphoton/core/polygon.h"
#include "dayphoton/project/project.h"
#include "dayphoton/project/pts_reader.h"
#include "geometry_fixture.h"

namespace dayphoton::project {
namespace {

using testing::build_error;
using testing::office_project;

TEST(SensorGrid, OfficeWorkPlaneMatchesReferenceOrder) {
  const SceneDescription scene = build_scene_description(office_project());
  ASSERT_EQ(scene.grids.size(), 1u);
  const SensorGrid& g = scene.grids[0];
  EXPECT_EQ(g.name, "workplane");
  ASSERT_EQ(g.points.size(), 165u);
  EXPECT_EQ(g.columns, 11);
  EXPECT_EQ(g.rows, 15);
  EXPECT_DOUBLE_EQ(g.spacing_m, 0.5);
  EXPECT_TRUE(g.planar);
  EXPECT_EQ(g.plane_normal, Vec3(0, 0, 1));
  EXPECT_DOUBLE_EQ(g.plane_height_m, 0.8);
  EXPECT_EQ(g.points.front().position, Vec3(0.5, 0.5, 0.8));
  EXPECT_EQ(g.points.back().position, Vec3(5.5, 7.5, 0.8));
  for (int iy = 0; iy < 15; ++iy)
    for (int ix = 0; ix < 11; ++ix) {
      const SensorPoint& s = g.points[static_cast<std::size_t>(11 * iy + ix)];
      EXPECT_NEAR(s.position.x, 0.5 + 0.5 * ix, 1e-12);
      EXPECT_NEAR(s.position.y, 0.5 + 0.5 * iy, 1e-12);
      EXPECT_EQ(s.normal, Vec3(0, 0, 1));
    }

  const std::string ref = std::string(DAYPHOTON_TEST_DATA_DIR) + "/radiance/grid_0p8m.pts";
  ASSERT_TRUE(std::ifstream(ref)) << "reference sensors not found: " << ref;
  Diagnostics diag;
  const std::vector<SensorPoint> expected = read_pts(ref, diag);
  ASSERT_FALSE(diag.has_errors()) << diag.format();
  ASSERT_EQ(expected.size(), g.points.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_LT(length(expected[i].position - g.points[i].position), 1e-9) << "sensor " << i;
    EXPECT_LT(length(expected[i].normal - g.points[i].normal), 1e-12) << "sensor " << i;
  }
}

TEST(SensorGrid, FloatingErrorDoesNotDropTheLastRow) {
  Project p = office_project();
  RoomSpec& room = p.geometry.rooms[0];
  room.origin = {10, 20, 3};
  room.size_m = {0.7, 0.3, 2.5};
  room.windows.clear();
  GridSpec& g = p.sensors.grids[0];
  g.spacing_m = 0.1;
  g.inset_m = 0;
  ASSERT_LT(0.7 / 0.1, 7.0);  // the trap
  const SceneDescription scene = build_scene_description(p);
  const SensorGrid& grid = scene.grids[0];
  EXPECT_EQ(grid.columns, 8);
  EXPECT_EQ(grid.rows, 4);
  ASSERT_EQ(grid.points.size(), 32u);
  EXPECT_NEAR(grid.points.back().position.x, 10.7, 1e-12);
  EXPECT_NEAR(grid.points.back().position.y, 20.3, 1e-12);
  EXPECT_NEAR(grid.points.back().position.z, 3.8, 1e-12);  // height above the room's floor
}

TEST(SensorGrid, LatticeIsCentredInTheInsetRectangle) {
  Project p = office_project();
  p.geometry.rooms[0].size_m.x = 6.2;  // span 5.2 = 10 spacings + 0.2 left over
  const SceneDescription scene = build_scene_description(p);
  const SensorGrid& grid = scene.grids[0];
  EXPECT_EQ(grid.columns, 11);
  EXPECT_NEAR(grid.points.front().position.x, 0.6, 1e-12);
  EXPECT_NEAR(grid.points[10].position.x, 5.6, 1e-12);
}

GridSpec l_shape_grid(double inset_m) {
  GridSpec g;
  g.name = "l";
  g.polygon = {{0, 0, 7}, {4, 0, 7}, {4, 2, 7}, {2, 2, 7}, {2, 4, 7}, {0, 4, 7}};  // z ignored
  g.height_m = 0.75;
  g.spacing_m = 1;
  g.inset_m = inset_m;
  g.location = {"p.yaml", 40, 3};
  return g;
}

TEST(SensorGrid, PolygonGridKeepsPointsInsideAtTheInset) {
  Project p = office_project();
  p.sensors.grids = {l_shape_grid(0.5)};
  SceneDescription scene = build_scene_description(p);
  ASSERT_EQ(scene.grids.size(), 1u);
  // 4 x 4 lattice at 0.5, 1.5, 2.5, 3.5 minus the 4 points of the missing quadrant.
  const std::vector<std::pair<double, double>> expected{
      {0.5, 0.5}, {1.5, 0.5}, {2.5, 0.5}, {3.5, 0.5}, {0.5, 1.5}, {1.5, 1.5},
      {2.5, 1.5}, {3.5, 1.5}, {0.5, 2.5}, {1.5, 2.5}, {0.5, 3.5}, {1.5, 3.5}};
  const SensorGrid& g = scene.grids[0];
  ASSERT_EQ(g.points.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(g.points[i].position.x, expected[i].first, 1e-12) << i;
    EXPECT_NEAR(g.points[i].position.y, expected[i].second, 1e-12) << i;
    EXPECT_DOUBLE_EQ(g.points[i].position.z, 0.75);
  }
  EXPECT_TRUE(g.planar);
  EXPECT_EQ(g.outline.size(), 6u);
  EXPECT_DOUBLE_EQ(g.outline[0].z, 0.75);

  // Inset 0.6: lattice 1, 2, 3 in each axis; points on the inner edges (distance 0) and in
  // the missing quadrant are dropped, leaving 5.
  p.sensors.grids = {l_shape_grid(0.6)};
  scene = build_scene_description(p);
  const std::vector<std::pair<double, double>> kept{{1, 1}, {2, 1}, {3, 1}, {1, 2}, {1, 3}};
  ASSERT_EQ(scene.grids[0].points.size(), kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const Vec3 q = scene.grids[0].points[i].position;
    EXPECT_NEAR(q.x, kept[i].first, 1e-12);
    EXPECT_NEAR(q.y, kept[i].second, 1e-12);
    EXPECT_GE(distance_to_polygon_boundary_m(scene.grids[0].outline, q), 0.6 - 1e-12);
  }
}

// A sensor whose lattice cell the outline cuts stands for the part of the cell inside it
// (project/src/sensor_areas.h, where the choice is measured against equal counts). The
// office (inset 0.5 m, spacing 0.5 m) and the L at inset 0.5 m have whole cells only: no
// areas, every sensor an equal share. A 6 x 8 m room at inset 0, spacing 1 m, puts its
// sensors on the walls: half a cell on a wall, a quarter in a corner (0.25 x 4 + 0.5 x 24 +
// 1 x 35 = 48 m^2, the floor). The L at inset 0: 0.75 m^2 at its re-entrant corner (2, 2),
// 0.5 on the notch's edges, 12 m^2 in all.
TEST(SensorGrid, CellsCutByTheOutlineCarryTheirFloorArea) {
  Project p = office_project();
  EXPECT_TRUE(build_scene_description(p).grids[0].area_m2.empty());
  p.sensors.grids = {l_shape_grid(0.5)};
  EXPECT_TRUE(build_scene_description(p).grids[0].area_m2.empty());

  p = office_project();
  p.sensors.grids[0].inset_m = 0;
  p.sensors.grids[0].spacing_m = 1;
  const SensorGrid room = build_scene_description(p).grids[0];
  ASSERT_EQ(room.points.size(), 63u);  // 7 x 9
  ASSERT_EQ(room.area_m2.size(), 63u);
  double total_m2 = 0;
  for (std::size_t i = 0; i < room.points.size(); ++i) {
    const Vec3 q = room.points[i].position;
    const int on_walls = int(q.x == 0 || q.x == 6) + int(q.y == 0 || q.y == 8);
    EXPECT_NEAR(room.area_m2[i], on_walls == 2 ? 0.25 : on_walls == 1 ? 0.5 : 1.0, 1e-12) << i;
    total_m2 += room.area_m2[i];
  }
  EXPECT_NEAR(total_m2, 48.0, 1e-9);

  p.sensors.grids = {l_shape_grid(0)};
  const SensorGrid l = build_scene_description(p).grids[0];
  ASSERT_EQ(l.area_m2.size(), l.points.size());
  total_m2 = 0;
  for (std::size_t i = 0; i < l.points.size(); ++i) {
    const Vec3 q = l.points[i].position;
    if (q.x == 2 && q.y == 2) {
      EXPECT_NEAR(l.area_m2[i], 0.75, 1e-12);
    }
    if (q.x == 3 && q.y == 2) {
      EXPECT_NEAR(l.area_m2[i], 0.5, 1e-12);
    }
    total_m2 += l.area_m2[i];
  }
  EXPECT_NEAR(total_m2, 12.0, 1e-9);
}

TEST(SensorGrid, GridsWithoutPointsAndUnknownRoomsAreLocatedErrors) {
  Project p = office_project();
  p.sensors.grids[0].inset_m = 3.5;  // 6 - 7 < 0
  EXPECT_NE(build_error(p).find("office.yaml:30:5: error: grid 'workplane' has no points"), std::string::npos)
      << build_error(p);
  p = office_project();
  p.sensors.grids = {l_shape_grid(1.5)};  // no lattice point is 1.5 m from every edge
  EXPECT_NE(build_error(p).find("p.yaml:40:3: error: grid 'l' has no points"), std::string::npos)
      << build_error(p);
  p = office_project();
  p.sensors.grids[0].room = "ofice";
  EXPECT_NE(build_error(p).find("unknown room 'ofice' (did you mean 'office'?)"), std::string::npos);
  p = office_project();
  p.sensors.grids[0].spacing_m = 0;
  EXPECT_NE(build_error(p).find("spacing must be positive"), std::string::npos);
  p = office_project();
  p.sensors.grids.push_back(p.sensors.grids[0]);
  EXPECT_NE(build_error(p).find("sensor set name 'workplane' is used twice"), std::string::npos);
}

TEST(SensorGrid, ARoomGridAboveTheCeilingOrBelowTheFloorIsALocatedError) {
  // A grid at 3.5 m in a 3 m room lies on the roof, outside the room: an error at `height`.
  Project p = office_project();
  p.sensors.grids[0].height_m = 3.5;
  p.sensors.grids[0].key_locations.push_back({"height", {"office.yaml", 31, 13}});
  EXPECT_NE(build_error(p).find("office.yaml:31:13: error: grid 'workplane': height 3.5 m puts the sensors above the "
                                "ceiling of room 'office' (3 m high); a room grid's height is measured from the "
                                "floor and must lie in [0, 3] m"),
            std::string::npos)
      << build_error(p);
  p.sensors.grids[0].height_m = -0.1;
  EXPECT_NE(build_error(p).find("height -0.1 m puts the sensors below the floor"), std::string::npos) << build_error(p);
  // The floor and the ceiling themselves are sensor planes.
  for (double h : {0.0, 3.0}) {
    p.sensors.grids[0].height_m = h;
    EXPECT_EQ(build_error(p), "") << "height " << h;
  }
}

TEST(PtsReader, ReadsAndNormalises) {
  Diagnostics diag;
  const auto pts = read_pts_from_string(
      "# sensors\n"
      "0.5 0.5 0.8 0 0 1\n"
      "\n"
      "  1\t2 3   0 0 2   # trailing comment\r\n"
      "1e0 -2.5 0 3 4 0\n",
      "s.pts", diag);
  ASSERT_FALSE(diag.has_errors()) << diag.format();
  ASSERT_EQ(pts.size(), 3u);
  EXPECT_EQ(pts[0].position, Vec3(0.5, 0.5, 0.8));
  EXPECT_EQ(pts[1].position, Vec3(1, 2, 3));
  EXPECT_EQ(pts[1].normal, Vec3(0, 0, 1));
  EXPECT_NEAR(pts[2].normal.x, 0.6, 1e-15);
  EXPECT_NEAR(pts[2].normal.y, 0.8, 1e-15);
}

TEST(PtsReader, EveryMalformedLineIsLocated) {
  Diagnostics diag;
  const auto pts = read_pts_from_string(
      "0 0 0 0 0 1\n"
      "0 0 0.8 0 0\n"       // 2: five values
      "0 x 0.8 0 0 1\n"     // 3: not a number at column 3
      "0 0 0.8 0 0 0\n"     // 4: zero direction (column of nx = 9)
      "0 0 nan 0 0 1\n"     // 5: not finite at column 5
      "0 0 0 0 0 1 7\n",    // 6: seven values, extra at column 13
      "s.pts", diag);
  EXPECT_EQ(pts.size(), 1u);
  const std::string text = diag.format();
  EXPECT_NE(text.find("s.pts:2:12: error: expected 6 values per sensor (x y z nx ny nz), found 5"),
            std::string::npos) << text;
  EXPECT_NE(text.find("s.pts:3:3: error: expected a number, found 'x'\n    0 x 0.8 0 0 1\n      ^\n"),
            std::string::npos) << text;
  EXPECT_NE(text.find("s.pts:4:9: error: sensor direction is zero"), std::string::npos) << text;
  EXPECT_NE(text.find("s.pts:5:5: error: value is not finite ('nan')"), std::string::npos) << text;
  EXPECT_NE(text.find("s.pts:6:13: error: expected 6 values"), std::string::npos) << text;
  EXPECT_EQ(diag.error_count(), 5u);
}

TEST(PtsReader, PointSetsThroughTheSceneBuilder) {
  testing::TempFile file("sensor_grid_test_points.pts", "1 2 3 0 0 -5\n4 5 6 1 0 0\n");
  Project p = office_project();
  PointsSpec spec;
  spec.name = "extra";
  spec.points = {{{0, 0, 1}, {0, 1, 0}}};
  spec.file = file.path();
  spec.location = {"office.yaml", 50, 5};
  p.sensors.points.push_back(spec);
  const SceneDescription scene = build_scene_description(p);
  ASSERT_EQ(scene.grids.size(), 2u);
  const SensorGrid& g = scene.grids[1];
  ASSERT_EQ(g.points.size(), 3u);  // inline first, then the file's
  EXPECT_EQ(g.points[1].normal, Vec3(0, 0, -1));
  EXPECT_EQ(g.points[2].position, Vec3(4, 5, 6));

  // A missing file is reported at the project entry that names it.
  p.sensors.points[0].file = file.path() + ".missing";
  EXPECT_NE(build_error(p).find("office.yaml:50:5: error: sensor file '" + file.path() + ".missing' not found"),
            std::string::npos);
  // Zero inline direction.
  p.sensors.points[0].file.clear();
  p.sensors.points[0].points[0].normal = {0, 0, 0};
  EXPECT_NE(build_error(p).find("point 1 needs a finite position and a non-zero direction"), std::string::npos);
}

}  // namespace
}  // namespace dayphoton::project

namespace dayphoton::project {
namespace {

using testing::build_error;
using testing::office_project;

TEST(SensorGridLimits, CountIsCheckedBeforeAnyPointIsMade) {
  // spacing 1e-6 m in the 6 x 8 m office: 5e6 x 7e6 sensors; 1e-300 m: a count no integer
  // type holds (the old code converted it to int, undefined behaviour). Both located at
  // `spacing`, at once.
  Project p = office_project();
  p.sensors.grids[0].spacing_location = {"office.yaml", 33, 16};
  p.sensors.grids[0].spacing_m = 1e-6;
  EXPECT_EQ(build_error(p),
            "office.yaml:33:16: error: grid 'workplane' (5e+06 x 7e+06 at spacing 1e-06 m over room 'office', 6 x 8 m) "
            "would have 3.5e+13 sensors, more than the limit of 20000 (raise it with limits.sensors_per_grid if you "
            "mean it)\n1 error generated.\n");
  p.sensors.grids[0].spacing_m = 1e-300;
  EXPECT_NE(build_error(p).find("(5e+300 x 7e+300 at spacing 1e-300 m over room 'office', 6 x 8 m) would have inf sensors"), std::string::npos) << build_error(p);
  // A room of 1e6 m at the default spacing.
  p = office_project();
  p.geometry.rooms[0].size_m = {1e6, 1e6, 3};
  EXPECT_NE(build_error(p).find("office.yaml:30:5: error: grid 'workplane' (2e+06 x 2e+06 at spacing 0.5 m"),
            std::string::npos)
      << build_error(p);
}

TEST(SensorGridLimits, RaisedLimitAdmitsTheGrid) {
  Project p = office_project();
  p.sensors.grids[0].spacing_m = 0.03;  // 167 x 234 = 39078 sensors
  EXPECT_NE(build_error(p).find("would have 39078 sensors"), std::string::npos) << build_error(p);
  p.limits.sensors_per_grid = 39078;
  const SceneDescription scene = build_scene_description(p);
  EXPECT_EQ(scene.grids.at(0).points.size(), 39078u);
}

TEST(SensorGridLimits, PolygonGridsAndPointSetsAreLimited) {
  Project p = office_project();
  GridSpec& g = p.sensors.grids[0];
  g.room.clear();
  g.polygon = {{1, 1, 0}, {4, 1, 0}, {4, 2.1, 0}, {1, 2.1, 0}};
  g.inset_m = 0;
  g.spacing_m = 0.1;  // 31 x 12 = 372 points
  EXPECT_EQ(build_scene_description(p).grids.at(0).points.size(), 372u);
  p.limits.sensors_per_grid = 371;  // the area estimate (330) passes; the points made do not
  EXPECT_NE(build_error(p).find("grid 'workplane' would have 372 sensors, more than the limit of 371"), std::string::npos)
      << build_error(p);
  p.limits.sensors_per_grid = 300;  // the area estimate already fails
  EXPECT_NE(build_error(p).find("grid 'workplane' (a polygon of 3.3 m2 at spacing 0.1 m) would have 330 sensors"),
            std::string::npos)
      << build_error(p);

  // A point set: inline points and the lines of its .pts file.
  p = office_project();
  p.limits.sensors_per_grid = 2;
  testing::TempFile file("sensor_grid_limits.pts", "1 1 1 0 0 1\n2 2 1 0 0 1\n3 3 1 0 0 1\n");
  PointsSpec spec;
  spec.name = "desks";
  spec.file = file.path();
  spec.location = {"office.yaml", 50, 5};
  p.sensors.grids.clear();
  p.sensors.points.push_back(spec);
  EXPECT_NE(build_error(p).find(file.path() + ":3:1: error: this file holds more than the limit of 2 sensors"),
            std::string::npos)
      << build_error(p);
}

TEST(SensorGridLimits, TotalOverAllSetsIsLimited) {
  Project p = office_project();
  p.sensors.grids.push_back(p.sensors.grids[0]);
  p.sensors.grids[1].name = "second";
  p.sensors.grids[1].location = {"office.yaml", 36, 5};
  p.limits.sensors = 300;  // 2 x 165
  EXPECT_EQ(build_error(p),
            "office.yaml:36:5: error: sensor set 'second' brings the project to 330 sensors, more than the limit of "
            "300 (raise it with limits.sensors if you mean it)\n1 error generated.\n");
  p.limits.sensors = 330;
  EXPECT_EQ(build_scene_description(p).grids.size(), 2u);
}

TEST(PtsReader, AWronglyNamedFileIsNotEchoedLineByLine) {
  std::string passwd_like;
  for (int i = 0; i < 60; ++i) passwd_like += "user" + std::to_string(i) + ":x:1000:1000::/home/user:/bin/bash\n";
  Diagnostics diag;
  read_pts_from_string(passwd_like, "passwd.pts", diag);
  // Two errors per line (not a number; 1 value, not 6) for three lines, then why it stopped:
  // 3 of the 60 lines echoed, not 25 (the diagnostics' cap of 50).
  ASSERT_EQ(diag.entries().size(), 7u) << diag.format();
  EXPECT_EQ(diag.entries()[5].location.line, 3);
  EXPECT_EQ(diag.entries()[6].location.line, 4);
  EXPECT_EQ(diag.entries()[6].message,
            "stopping after 5 errors and no valid line: is this a sensor file (x y z nx ny nz per line)?");
  EXPECT_EQ(diag.entries()[0].message, "expected a number, found 'user0:x:1000:1000::/home/user:/bin/bash'");
  // A long token is cut in the message.
  Diagnostics long_token;
  read_pts_from_string(std::string(100, 'a') + " 1 2 0 0 1\n", "long.pts", long_token);
  EXPECT_EQ(long_token.entries().at(0).message, "expected a number, found '" + std::string(40, 'a') + "...'");
}

}  // namespace
}  // namespace dayphoton::project
