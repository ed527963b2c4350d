// Geometry stage (build_scene_description) on Project structs built in C++:
// - the reference office (tests/data/radiance/office.rad) gives floor 48 m^2 (normal +z),
//   ceiling 48 m^2 (normal -z), 2 (6 x 3) + 2 (8 x 3) - 6 = 78 m^2 of wall, a 6 m^2 glazing
//   port with normal +y (into the room), and the window/floor/ceiling polygons of office.rad;
// - triangulations keep every surface's normal and area;
// - boxes have outward normals and rotate about their origin corner;
// - the north rotation (north_rotation.h) maps model directions to true north;
// - invalid geometry gives located errors (window outside its wall, overlapping windows,
//   zero room size, unknown material, non-planar / degenerate / NaN polygons).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "dayphoton/core/polygon.h"
#include "dayphoton/project/north_rotation.h"
#include "dayphoton/project/project.h"
#include "geometry_fixture.h"

namespace dayphoton::project {
namespace {

using testing::build_error;
using testing::office_project;

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

const Surface* find_surface(const SceneDescription& scene, const std::string& name) {
  for (const Surface& s : scene.surfaces)
    if (s.name == name) return &s;
  return nullptr;
}

void expect_vec_near(const Vec3& a, const Vec3& b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(Geometry, OfficeSurfaceAreasAndNormals) {
  const SceneDescription scene = build_scene_description(office_project());
  ASSERT_EQ(scene.materials.size(), 4u);
  double wall_m2 = 0, window_m2 = 0;
  int ports = 0;
  const Vec3 centre{3, 4, 1.5};
  for (const Surface& s : scene.surfaces) {
    ASSERT_GE(s.material, 0) << s.name;
    const Vec3 n = polygon_normal(s.vertices);
    // Every surface of the room faces into it.
    EXPECT_GT(dot(n, centre - polygon_centroid(s.vertices)), 0) << s.name;
    if (starts_with(s.name, "office.wall_")) {
      wall_m2 += polygon_area_m2(s.vertices);
      EXPECT_FALSE(s.port);
      EXPECT_EQ(scene.materials[s.material].name, "wall_mat");
    }
    if (s.port) {
      ++ports;
      window_m2 += polygon_area_m2(s.vertices);
    }
  }
  EXPECT_NEAR(wall_m2, 2 * (6 * 3) + 2 * (8 * 3) - 6.0, 1e-12);
  EXPECT_NEAR(window_m2, 6.0, 1e-12);
  EXPECT_EQ(ports, 1);

  const Surface* floor = find_surface(scene, "office.floor");
  const Surface* ceiling = find_surface(scene, "office.ceiling");
  const Surface* window = find_surface(scene, "office.window");
  ASSERT_TRUE(floor && ceiling && window);
  EXPECT_NEAR(polygon_area_m2(floor->vertices), 48, 1e-12);
  EXPECT_NEAR(polygon_area_m2(ceiling->vertices), 48, 1e-12);
  EXPECT_EQ(polygon_normal(floor->vertices), Vec3(0, 0, 1));
  EXPECT_EQ(polygon_normal(ceiling->vertices), Vec3(0, 0, -1));
  expect_vec_near(polygon_normal(window->vertices), {0, 1, 0}, 1e-15);
  EXPECT_TRUE(window->port);
  EXPECT_EQ(scene.materials[window->material].name, "glass_mat");
  EXPECT_EQ(window->location.line, 20);  // errors about the glazing point at the window entry
  // The uncut walls are single rectangles; the south wall is split around the opening.
  EXPECT_NE(find_surface(scene, "office.wall_north"), nullptr);
  EXPECT_EQ(find_surface(scene, "office.wall_south"), nullptr);
  EXPECT_NE(find_surface(scene, "office.wall_south.1"), nullptr);
}

/// Polygons of a RADIANCE scene file: name -> vertices.
std::map<std::string, std::vector<Vec3>> read_rad_polygons(const std::string& path) {
  std::ifstream in(path);
  std::map<std::string, std::vector<Vec3>> out;
  std::string line, text;
  while (std::getline(in, line)) {
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    text += line + "\n";
  }
  std::istringstream words(text);
  std::string modifier, type, name;
  while (words >> modifier >> type >> name) {
    int n_strings = 0, n_ints = 0, n_reals = 0;
    words >> n_strings;
    for (int i = 0; i < n_strings; ++i) words >> modifier;
    words >> n_ints >> n_reals;
    std::vector<Vec3> v(static_cast<std::size_t>(n_reals / 3));
    for (auto& p : v) words >> p.x >> p.y >> p.z;
    if (type == "polygon") out[name] = v;
  }
  return out;
}

TEST(Geometry, OfficeMatchesRadianceReferenceScene) {
  const std::string path = std::string(DAYPHOTON_TEST_DATA_DIR) + "/radiance/office.rad";
  ASSERT_TRUE(std::ifstream(path)) << "reference scene not found: " << path;
  const auto ref = read_rad_polygons(path);
  ASSERT_EQ(ref.count("window"), 1u);
  const SceneDescription scene = build_scene_description(office_project());
  // Same vertices in the same order (so the same winding) as RADIANCE's scene.
  for (const auto& [ours, theirs] : std::map<std::string, std::string>{
           {"office.floor", "floor"}, {"office.ceiling", "ceiling"}, {"office.window", "window"},
           {"office.wall_north", "wall_north"}, {"office.wall_east", "wall_east"},
           {"office.wall_west", "wall_west"}}) {
    const Surface* s = find_surface(scene, ours);
    ASSERT_NE(s, nullptr) << ours;
    ASSERT_EQ(ref.count(theirs), 1u) << theirs;
    const auto& v = ref.at(theirs);
    ASSERT_EQ(s->vertices.size(), v.size()) << ours;
    // Same polygon up to the starting vertex: compare normal, area and vertex set.
    expect_vec_near(polygon_normal(s->vertices), polygon_normal(v), 1e-12);
    EXPECT_NEAR(polygon_area_m2(s->vertices), polygon_area_m2(v), 1e-12) << ours;
    for (const Vec3& p : v) {
      bool found = false;
      for (const Vec3& q : s->vertices) found = found || length(p - q) < 1e-12;
      EXPECT_TRUE(found) << ours << " lacks a vertex of " << theirs;
    }
  }
  // The reference's south wall pieces cover the same area with the same normal.
  double ref_south = 0, our_south = 0;
  for (const auto& [name, v] : ref)
    if (starts_with(name, "wall_south")) {
      ref_south += polygon_area_m2(v);
      expect_vec_near(polygon_normal(v), {0, 1, 0}, 1e-12);
    }
  for (const Surface& s : scene.surfaces)
    if (starts_with(s.name, "office.wall_south")) {
      our_south += polygon_area_m2(s.vertices);
      expect_vec_near(polygon_normal(s.vertices), {0, 1, 0}, 1e-12);
    }
  EXPECT_NEAR(our_south, ref_south, 1e-12);
}

TEST(Geometry, TriangulationsKeepNormalsAndAreas) {
  Project p = office_project();
  // Add windows on every wall (one wall with two) so that many pieces are generated.
  WindowSpec w = p.geometry.rooms[0].windows[0];
  w.name = "east_a"; w.wall = Wall::East; w.width_m = 1; w.height_m = 1; w.sill_m = 1; w.offset_m = 1;
  p.geometry.rooms[0].windows.push_back(w);
  w.name = "east_b"; w.offset_m = 5; w.sill_m = 0.5; w.height_m = 2;
  p.geometry.rooms[0].windows.push_back(w);
  w.name = "west"; w.wall = Wall::West; w.offset_m.reset(); w.sill_m = 0; w.height_m = 3; w.width_m = 2;
  p.geometry.rooms[0].windows.push_back(w);
  w.name = "north"; w.wall = Wall::North; w.sill_m = 1; w.height_m = 1; w.width_m = 6;
  p.geometry.rooms[0].windows.push_back(w);
  const SceneDescription scene = build_scene_description(p);
  double wall_m2 = 0, glass_m2 = 0;
  for (const Surface& s : scene.surfaces) {
    const Vec3 n = polygon_normal(s.vertices);
    const auto tris = triangulate_polygon(s.vertices);
    double sum = 0;
    for (const auto& t : tris) {
      const Vec3 c = cross(s.vertices[t[1]] - s.vertices[t[0]], s.vertices[t[2]] - s.vertices[t[0]]);
      sum += 0.5 * length(c);
      expect_vec_near(normalize(c), n, 1e-12);
    }
    EXPECT_NEAR(sum, polygon_area_m2(s.vertices), 1e-12) << s.name;
    EXPECT_GT(dot(n, Vec3{3, 4, 1.5} - polygon_centroid(s.vertices)), 0) << s.name;
    if (starts_with(s.name, "office.wall_")) wall_m2 += sum;
    if (s.port) glass_m2 += sum;
  }
  const double glass_expected = 6.0 + 1 + 2 + 2 * 3 + 6 * 1;
  EXPECT_NEAR(glass_m2, glass_expected, 1e-12);
  EXPECT_NEAR(wall_m2, 2 * 18 + 2 * 24 - glass_expected, 1e-12);
}

TEST(Geometry, BoxHasOutwardNormalsAndRotatesAboutItsOrigin) {
  Project p;
  p.materials = {testing::lambertian("grey", 0.5)};
  BoxSpec box;
  box.name = "shelf";
  box.origin = {1, 2, 3};
  box.size_m = {2, 0.5, 0.1};
  box.rotation_deg = 90;
  box.material = "grey";
  p.geometry.boxes.push_back(box);
  const SceneDescription scene = build_scene_description(p);
  ASSERT_EQ(scene.surfaces.size(), 6u);
  Vec3 centre{0, 0, 0};
  for (const Surface& s : scene.surfaces) centre += polygon_centroid(s.vertices) / 6.0;
  // Rotated by +90 degrees (counter-clockwise) about the origin corner: the box's x extent
  // now runs along +y, its y extent along -x.
  expect_vec_near(centre, {1 - 0.25, 2 + 1, 3 + 0.05}, 1e-12);
  double area = 0;
  for (const Surface& s : scene.surfaces) {
    EXPECT_GT(dot(polygon_normal(s.vertices), polygon_centroid(s.vertices) - centre), 0) << s.name;
    area += polygon_area_m2(s.vertices);
  }
  EXPECT_NEAR(area, 2 * (2 * 0.5 + 2 * 0.1 + 0.5 * 0.1), 1e-12);
  const Surface* bottom = find_surface(scene, "shelf.bottom");
  ASSERT_NE(bottom, nullptr);
  expect_vec_near(polygon_normal(bottom->vertices), {0, 0, -1}, 1e-12);
}

TEST(Geometry, NorthRotationConvention) {
  // north = 90: true north is along model +X, so model +X becomes world +Y (north) and
  // model +Y becomes world -X (west): a counter-clockwise quarter turn.
  EXPECT_EQ(model_to_world({1, 0, 0}, 90), Vec3(0, 1, 0));
  EXPECT_EQ(model_to_world({0, 1, 0}, 90), Vec3(-1, 0, 0));
  EXPECT_EQ(model_to_world({0, 1, 0}, 0), Vec3(0, 1, 0));
  EXPECT_EQ(model_to_world({1, 2, 3}, -90), Vec3(2, -1, 3));
  EXPECT_EQ(model_to_world({1, 2, 3}, 450), model_to_world({1, 2, 3}, 90));
  // For any angle, the model direction that is `north` degrees clockwise from model +Y
  // (i.e. (sin a, cos a)) is true north in the world.
  for (double north : {-170.0, -30.0, 12.5, 30.0, 135.0, 271.0}) {
    const double a = north * 3.14159265358979323846 / 180;
    expect_vec_near(model_to_world({std::sin(a), std::cos(a), 0}, north), {0, 1, 0}, 1e-15);
    const Vec3 v{0.3, -1.7, 2.0};
    expect_vec_near(world_to_model(model_to_world(v, north), north), v, 1e-14);
  }
}

TEST(Geometry, SceneIsRotatedToTrueNorth) {
  Project p = office_project();
  p.site.north_deg = 90;
  PointsSpec pts;
  pts.name = "facade";
  pts.points = {{{3, 0.1, 1.5}, {0, 2, 0}}};  // facing +y (into the room) in the model
  p.sensors.points.push_back(pts);
  const SceneDescription scene = build_scene_description(p);
  const Surface* floor = find_surface(scene, "office.floor");
  ASSERT_NE(floor, nullptr);
  EXPECT_EQ(floor->vertices[1], Vec3(0, 6, 0));  // model (6,0,0)
  EXPECT_EQ(polygon_normal(floor->vertices), Vec3(0, 0, 1));
  const Surface* window = find_surface(scene, "office.window");
  ASSERT_NE(window, nullptr);
  // The window faces model +y into the room = world west; the wall itself faces east.
  expect_vec_near(polygon_normal(window->vertices), {-1, 0, 0}, 1e-15);
  ASSERT_EQ(scene.grids.size(), 2u);
  const SensorGrid& grid = scene.grids[0];
  expect_vec_near(grid.points.front().position, {-0.5, 0.5, 0.8}, 1e-12);
  expect_vec_near(grid.points.back().position, {-7.5, 5.5, 0.8}, 1e-12);
  expect_vec_near(grid.points.front().normal, {0, 0, 1}, 0);
  EXPECT_TRUE(grid.planar);
  EXPECT_NEAR(grid.plane_height_m, 0.8, 1e-15);
  ASSERT_EQ(grid.outline.size(), 4u);
  EXPECT_EQ(grid.outline[1], Vec3(0, 6, 0.8));
  const SensorGrid& facade = scene.grids[1];
  ASSERT_EQ(facade.points.size(), 1u);
  expect_vec_near(facade.points[0].position, {-0.1, 3, 1.5}, 1e-12);
  expect_vec_near(facade.points[0].normal, {-1, 0, 0}, 1e-15);  // normalised and rotated
}

TEST(Geometry, RotationIncludesTheMeridianConvergence) {
  // The builder rotates by Site::rotation_to_true_north_deg(), which combines north_deg with
  // the UTM meridian convergence (sign convention in project.h / site_geodesy.h).
  Project p = office_project();
  p.site.north_deg = 20;
  p.site.meridian_convergence_deg = 1.5;
  const double total = p.site.rotation_to_true_north_deg();
  ASSERT_NE(total, 20.0);
  const SceneDescription scene = build_scene_description(p);
  const Surface* floor = find_surface(scene, "office.floor");
  ASSERT_NE(floor, nullptr);
  expect_vec_near(floor->vertices[2], model_to_world({6, 8, 0}, total), 1e-12);
  expect_vec_near(scene.grids[0].points[0].position, model_to_world({0.5, 0.5, 0.8}, total), 1e-12);
}

TEST(Geometry, WindowOutsideItsWallIsALocatedError) {
  Project p = office_project();
  p.geometry.rooms[0].windows[0].width_m = 7;  // wider than the 6 m south wall
  const std::string text = build_error(p);
  EXPECT_NE(text.find("office.yaml:20:9: error: window 'window' of room 'office' does not fit in the south wall"),
            std::string::npos)
      << text;
  p = office_project();
  p.geometry.rooms[0].windows[0].sill_m = 2;  // head at 3.5 m > 3 m
  EXPECT_NE(build_error(p).find("does not fit"), std::string::npos);
  p = office_project();
  p.geometry.rooms[0].windows[0].offset_m = 2.5;  // 2.5 + 4 > 6
  EXPECT_NE(build_error(p).find("does not fit"), std::string::npos);
  // A window filling its whole wall is fine: no wall pieces are left.
  p = office_project();
  auto& w = p.geometry.rooms[0].windows[0];
  w.width_m = 6; w.sill_m = 0; w.height_m = 3;
  const SceneDescription scene = build_scene_description(p);
  for (const Surface& s : scene.surfaces) EXPECT_FALSE(starts_with(s.name, "office.wall_south")) << s.name;
}

TEST(Geometry, OverlappingWindowsAreALocatedError) {
  Project p = office_project();
  WindowSpec second = p.geometry.rooms[0].windows[0];
  second.name = "second";
  second.width_m = 1;
  second.offset_m = 4.5;  // 4.5..5.5 overlaps 1..5
  second.location = {"office.yaml", 26, 9};
  p.geometry.rooms[0].windows.push_back(second);
  const std::string text = build_error(p);
  EXPECT_NE(text.find("office.yaml:26:9: error: window 'second' of room 'office' overlaps window 'window' "
                      "in the south wall (defined at office.yaml:20:9)"),
            std::string::npos)
      << text;
  // Touching windows (sharing a jamb) are allowed.
  p.geometry.rooms[0].windows[1].offset_m = 5;
  EXPECT_EQ(build_error(p), "");
}

TEST(Geometry, BadRoomsAndMaterialsAreLocatedErrors) {
  Project p = office_project();
  p.geometry.rooms[0].size_m.y = 0;
  EXPECT_NE(build_error(p).find("office.yaml:10:5: error: room 'office': every size must be positive"),
            std::string::npos);
  p = office_project();
  p.geometry.rooms[0].floor_material = "flor_mat";
  EXPECT_NE(build_error(p).find("office.yaml:10:5: error: unknown material 'flor_mat' for the floor of "
                                "room 'office' (did you mean 'floor_mat'?)"),
            std::string::npos);
  p = office_project();
  p.geometry.rooms[0].windows[0].material = "unobtainium";
  const std::string text = build_error(p);
  EXPECT_NE(text.find("office.yaml:20:9: error: unknown material 'unobtainium'"), std::string::npos) << text;
  EXPECT_EQ(text.find("did you mean"), std::string::npos) << text;
}

TEST(Geometry, FreePolygonsAreValidated) {
  Project p;
  p.materials = {testing::lambertian("grey", 0.5)};
  PolygonSpec poly;
  poly.name = "shelf";
  poly.material = "grey";
  poly.vertices = {{0, 0, 1}, {2, 0, 1}, {2, 1, 1}, {0, 1, 1}};
  poly.location = {"p.yaml", 5, 7};
  p.geometry.polygons.push_back(poly);
  SceneDescription scene = build_scene_description(p);
  ASSERT_EQ(scene.surfaces.size(), 1u);
  EXPECT_EQ(scene.surfaces[0].vertices, poly.vertices);

  // Planarity tolerance: 1e-3 m x max(1, size); the 2 m polygon tolerates 2 mm. Lifting a
  // corner by h gives a deviation of about h/4 (see polygon_test).
  p.geometry.polygons[0].vertices[2].z = 1 + 0.007;  // ~1.75 mm
  EXPECT_EQ(build_error(p), "");
  p.geometry.polygons[0].vertices[2].z = 1 + 0.009;  // ~2.25 mm
  EXPECT_NE(build_error(p).find("p.yaml:5:7: error: surface 'shelf' is not planar"), std::string::npos);

  p.geometry.polygons[0].vertices = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  EXPECT_NE(build_error(p).find("p.yaml:5:7: error: surface 'shelf' is degenerate (zero area)"),
            std::string::npos);
  p.geometry.polygons[0].vertices = {{0, 0, 0}, {1, 0, 0}, {1, std::nan(""), 0}};
  EXPECT_NE(build_error(p).find("vertex 3 is not finite"), std::string::npos);
  p.geometry.polygons[0].vertices = {{0, 0, 0}, {1, 0, 0}, {1, HUGE_VAL, 0}};
  EXPECT_NE(build_error(p).find("vertex 3 is not finite"), std::string::npos);
  p.geometry.polygons[0].vertices = {{0, 0, 0}, {2, 1, 0}, {2, 0, 0}, {0, 2, 0}};  // bow-tie
  EXPECT_NE(build_error(p).find("cannot be triangulated"), std::string::npos);
}

TEST(Geometry, AllErrorsAreReportedTogether) {
  Project p = office_project();
  p.geometry.rooms[0].windows[0].width_m = 9;
  p.geometry.rooms[0].ceiling_material = "nope";
  p.sensors.grids[0].room = "offise";
  try {
    build_scene_description(p);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.diagnostics().size(), 3u) << e.what();
    EXPECT_NE(std::string(e.what()).find("unknown room 'offise' (did you mean 'office'?)"), std::string::npos);
  }
}

}  // namespace
}  // namespace dayphoton::project
