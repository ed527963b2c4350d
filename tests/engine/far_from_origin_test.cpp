// A model far from its coordinates' origin (site plans, survey and UTM coordinates): Embree
// intersects in single precision, so Scene holds its vertices and rays relative to a local
// origin (scene.h, "Precision"), and photon positions, floats in the description's
// coordinates, are the reason geometry beyond PhotonCoordinateLimit_m of the description's
// origin is refused (photon.h; a project's description is held around its own centre,
// project/local_origin.h, tested in tests/study/survey_coordinates_test.cpp).
//
// The sky component of a CIE 171:2006-style black room (reflectances 0, an unglazed 4 x 1.5 m
// opening) is a function of the geometry relative to the sensor only: the same room and
// sensors moved 10 km give the same direct coefficients as at the origin, up to the rounding
// of the moved coordinates in double precision (1e-12 m). Before the local origin the room
// 10 km out read 1.5 % (near the opening) to 12.5 % (at the back) low, and at 30 km its
// sensors saw the sky through the walls.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/engine/direct_component.h"
#include "dayphoton/engine/photon.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/sky/patch_basis.h"
#include "system_scenes.h"

namespace dayphoton::engine {
namespace {

using namespace test;

struct Room {
  SceneDescription description;
  std::vector<Material> materials;
};

Room black_room_at(const Vec3& offset) {
  Room r;
  const int black = add_spec(r.description, grey("black", MaterialType::Lambertian, 0.0));
  const int hole = add_spec(r.description, material_of("opening", MaterialType::Opening));
  add_room(r.description, {6, 8, 3}, black, black, black, SouthWindow{1, 5, 0.9, 2.4, hole});
  for (Surface& s : r.description.surfaces)
    for (Vec3& p : s.vertices) p = p + offset;
  for (const MaterialSpec& m : r.description.materials) r.materials.push_back(Material::from_spec(m));
  return r;
}

std::vector<SensorPoint> sensors_at(const Vec3& offset) {
  std::vector<SensorPoint> s{{{3, 0.5, 0.8}, {0, 0, 1}},  {{3, 2, 0.8}, {0, 0, 1}},
                             {{3, 5, 0.8}, {0, 0, 1}},    {{3, 7.5, 0.8}, {0, 0, 1}},
                             {{0.5, 7.5, 0.8}, {0, 0, 1}}, {{3, 4, 1.2}, {0, -1, 0}},
                             {{3, 7.99, 1.5}, {0, -1, 0}}, {{5.99, 3, 1.5}, {-1, 0, 0}}};
  for (SensorPoint& p : s) p.position = p.position + offset;
  return s;
}

/// Sum over the sky bins (bin 0, the ground, left out) of each sensor's direct coefficients.
std::vector<double> sky_components(const Vec3& offset) {
  const Room room = black_room_at(offset);
  const Scene scene = Scene::build(room.description);
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  const std::vector<SensorPoint> sensors = sensors_at(offset);
  DirectOptions options;
  options.samples_per_source = 16;
  options.seed = 7;
  const std::vector<Vec3> c = direct_coefficients(scene, room.materials, sources, sensors, options);
  std::vector<double> sky(sensors.size(), 0.0);
  for (std::size_t s = 0; s < sensors.size(); ++s)
    for (std::size_t p = 1; p < sources.size(); ++p) sky[s] += c[s * sources.size() + p].y;
  return sky;
}

TEST(FarFromOrigin, ASkyComponentDoesNotDependOnWhereTheRoomIsDrawn) {
  const std::vector<double> at_origin = sky_components({0, 0, 0});
  for (const Vec3& offset : {Vec3{1e3, 1e3, 0}, Vec3{1e4, 2e4, 10}, Vec3{-9.5e4, 9e4, 250}}) {
    const std::vector<double> moved = sky_components(offset);
    ASSERT_EQ(moved.size(), at_origin.size());
    for (std::size_t s = 0; s < moved.size(); ++s) {
      ASSERT_GT(at_origin[s], 0.0);
      // The same directions (same seed), the same geometry relative to each sensor: only the
      // rounding of the moved vertices and sensors (double) and Embree's local floats differ.
      EXPECT_NEAR(moved[s] / at_origin[s], 1.0, 1e-4)
          << "sensor " << s << " with the room moved by (" << offset.x << ", " << offset.y << ", "
          << offset.z << ") m";
    }
  }
}

TEST(FarFromOrigin, TheRayEpsilonFollowsTheSizeOfTheModelNotItsPlace) {
  // 1e-5 x the largest coordinate relative to the local origin: at (0, 0, 0) the room's far
  // corner, 8 m; moved, its half-diagonal's largest component about the rounded centre, 4 m.
  const Scene at_origin = Scene::build(black_room_at({0, 0, 0}).description);
  const Scene moved = Scene::build(black_room_at({3e4, -7e4, 40}).description);
  EXPECT_DOUBLE_EQ(at_origin.ray_epsilon_m(), 1e-5 * 8.0);
  EXPECT_DOUBLE_EQ(moved.ray_epsilon_m(), 1e-5 * 4.0);
}

TEST(FarFromOrigin, GeometryBeyondThePhotonCoordinateLimitIsALocatedError) {
  // A UTM position (easting 500 km, northing 4200 km): photon positions would be rounded by
  // up to 0.25 m there.
  SceneDescription d = black_room_at({5e5, 4.2e6, 30}).description;
  d.surfaces[0].location = SourceLocation{"model.hbjson", 12, 5};
  try {
    (void)Scene::build(d);
    FAIL() << "geometry 4.2e6 m from the origin was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("model.hbjson:12:5"), std::string::npos) << what;
    EXPECT_NE(what.find("'floor'"), std::string::npos) << what;
    EXPECT_NE(what.find("from (0, 0, 0), the point the model is held around"), std::string::npos) << what;
    EXPECT_NE(what.find("leave out the distant geometry"), std::string::npos) << what;
  }
  // Just inside the limit it builds.
  EXPECT_NO_THROW((void)Scene::build(black_room_at({PhotonCoordinateLimit_m - 10, 0, 0}).description));
}

}  // namespace
}  // namespace dayphoton::engine
