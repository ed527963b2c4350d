// Scene: analytic hit distances and normals, front-face logic, tmin/tmax, occluded vs
// intersect agreement, batched queries, watertightness of closed rooms (random rays and
// rays aimed exactly at edges and vertices), self-intersection avoidance, ports and grids.
#include "dayphoton/engine/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <thread>
#include <type_traits>

#include "dayphoton/core/units.h"
#include "test_scenes.h"

namespace dayphoton::engine {
namespace {

using test::box_room;
using test::office_room;
using test::single_square;

Vec3 random_unit_vector(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double z = 1.0 - 2.0 * u(rng);
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = 2.0 * Pi * u(rng);
  return {r * std::cos(phi), r * std::sin(phi), z};
}

/// Closed-form first hit of a ray from inside the box [0,size] (local frame): the smallest
/// positive plane distance, and the index of the second smallest to tell near-edge hits.
struct BoxHit {
  double t, t_second;
  Vec3 normal;
};
BoxHit analytic_box_hit(const Vec3& o, const Vec3& d, const Vec3& size) {
  std::array<std::pair<double, Vec3>, 3> planes;
  for (int k = 0; k < 3; ++k) {
    Vec3 n{0, 0, 0};
    double t;
    if (d[k] == 0) {
      t = HUGE_VAL;  // parallel to both planes of this axis
    } else if (d[k] > 0) {
      t = (size[k] - o[k]) / d[k];
      n[k] = -1;
    } else {
      t = (0.0 - o[k]) / d[k];
      n[k] = 1;
    }
    planes[static_cast<std::size_t>(k)] = {t, n};
  }
  std::sort(planes.begin(), planes.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  return {planes[0].first, planes[1].first, planes[0].second};
}

TEST(Scene, IsMovableNotCopyable) {
  static_assert(!std::is_copy_constructible_v<Scene>);
  static_assert(!std::is_copy_assignable_v<Scene>);
  static_assert(std::is_nothrow_move_constructible_v<Scene>);
  Scene a = Scene::build(box_room());
  Scene b = std::move(a);
  EXPECT_TRUE(b.intersect({{0.5, 0.5, 0.5}, {0, 0, -1}}).has_value());
  Scene c = Scene::build(single_square());
  c = std::move(b);
  EXPECT_EQ(c.triangle_count(), 12u);
}

TEST(Scene, CountsBoundsAndEpsilon) {
  const Scene office = Scene::build(office_room());
  EXPECT_EQ(office.triangle_count(), 20u);  // 10 quadrilaterals
  EXPECT_EQ(office.bounds().lower, Vec3(0, 0, 0));
  EXPECT_EQ(office.bounds().upper, Vec3(6, 8, 3));
  EXPECT_DOUBLE_EQ(office.ray_epsilon_m(), 1e-5 * 8.0);
  for (std::uint32_t i = 0; i < office.triangle_count(); ++i) {
    const SceneTriangle& t = office.triangle(i);
    EXPECT_NEAR(length(t.normal), 1.0, 1e-12);
    // Every triangle keeps its polygon's (inward) normal: it points to the room centre.
    EXPECT_GT(dot(t.normal, Vec3(3, 4, 1.5) - t.vertices[0]), 0) << "triangle " << i;
  }
}

TEST(Scene, AxisRaysHitAllSixFacesAtAnalyticDistance) {
  const Vec3 size{2, 3, 1.5};
  const Scene scene = Scene::build(box_room(size));
  const Vec3 o{0.7, 1.1, 0.4};
  const std::array<Vec3, 6> dirs{{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
  for (const Vec3& d : dirs) {
    const auto hit = scene.intersect({o, d});
    ASSERT_TRUE(hit.has_value());
    const BoxHit expected = analytic_box_hit(o, d, size);
    EXPECT_NEAR(hit->t, expected.t, 1e-6 * expected.t);
    EXPECT_EQ(hit->normal, expected.normal);
    EXPECT_EQ(hit->normal, -d);
    EXPECT_TRUE(hit->front_face);
    EXPECT_EQ(hit->material, 0);
    EXPECT_EQ(hit->port, -1);
    EXPECT_NEAR(length(hit->position - (o + d * expected.t)), 0, 1e-6);
  }
}

// Random rays in a plain box and in the same box rotated by 30 degrees and moved to
// (100, 200, 10) m: t to 1e-6 relative (the brief's tolerance; the double-precision
// refinement gives ~1e-12), the normal of the face hit, barycentrics that rebuild the hit.
TEST(Scene, RandomRaysMatchAnalyticBoxDistances) {
  const Vec3 size{6, 8, 3};
  for (const auto& [rotation_rad, offset] :
       {std::pair<double, Vec3>{0.0, {0, 0, 0}}, {deg_to_rad(30.0), {100, 200, 10}}}) {
    const Scene scene = Scene::build(box_room(size, rotation_rad, offset));
    const double c = std::cos(rotation_rad), s = std::sin(rotation_rad);
    auto to_world = [&](const Vec3& v) { return Vec3{c * v.x - s * v.y, s * v.x + c * v.y, v.z}; };
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int checked_normals = 0;
    for (int i = 0; i < 20000; ++i) {
      const Vec3 local_o{u(rng) * size.x, u(rng) * size.y, u(rng) * size.z};
      const Vec3 local_d = random_unit_vector(rng);
      const BoxHit expected = analytic_box_hit(local_o, local_d, size);
      const auto hit = scene.intersect({to_world(local_o) + offset, to_world(local_d)});
      ASSERT_TRUE(hit.has_value()) << "ray " << i << " escaped";
      ASSERT_NEAR(hit->t, expected.t, 1e-6 * expected.t) << "ray " << i;
      EXPECT_TRUE(hit->front_face);
      // Near an edge (two planes within float error) either face is a correct answer.
      if (expected.t_second - expected.t > 1e-5 * expected.t) {
        ASSERT_NEAR(length(hit->normal - to_world(expected.normal)), 0, 1e-12) << "ray " << i;
        ++checked_normals;
      }
      const SceneTriangle& tri = scene.triangle(hit->primitive);
      const Vec3 rebuilt = tri.vertices[0] * (1 - hit->u - hit->v) + tri.vertices[1] * hit->u +
                           tri.vertices[2] * hit->v;
      ASSERT_NEAR(length(rebuilt - hit->position), 0, 1e-5 * (1 + length(offset)));
    }
    EXPECT_GT(checked_normals, 19900);
  }
}

TEST(Scene, FrontFaceFollowsTheWinding) {
  const Scene scene = Scene::build(single_square());
  const auto from_above = scene.intersect({{0.2, 0.3, 2}, {0, 0, -1}});
  ASSERT_TRUE(from_above.has_value());
  EXPECT_TRUE(from_above->front_face);
  EXPECT_EQ(from_above->normal, Vec3(0, 0, 1));
  EXPECT_DOUBLE_EQ(from_above->t, 2.0);
  EXPECT_EQ(from_above->position, Vec3(0.2, 0.3, 0));
  EXPECT_EQ(from_above->surface, 0);

  const auto from_below = scene.intersect({{0.2, 0.3, -1}, normalize(Vec3(0.1, 0, 1))});
  ASSERT_TRUE(from_below.has_value());
  EXPECT_FALSE(from_below->front_face);
  EXPECT_EQ(from_below->normal, Vec3(0, 0, 1));  // the normal does not flip with the ray
  EXPECT_NEAR(from_below->t, std::sqrt(1.01) / 1.0, 1e-12);

  EXPECT_FALSE(scene.intersect({{1.5, 0, 1}, {0, 0, -1}}).has_value());  // beside the square
  EXPECT_FALSE(scene.intersect({{0, 0, 1}, {0, 0, 1}}).has_value());    // away from it
  EXPECT_FALSE(scene.occluded({{0, 0, 1}, {0, 0, 1}}));
}

TEST(Scene, RespectsTminAndTmax) {
  const Scene scene = Scene::build(single_square());
  const Vec3 o{0, 0, 1}, d{0, 0, -1};
  EXPECT_TRUE(scene.intersect({o, d, 0, 1.001}).has_value());
  EXPECT_FALSE(scene.intersect({o, d, 0, 0.999}).has_value());
  EXPECT_FALSE(scene.intersect({o, d, 1.001, 5}).has_value());
  EXPECT_TRUE(scene.occluded({o, d, 0, 1.001}));
  EXPECT_FALSE(scene.occluded({o, d, 0, 0.999}));
  EXPECT_FALSE(scene.occluded({o, d, 1.001, 5}));
}

// Thousands of random rays with random finite or infinite tmax in the office: occluded()
// agrees with intersect(), and both agree with the closest hit distance. Rays whose tmax is
// within 1e-5 m of the hit (single-precision ambiguity) are not judged.
TEST(Scene, OccludedAgreesWithIntersect) {
  const Scene scene = Scene::build(office_room());
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int judged = 0, hits = 0;
  for (int i = 0; i < 20000; ++i) {
    // Origins inside and outside the room.
    const Vec3 o{-3 + 12 * u(rng), -4 + 16 * u(rng), -1.5 + 6 * u(rng)};
    const Vec3 d = random_unit_vector(rng);
    const auto full = scene.intersect({o, d});
    ASSERT_EQ(full.has_value(), scene.occluded({o, d})) << "ray " << i;
    const double tmax = u(rng) < 0.2 ? HUGE_VAL : 10 * u(rng);
    if (full && std::abs(full->t - tmax) < 1e-5) continue;
    const Ray ray{o, d, 0, tmax};
    const auto limited = scene.intersect(ray);
    const bool expected = full && full->t <= tmax;
    ASSERT_EQ(limited.has_value(), expected) << "ray " << i;
    ASSERT_EQ(scene.occluded(ray), expected) << "ray " << i;
    if (limited) {
      ASSERT_EQ(limited->primitive, full->primitive);
      ++hits;
    }
    ++judged;
  }
  EXPECT_GT(judged, 19900);
  EXPECT_GT(hits, 1000);
  EXPECT_LT(hits, judged - 1000);
}

TEST(Scene, BatchedQueriesEqualSingleQueries) {
  const Scene scene = Scene::build(office_room());
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Ray> rays(5000);
  for (auto& r : rays)
    r = {{-1 + 8 * u(rng), -1 + 10 * u(rng), -1 + 5 * u(rng)}, random_unit_vector(rng), 0,
         u(rng) < 0.5 ? HUGE_VAL : 6 * u(rng)};
  std::vector<std::optional<Hit>> hits(rays.size());
  std::unique_ptr<bool[]> occluded(new bool[rays.size()]);
  scene.intersect_batch(rays.data(), rays.size(), hits.data());
  scene.occluded_batch(rays.data(), rays.size(), occluded.get());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const auto single = scene.intersect(rays[i]);
    ASSERT_EQ(hits[i].has_value(), single.has_value());
    ASSERT_EQ(occluded[i], scene.occluded(rays[i]));
    if (single) {
      ASSERT_EQ(hits[i]->t, single->t);
      ASSERT_EQ(hits[i]->primitive, single->primitive);
    }
  }
}

// 1e5 rays from inside a closed room must all hit it: a third in random directions, a third
// aimed exactly at the 8 corners, a third at random points on the 12 edges (where two
// triangles, or the two triangles of one quad along its diagonal, meet).
void expect_watertight(const Scene& scene, const std::vector<Vec3>& corners,
                       const std::vector<std::pair<int, int>>& edges, const Vec3& lo,
                       const Vec3& hi, const std::function<Vec3(const Vec3&)>& to_world,
                       std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int escaped = 0, not_occluded = 0;
  constexpr int N = 100000;
  for (int i = 0; i < N; ++i) {
    const Vec3 local_o{lo.x + (hi.x - lo.x) * u(rng), lo.y + (hi.y - lo.y) * u(rng),
                       lo.z + (hi.z - lo.z) * u(rng)};
    const Vec3 o = to_world(local_o);
    Vec3 target;
    switch (i % 3) {
      case 0: target = o + random_unit_vector(rng); break;
      case 1: target = corners[static_cast<std::size_t>(i / 3) % corners.size()]; break;
      default: {
        const auto& e = edges[static_cast<std::size_t>(i / 3) % edges.size()];
        const double w = u(rng);
        target = corners[static_cast<std::size_t>(e.first)] * (1 - w) +
                 corners[static_cast<std::size_t>(e.second)] * w;
      }
    }
    const Ray ray{o, normalize(target - o)};
    if (!scene.intersect(ray)) ++escaped;
    if (!scene.occluded(ray)) ++not_occluded;
  }
  EXPECT_EQ(escaped, 0) << "of " << N << " rays";
  EXPECT_EQ(not_occluded, 0) << "of " << N << " rays";
}

TEST(Scene, ClosedBoxIsWatertight) {
  const std::vector<std::pair<int, int>> edges{{0, 1}, {1, 3}, {3, 2}, {2, 0}, {4, 5}, {5, 7},
                                               {7, 6}, {6, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7},
                                               // face diagonals, where quads are split
                                               {0, 3}, {1, 2}, {4, 7}, {5, 6}, {0, 5}, {1, 4},
                                               {2, 7}, {3, 6}, {0, 6}, {2, 4}, {1, 7}, {3, 5}};
  for (const auto& [rotation_rad, offset] :
       {std::pair<double, Vec3>{0.0, {0, 0, 0}}, {deg_to_rad(37.0), {100, 200, 10}}}) {
    const Vec3 size{1, 1, 1};
    const Scene scene = Scene::build(box_room(size, rotation_rad, offset));
    const double c = std::cos(rotation_rad), s = std::sin(rotation_rad);
    const Vec3 shift = offset;  // a lambda cannot capture a structured binding in C++17 (clang)
    auto to_world = [&](const Vec3& v) { return Vec3{c * v.x - s * v.y, s * v.x + c * v.y, v.z} + shift; };
    std::vector<Vec3> corners;
    for (int k = 0; k < 8; ++k) corners.push_back(to_world({double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)}));
    expect_watertight(scene, corners, edges, {0, 0, 0}, size, to_world, 99);
  }
}

// The office's south wall has T-junctions (the sill's top edge is shared by the jambs and
// the window); the room with its glazing must still be closed.
TEST(Scene, OfficeWithWindowIsClosed) {
  const Scene scene = Scene::build(office_room());
  std::vector<Vec3> corners;
  for (const Vec3& p : {Vec3{0, 0, 0}, Vec3{6, 0, 0}, Vec3{0, 8, 0}, Vec3{6, 8, 0}, Vec3{0, 0, 3},
                        Vec3{6, 0, 3}, Vec3{0, 8, 3}, Vec3{6, 8, 3},
                        // window corners and the T-junction points on the south wall
                        Vec3{1, 0, 0.9}, Vec3{5, 0, 0.9}, Vec3{1, 0, 2.4}, Vec3{5, 0, 2.4},
                        Vec3{0, 0, 0.9}, Vec3{6, 0, 0.9}, Vec3{0, 0, 2.4}, Vec3{6, 0, 2.4}})
    corners.push_back(p);
  const std::vector<std::pair<int, int>> edges{{0, 1}, {0, 2}, {1, 3}, {2, 3}, {4, 5}, {4, 6},
                                               {5, 7}, {6, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7},
                                               {8, 9}, {10, 11}, {8, 10}, {9, 11}, {12, 13},
                                               {14, 15}, {8, 11}, {0, 13}};
  expect_watertight(scene, corners, edges, {0, 0, 0}, {6, 8, 3}, [](const Vec3& v) { return v; },
                    4242);
}

// Self-intersection avoidance: paths of diffuse-like bounces in the office. From each hit
// the next ray leaves into the hemisphere the ray arrived from, starting at
// offset_ray_origin(...) with tmin = 0. It must hit something (the room is closed), and not
// the plane it starts on (all surfaces are planar: a ray leaving a plane cannot return).
TEST(Scene, OffsetOriginsAvoidSelfIntersection) {
  const Scene scene = Scene::build(office_room());
  std::mt19937_64 rng(31337);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int bounces = 0;
  for (int path = 0; path < 5000; ++path) {
    Ray ray{{0.1 + 5.8 * u(rng), 0.1 + 7.8 * u(rng), 0.1 + 2.8 * u(rng)}, random_unit_vector(rng)};
    auto hit = scene.intersect(ray);
    ASSERT_TRUE(hit.has_value());
    for (int b = 0; b < 20; ++b, ++bounces) {
      const Vec3 facing = hit->front_face ? hit->normal : -hit->normal;
      Vec3 d = random_unit_vector(rng);
      if (dot(d, facing) < 0) d = -d;
      const Vec3 origin = scene.offset_ray_origin(hit->position, hit->normal, d);
      ASSERT_NEAR(dot(origin - hit->position, facing), scene.ray_epsilon_m(), 1e-15);
      const auto next = scene.intersect({origin, d, 0.0});
      ASSERT_TRUE(next.has_value()) << "path " << path << " bounce " << b;
      ASSERT_GT(std::abs(dot(next->position - hit->position, hit->normal)),
                0.5 * scene.ray_epsilon_m())
          << "self-intersection at path " << path << " bounce " << b;
      hit = next;
    }
  }
  EXPECT_EQ(bounces, 100000);
}

TEST(Scene, PortsAreGeometryAndKeptApart) {
  const Scene scene = Scene::build(office_room());
  ASSERT_EQ(scene.ports().size(), 1u);
  const Port& window = scene.ports()[0];
  EXPECT_EQ(window.surface, test::OfficeWindowSurface);
  EXPECT_EQ(window.name, "window");
  EXPECT_NEAR(window.area_m2, 6.0, 1e-12);  // office.rad: glass area 6.0 m^2
  EXPECT_NEAR(length(window.normal - Vec3(0, 1, 0)), 0, 1e-12);
  EXPECT_NEAR(length(window.centroid - Vec3(3, 0, 1.65)), 0, 1e-12);
  EXPECT_TRUE(scene.is_port(test::OfficeWindowSurface));
  EXPECT_FALSE(scene.is_port(0));
  EXPECT_FALSE(scene.is_port(-1));
  EXPECT_FALSE(scene.is_port(99));

  // From inside toward the window: a port hit on glass, from its front (inner) side.
  const auto glazing = scene.intersect({{3, 4, 1.5}, {0, -1, 0}});
  ASSERT_TRUE(glazing.has_value());
  EXPECT_EQ(glazing->surface, test::OfficeWindowSurface);
  EXPECT_EQ(glazing->port, 0);
  EXPECT_EQ(glazing->material, 3);
  EXPECT_TRUE(glazing->front_face);
  EXPECT_DOUBLE_EQ(glazing->t, 4.0);
  // From outside through the window: the same port, from its back.
  const auto outside = scene.intersect({{3, -2, 1.5}, {0, 1, 0}});
  ASSERT_TRUE(outside.has_value());
  EXPECT_EQ(outside->port, 0);
  EXPECT_FALSE(outside->front_face);
  // The wall below the window is not a port.
  const auto sill = scene.intersect({{3, 4, 0.5}, {0, -1, 0}});
  ASSERT_TRUE(sill.has_value());
  EXPECT_EQ(sill->port, -1);
  EXPECT_EQ(scene.description().surfaces[static_cast<std::size_t>(sill->surface)].name,
            "wall_south_sill");
}

TEST(Scene, SensorGridsAreNotGeometry) {
  SceneDescription d = single_square();
  SensorGrid grid;
  grid.name = "workplane";
  grid.planar = true;
  grid.plane_height_m = 0.8;
  grid.points = {{{0, 0, 0.8}, {0, 0, 1}}, {{0.5, 0, 0.8}, {0, 0, 1}}};
  grid.outline = {{-1, -1, 0.8}, {1, -1, 0.8}, {1, 1, 0.8}, {-1, 1, 0.8}};
  d.grids.push_back(grid);
  const Scene scene = Scene::build(d);
  EXPECT_EQ(scene.triangle_count(), 2u);
  ASSERT_EQ(scene.sensor_grids().size(), 1u);
  EXPECT_EQ(scene.sensor_grids()[0].name, "workplane");
  EXPECT_EQ(scene.sensor_grids()[0].points.size(), 2u);
  const auto hit = scene.intersect({{0, 0, 2}, {0, 0, -1}});
  ASSERT_TRUE(hit.has_value());
  EXPECT_DOUBLE_EQ(hit->t, 2.0);  // passes the grid plane at 1.2 m untouched
}

// A built scene is queried from several threads at once (as the photon tracer will do):
// every thread sees exactly the single-threaded answers.
TEST(Scene, ConcurrentQueriesGiveTheSameAnswers) {
  const Scene scene = Scene::build(office_room());
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Ray> rays(20000);
  for (auto& r : rays) r = {{6 * u(rng), 8 * u(rng), 3 * u(rng)}, random_unit_vector(rng)};
  std::vector<std::uint32_t> serial(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) serial[i] = scene.intersect(rays[i])->primitive;
  std::vector<std::vector<std::uint32_t>> results(4, std::vector<std::uint32_t>(rays.size()));
  std::vector<std::thread> threads;
  for (std::size_t k = 0; k < results.size(); ++k)
    threads.emplace_back([&, k] {
      for (std::size_t i = 0; i < rays.size(); ++i) {
        const auto hit = scene.intersect(rays[i]);
        results[k][i] = hit && scene.occluded(rays[i]) ? hit->primitive : 0xFFFFFFFFu;
      }
    });
  for (auto& t : threads) t.join();
  for (const auto& r : results) EXPECT_EQ(r, serial);
}

TEST(Scene, EmptySceneHitsNothing) {
  const Scene scene = Scene::build(SceneDescription{});
  EXPECT_EQ(scene.triangle_count(), 0u);
  EXPECT_FALSE(scene.intersect({{0, 0, 0}, {0, 0, 1}}).has_value());
  EXPECT_FALSE(scene.occluded({{0, 0, 0}, {0, 0, 1}}));
  EXPECT_TRUE(scene.ports().empty());
}

TEST(OffsetRayOrigin, MovesToTheSideOfTheDirection) {
  const Vec3 p{1, 2, 3}, n{0, 0, 1};
  EXPECT_EQ(offset_ray_origin(p, n, {0.3, 0, 0.5}, 0.01), Vec3(1, 2, 3.01));
  EXPECT_EQ(offset_ray_origin(p, n, {0.3, 0, -0.5}, 0.01), Vec3(1, 2, 2.99));
}

}  // namespace
}  // namespace dayphoton::engine
