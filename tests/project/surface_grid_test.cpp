// Wall and rectangle sensor grids (project/src/surface_grid.cpp, docs/project-format.md):
// - the office's north wall: 11 x 5 sensors, positions in the documented order, normals
//   into the room, outline, columns/rows, not a receiver plane;
// - every room surface of a room away from the origin: points on the surface plane (plus the
//   offset), inside the inset rectangle, normals into the room; the wall frames' u x v;
// - a north-rotated room: world positions and normals by the rotation written out here;
// - the window wall: lattice points in the window or within the inset of it are left out;
// - rectangles: normal u x v (right-hand rule), parallelogram inset perpendicular to edges;
// - every input error located at its key, through the YAML loader;
// - the sensor files of the backward references (tests/data/reference/) are the example's
//   wall grids, and its .pts point set is its work-plane grid.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "dayphoton/project/project.h"
#include "dayphoton/project/pts_reader.h"
#include "geometry_fixture.h"
#include "located_errors.h"

namespace dayphoton::project {
namespace {

using testing::build_error;
using testing::office_project;

constexpr double Pi = 3.14159265358979323846;

GridSpec wall_grid(const std::string& surface_name, RoomSurface surface, double offset_m = 0) {
  GridSpec g;
  g.name = surface_name;
  g.wall = GridSpec::WallReference{"office", surface};
  g.spacing_m = 0.5;
  g.inset_m = 0.5;
  g.offset_m = offset_m;
  g.location = {"office.yaml", 40, 5};
  return g;
}

TEST(SurfaceGrid, OfficeNorthWallInDocumentedOrder) {
  Project p = office_project();
  p.sensors.grids.push_back(wall_grid("back_wall", RoomSurface::North));
  const SceneDescription scene = build_scene_description(p);
  ASSERT_EQ(scene.grids.size(), 2u);
  const SensorGrid& g = scene.grids[1];
  // 6 m x 3 m wall, inset 0.5: u (= +x) 0.5..5.5 (11), v (= +z) 0.5..2.5 (5).
  EXPECT_EQ(g.columns, 11);
  EXPECT_EQ(g.rows, 5);
  ASSERT_EQ(g.points.size(), 55u);
  EXPECT_DOUBLE_EQ(g.spacing_m, 0.5);
  EXPECT_FALSE(g.planar);
  EXPECT_EQ(g.plane_normal, Vec3(0, -1, 0));
  EXPECT_DOUBLE_EQ(g.plane_height_m, -8);  // n . p = -y on the plane y = 8
  for (int iv = 0; iv < 5; ++iv)
    for (int iu = 0; iu < 11; ++iu) {
      const SensorPoint& s = g.points[static_cast<std::size_t>(11 * iv + iu)];
      EXPECT_NEAR(s.position.x, 0.5 + 0.5 * iu, 1e-12);
      EXPECT_NEAR(s.position.y, 8, 1e-12);
      EXPECT_NEAR(s.position.z, 0.5 + 0.5 * iv, 1e-12);
      EXPECT_EQ(s.normal, Vec3(0, -1, 0));
    }
  const std::vector<Vec3> outline{{0, 8, 0}, {6, 8, 0}, {6, 8, 3}, {0, 8, 3}};
  ASSERT_EQ(g.outline.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_LT(length(g.outline[i] - outline[i]), 1e-12) << i;
}

TEST(SurfaceGrid, EverySurfaceFacesIntoTheRoomAtItsOffset) {
  Project p = office_project();
  RoomSpec& room = p.geometry.rooms[0];
  room.origin = {10, -4, 2};
  room.size_m = {5, 7, 3.2};
  room.windows.clear();
  struct Case {
    const char* name;
    RoomSurface surface;
    Vec3 normal;
    Vec3 first;  // the first sensor (u = v = inset from the frame's origin), offset 0.25
    int columns, rows;
  };
  // Lattices: 5 - 1 = 4 -> 9, 7 - 1 = 6 -> 13, 3.2 - 1 = 2.2 -> 5 (centred: first at 0.6).
  const std::vector<Case> cases{
      {"south", RoomSurface::South, {0, 1, 0}, {14.5, -3.75, 2.6}, 9, 5},
      {"north", RoomSurface::North, {0, -1, 0}, {10.5, 2.75, 2.6}, 9, 5},
      {"east", RoomSurface::East, {-1, 0, 0}, {14.75, 2.5, 2.6}, 13, 5},
      {"west", RoomSurface::West, {1, 0, 0}, {10.25, -3.5, 2.6}, 13, 5},
      {"floor", RoomSurface::Floor, {0, 0, 1}, {10.5, -3.5, 2.25}, 9, 13},
      {"ceiling", RoomSurface::Ceiling, {0, 0, -1}, {10.5, -3.5, 4.95}, 9, 13},
  };
  for (const Case& c : cases) {
    p.sensors.grids = {wall_grid(c.name, c.surface, 0.25)};
    const SceneDescription scene = build_scene_description(p);
    const SensorGrid& g = scene.grids.at(0);
    EXPECT_EQ(g.columns, c.columns) << c.name;
    EXPECT_EQ(g.rows, c.rows) << c.name;
    ASSERT_EQ(g.points.size(), static_cast<std::size_t>(c.columns * c.rows)) << c.name;
    EXPECT_LT(length(g.points[0].position - c.first), 1e-12) << c.name;
    EXPECT_FALSE(g.planar) << c.name;
    EXPECT_EQ(g.plane_normal, c.normal) << c.name;
    for (const SensorPoint& s : g.points) {
      EXPECT_EQ(s.normal, c.normal) << c.name;
      // 0.25 m inside the room from the surface, at least the inset from its edges.
      const Vec3 q = s.position;
      const Vec3 lo = room.origin, hi = room.origin + room.size_m;
      const double along = dot(q - (c.normal.x + c.normal.y + c.normal.z > 0 ? lo : hi), c.normal);
      EXPECT_NEAR(along, 0.25, 1e-12) << c.name;
      for (int axis = 0; axis < 3; ++axis) {
        const double n = axis == 0 ? c.normal.x : axis == 1 ? c.normal.y : c.normal.z;
        if (n != 0) continue;
        const double v = axis == 0 ? q.x : axis == 1 ? q.y : q.z;
        const double a = axis == 0 ? lo.x : axis == 1 ? lo.y : lo.z;
        const double b = axis == 0 ? hi.x : axis == 1 ? hi.y : hi.z;
        EXPECT_GE(v, a + 0.5 - 1e-12) << c.name;
        EXPECT_LE(v, b - 0.5 + 1e-12) << c.name;
      }
    }
    // Walls: seen from inside, columns run left to right (u x v = n, v up).
    if (c.surface != RoomSurface::Floor && c.surface != RoomSurface::Ceiling) {
      const Vec3 u = g.points[1].position - g.points[0].position;
      const Vec3 v = g.points[static_cast<std::size_t>(c.columns)].position - g.points[0].position;
      EXPECT_LT(length(normalize(cross(u, v)) - c.normal), 1e-12) << c.name;
      EXPECT_NEAR(v.z, 0.5, 1e-12) << c.name;
    }
  }
}

TEST(SurfaceGrid, RotatedRoomRotatesPositionsAndNormals) {
  Project p = office_project();
  p.site.north_deg = 30;
  p.sensors.grids = {wall_grid("back_wall", RoomSurface::North), wall_grid("west_wall", RoomSurface::West)};
  const SceneDescription scene = build_scene_description(p);
  // x_w = x cos a - y sin a, y_w = x sin a + y cos a (north_rotation.h), a = 30 degrees.
  const double c = std::cos(30 * Pi / 180), s = std::sin(30 * Pi / 180);
  auto world = [&](double x, double y, double z) { return Vec3{x * c - y * s, x * s + y * c, z}; };
  const SensorGrid& north = scene.grids.at(0);
  ASSERT_EQ(north.points.size(), 55u);
  EXPECT_LT(length(north.points[0].position - world(0.5, 8, 0.5)), 1e-12);
  EXPECT_LT(length(north.points[54].position - world(5.5, 8, 2.5)), 1e-12);
  EXPECT_LT(length(north.points[12].position - world(1.0, 8, 1.0)), 1e-12);
  for (const SensorPoint& q : north.points) EXPECT_LT(length(q.normal - Vec3{s, -c, 0}), 1e-12);
  EXPECT_LT(length(north.plane_normal - Vec3{s, -c, 0}), 1e-12);
  EXPECT_LT(length(north.outline[2] - world(6, 8, 3)), 1e-12);
  // The west wall (model x = 0, facing +x): 15 x 5, u along +y.
  const SensorGrid& west = scene.grids.at(1);
  EXPECT_EQ(west.columns, 15);
  EXPECT_EQ(west.rows, 5);
  ASSERT_EQ(west.points.size(), 75u);
  EXPECT_LT(length(west.points[0].position - world(0, 0.5, 0.5)), 1e-12);
  EXPECT_LT(length(west.points[16].position - world(0, 1.0, 1.0)), 1e-12);
  for (const SensorPoint& q : west.points) EXPECT_LT(length(q.normal - Vec3{c, s, 0}), 1e-12);
}

TEST(SurfaceGrid, WindowWallLeavesOutTheWindowAndItsInset) {
  // The office window: x = 1..5, z = 0.9..2.4 in the south wall (y = 0).
  Project p = office_project();
  GridSpec g = wall_grid("front", RoomSurface::South);
  g.inset_m = 0;
  g.spacing_m = 1;
  p.sensors.grids = {g};
  SceneDescription scene = build_scene_description(p);
  // Lattice u (= -x from x = 6): x = 6, 5, ..., 0; z = 0..3. Left out: the window's closed
  // rectangle, i.e. x in [1, 5] and z in {1, 2}: 5 x 2 = 10 of 28.
  const SensorGrid& front = scene.grids.at(0);
  EXPECT_EQ(front.points.size(), 18u);
  EXPECT_EQ(front.columns, 0);  // not a full lattice any more
  EXPECT_EQ(front.rows, 0);
  for (const SensorPoint& q : front.points) {
    EXPECT_EQ(q.normal, Vec3(0, 1, 0));
    const bool in_window = q.position.x >= 1 && q.position.x <= 5 && q.position.z >= 0.9 && q.position.z <= 2.4;
    EXPECT_FALSE(in_window) << q.position.x << " " << q.position.z;
  }
  EXPECT_EQ(front.points[0].position, Vec3(6, 0, 0));  // the south wall's u runs toward -x
  EXPECT_EQ(front.points[1].position, Vec3(5, 0, 0));
  // Inset 0.5, spacing 0.5: x = 5.5..0.5, z = 0.5..2.5; kept: the columns x = 0.5 and 5.5
  // (0.5 m from the jambs) and nothing else (z = 0.5 and 2.5 are only 0.4 and 0.1 m away).
  g.inset_m = 0.5;
  g.spacing_m = 0.5;
  p.sensors.grids = {g};
  scene = build_scene_description(p);
  ASSERT_EQ(scene.grids.at(0).points.size(), 10u);
  for (const SensorPoint& q : scene.grids.at(0).points)
    EXPECT_TRUE(std::fabs(q.position.x - 0.5) < 1e-12 || std::fabs(q.position.x - 5.5) < 1e-12) << q.position.x;
}

TEST(SurfaceGrid, RectangleFacesUCrossVWithPerpendicularInset) {
  Project p = office_project();
  GridSpec g;
  g.name = "facade";
  g.location = {"office.yaml", 40, 5};
  g.rectangle = GridSpec::Rectangle{{2, 1, 0.5}, {0, 2, 0}, {0, 0, 1}};  // u x v = +x
  g.spacing_m = 0.5;
  g.inset_m = 0.25;
  g.offset_m = 0.1;
  p.sensors.grids = {g};
  SceneDescription scene = build_scene_description(p);
  const SensorGrid& r = scene.grids.at(0);
  EXPECT_EQ(r.columns, 4);  // 2 - 0.5 = 1.5 -> 4
  EXPECT_EQ(r.rows, 2);     // 1 - 0.5 = 0.5 -> 2
  ASSERT_EQ(r.points.size(), 8u);
  EXPECT_LT(length(r.points[0].position - Vec3{2.1, 1.25, 0.75}), 1e-12);
  EXPECT_LT(length(r.points[3].position - Vec3{2.1, 2.75, 0.75}), 1e-12);
  EXPECT_LT(length(r.points[4].position - Vec3{2.1, 1.25, 1.25}), 1e-12);
  for (const SensorPoint& q : r.points) EXPECT_EQ(q.normal, Vec3(1, 0, 0));
  EXPECT_LT(length(r.outline[2] - Vec3{2.1, 3, 1.5}), 1e-12);
  // Swapping u and v turns the sensors around (and the order: v outer).
  std::swap(p.sensors.grids[0].rectangle->u, p.sensors.grids[0].rectangle->v);
  scene = build_scene_description(p);
  EXPECT_EQ(scene.grids.at(0).columns, 2);
  EXPECT_EQ(scene.grids.at(0).points[0].normal, Vec3(-1, 0, 0));
  EXPECT_LT(length(scene.grids.at(0).points[0].position - Vec3{1.9, 1.25, 0.75}), 1e-12);

  // A parallelogram with 60 degrees between u and v: the inset is measured perpendicular
  // to the edges, i.e. inset / sin(60) along them; every sensor keeps it from all 4 edges.
  const Vec3 u{3, 0, 0}, v{1, std::sqrt(3.0), 0};  // |v| = 2, 60 degrees
  g.rectangle = GridSpec::Rectangle{{0.5, 0.5, 1}, u, v};
  g.inset_m = 0.2;
  g.offset_m = 0;
  g.spacing_m = 0.4;
  p.sensors.grids = {g};
  scene = build_scene_description(p);
  const SensorGrid& par = scene.grids.at(0);
  ASSERT_FALSE(par.points.empty());
  const double along = 0.2 / std::sin(Pi / 3);
  EXPECT_EQ(par.columns, static_cast<int>(std::floor((3 - 2 * along) / 0.4 + 1e-9)) + 1);
  EXPECT_EQ(par.rows, static_cast<int>(std::floor((2 - 2 * along) / 0.4 + 1e-9)) + 1);
  const Vec3 o{0.5, 0.5, 1};
  for (const SensorPoint& q : par.points) {
    EXPECT_EQ(q.normal, Vec3(0, 0, 1));
    // Distances to the 4 edge lines in the plane.
    const Vec3 d = q.position - o;
    const double to_u_edge = length(cross(d, normalize(u)));           // line through o along u
    const double to_v_edge = length(cross(d, normalize(v)));           // line through o along v
    const double to_far_u = length(cross(d - v, normalize(u)));        // line through o + v along u
    const double to_far_v = length(cross(d - u, normalize(v)));        // line through o + u along v
    for (double dist : {to_u_edge, to_v_edge, to_far_u, to_far_v}) EXPECT_GE(dist, 0.2 - 1e-9);
  }
}

// ---- input errors, through the loader (and the scene builder for geometric ones) --------

const std::string Head =
    "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"
    "outputs: {annual_illuminance: false, metrics: false}\n"
    "materials: {w: {type: lambertian, reflectance: 0.5}}\n"
    "geometry:\n"
    "  rooms:\n"
    "    - {name: office, size: [6, 8, 3], materials: {floor: w, ceiling: w, walls: w}}\n"
    "sensors:\n"
    "  grids:\n";  // the grid of each case is line 9

std::vector<std::string> errors_of(const std::string& grid) {
  const std::string path = "walls.yaml";
  return test::located_errors(
      [&] { build_scene_description(load_project_from_string(Head + grid, path)); }, path);
}

TEST(SurfaceGrid, InputErrorsAreLocatedAtTheirKey) {
  using V = std::vector<std::string>;
  EXPECT_EQ(errors_of("    - {name: g, wall: {room: office, wall: nort}}\n"),
            V{"9:44: unknown value 'nort' for 'wall': expected one of south, north, east, west, floor, ceiling "
              "(did you mean 'north'?)"});
  EXPECT_EQ(errors_of("    - {name: g, wall: {room: ofice, wall: north}}\n"),
            V{"9:30: unknown room 'ofice' (did you mean 'office'?)"});
  EXPECT_EQ(errors_of("    - {name: g, room: office, wall: {room: office, wall: north}}\n"),
            V{"9:37: grid takes one of 'room', 'polygon', 'wall' and 'rectangle', got 'room' and 'wall'"});
  EXPECT_EQ(errors_of("    - {name: g, spacing: 0.5}\n"),
            V{"9:7: grid needs one of 'room', 'polygon', 'wall' and 'rectangle'"});
  EXPECT_EQ(errors_of("    - {name: g, wall: {room: office, wall: north}, height: 1}\n"),
            V{"9:60: 'height' applies to room and polygon grids only (a wall grid's sensors face into the "
              "room; 'offset' moves them off the surface)"});
  EXPECT_EQ(errors_of("    - {name: g, room: office, offset: 0.1}\n"),
            V{"9:39: 'offset' applies to wall and rectangle grids only (room and polygon grids are placed by "
              "'height')"});
  EXPECT_EQ(errors_of("    - {name: g, rectangle: {origin: [0, 0, 0], u: [0, 0, 0], v: [0, 0, 1]}}\n"),
            V{"9:51: grid 'g': edge vector 'u' is zero"});
  EXPECT_EQ(errors_of("    - {name: g, rectangle: {origin: [0, 0, 0], u: [1, 0, 0], v: [-2, 0, 0]}}\n"),
            V{"9:65: grid 'g': edge vectors 'u' and 'v' are parallel: they span no rectangle"});
  EXPECT_EQ(errors_of("    - {name: g, rectangle: {origin: [0, .inf, 0], u: [1, 0, 0], v: [0, 0, 1]}}\n"),
            V{"9:41: expected a number in 'origin', got '.inf'"});
  EXPECT_EQ(errors_of("    - {name: g, rectangle: {u: [1, 0, 0], v: [0, 0, 1]}}\n"),
            V{"9:28: missing required key 'origin' in grid rectangle"});
  EXPECT_EQ(errors_of("    - {name: g, wall: {room: office, wall: north}, inset: 1.6}\n"),
            V{"9:59: grid 'g' has no points: the inset (1.6 m) leaves nothing of the north wall of room "
              "'office' (6 x 3 m)"});
  EXPECT_EQ(errors_of("    - {name: g, wall: {room: office, wall: north}, offset: -0.1}\n"),
            V{"9:60: 'offset' must be >= 0, got -0.1"});
}

// The backward-reference sensor files in tests/data/reference/ (README there) are the wall
// grids of projects/wall_sensors: if the grids change, the references must be made again.
TEST(SurfaceGrid, ReferenceSensorFilesAreTheExampleWallGrids) {
  const std::string source = DAYPHOTON_SOURCE_DIR;
  const SceneDescription scene =
      build_scene_description(load_project(source + "/projects/wall_sensors/project.yaml"));
  for (const std::string name : {"back_wall", "west_wall"}) {
    const SensorGrid* grid = nullptr;
    for (const SensorGrid& g : scene.grids)
      if (g.name == name) grid = &g;
    ASSERT_NE(grid, nullptr) << name;
    Diagnostics diag;
    const std::vector<SensorPoint> pts = read_pts(source + "/tests/data/reference/office_" + name + ".pts", diag);
    ASSERT_FALSE(diag.has_errors()) << diag.format();
    ASSERT_EQ(pts.size(), grid->points.size()) << name;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      EXPECT_LT(length(pts[i].position - grid->points[i].position), 1e-9) << name << " " << i;
      EXPECT_LT(length(pts[i].normal - grid->points[i].normal), 1e-12) << name << " " << i;
    }
  }
}

// The example's mid-air point set holds exactly the work-plane grid's 165 positions, in order.
TEST(SurfaceGrid, ExamplePointSetIsTheWorkPlaneGrid) {
  const SceneDescription scene = build_scene_description(
      load_project(std::string(DAYPHOTON_SOURCE_DIR) + "/projects/wall_sensors/project.yaml"));
  const SensorGrid *grid = nullptr, *points = nullptr;
  for (const SensorGrid& g : scene.grids) {
    if (g.name == "workplane") grid = &g;
    if (g.name == "workplane_points") points = &g;
  }
  ASSERT_TRUE(grid && points);
  EXPECT_TRUE(grid->planar);
  EXPECT_FALSE(points->planar);
  ASSERT_EQ(grid->points.size(), 165u);
  ASSERT_EQ(points->points.size(), 165u);
  for (std::size_t i = 0; i < 165; ++i) {
    EXPECT_LT(length(points->points[i].position - grid->points[i].position), 1e-12) << i;
    EXPECT_EQ(points->points[i].normal, Vec3(0, 0, 1)) << i;
  }
}

}  // namespace
}  // namespace dayphoton::project
