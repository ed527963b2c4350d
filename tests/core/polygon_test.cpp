// Tests for core/polygon.h: Newell normal and area against closed forms (rectangles, regular
// n-gons: area = n/2 r^2 sin(2 pi/n)), planarity deviation, ear clipping on convex, concave
// and degenerate inputs (triangle normals equal the polygon normal, areas add up),
// point-in-polygon and distance to the boundary.
#include "dayphoton/core/polygon.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "dayphoton/core/units.h"

namespace dayphoton {
namespace {

double triangle_area(const std::vector<Vec3>& v, const std::array<std::uint32_t, 3>& t) {
  return 0.5 * length(cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]));
}

Vec3 triangle_normal(const std::vector<Vec3>& v, const std::array<std::uint32_t, 3>& t) {
  return normalize(cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]));
}

/// Checks shared by every triangulation test: triangles keep the winding (their geometric
/// normal equals the polygon normal), have positive area, and cover the polygon's area.
void expect_valid_triangulation(const std::vector<Vec3>& v) {
  const auto tris = triangulate_polygon(v);
  const Vec3 n = polygon_normal(v);
  double sum = 0;
  for (const auto& t : tris) {
    for (std::uint32_t i : t) ASSERT_LT(i, v.size());
    const double a = triangle_area(v, t);
    EXPECT_GT(a, 0);
    sum += a;
    const Vec3 tn = triangle_normal(v, t);
    EXPECT_NEAR(dot(tn, n), 1.0, 1e-9);
  }
  EXPECT_NEAR(sum, polygon_area_m2(v), 1e-9 * std::max(1.0, sum));
}

TEST(Polygon, RectangleNormalAndAreaFollowWinding) {
  // Office floor (refdata/scenes/office.rad): counter-clockwise from above, normal +z.
  const std::vector<Vec3> floor{{0, 0, 0}, {6, 0, 0}, {6, 8, 0}, {0, 8, 0}};
  EXPECT_EQ(polygon_normal(floor), Vec3(0, 0, 1));
  EXPECT_DOUBLE_EQ(polygon_area_m2(floor), 48.0);
  // Office window: normal +y (into the room).
  const std::vector<Vec3> window{{1, 0, 0.9}, {1, 0, 2.4}, {5, 0, 2.4}, {5, 0, 0.9}};
  const Vec3 n = polygon_normal(window);
  EXPECT_NEAR(n.x, 0, 1e-15);
  EXPECT_NEAR(n.y, 1, 1e-15);
  EXPECT_NEAR(n.z, 0, 1e-15);
  EXPECT_NEAR(polygon_area_m2(window), 6.0, 1e-12);
  // Reversed winding flips the normal, keeps the area.
  const std::vector<Vec3> reversed(floor.rbegin(), floor.rend());
  EXPECT_EQ(polygon_normal(reversed), Vec3(0, 0, -1));
  EXPECT_DOUBLE_EQ(polygon_area_m2(reversed), 48.0);
}

TEST(Polygon, RegularPolygonAreaMatchesClosedFormFarFromOrigin) {
  // Tilted regular 7-gon of radius 2 centred 1 km away: area = n/2 r^2 sin(2 pi / n).
  const int n = 7;
  const double r = 2.0;
  const Vec3 c{1000, -2000, 50};
  const Vec3 axis_u = normalize(Vec3{1, 1, 0});
  const Vec3 axis_v = normalize(Vec3{-1, 1, 1});
  const Vec3 expected_normal = normalize(cross(axis_u, axis_v));
  std::vector<Vec3> v;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * Pi * i / n;
    v.push_back(c + axis_u * (r * std::cos(a)) + axis_v * (r * std::sin(a)));
  }
  EXPECT_NEAR(polygon_area_m2(v), 0.5 * n * r * r * std::sin(2 * Pi / n), 1e-9);
  EXPECT_NEAR(dot(polygon_normal(v), expected_normal), 1.0, 1e-12);
  EXPECT_LT(planarity_deviation_m(v), 1e-9);
  const Vec3 centroid = polygon_centroid(v);
  EXPECT_NEAR(length(centroid - c), 0, 1e-9);
  expect_valid_triangulation(v);
}

TEST(Polygon, DegenerateInputsGiveZeroNormal) {
  EXPECT_EQ(polygon_normal({}), Vec3(0, 0, 0));
  EXPECT_EQ(polygon_normal({{0, 0, 0}, {1, 0, 0}}), Vec3(0, 0, 0));
  // Collinear points: no area.
  const std::vector<Vec3> line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
  EXPECT_EQ(polygon_normal(line), Vec3(0, 0, 0));
  EXPECT_NEAR(polygon_area_m2(line), 0, 1e-15);
  EXPECT_THROW(triangulate_polygon(line), std::invalid_argument);
  EXPECT_THROW(triangulate_polygon({{0, 0, 0}, {1, 0, 0}}), std::invalid_argument);
  const double nan = std::nan("");
  EXPECT_THROW(triangulate_polygon({{0, 0, 0}, {1, 0, 0}, {nan, 1, 0}}), std::invalid_argument);
}

TEST(Polygon, PlanarityDeviationOfATwistedQuad) {
  // Lift one corner of a unit square by h. For a quad the Newell vector is the cross
  // product of the diagonals, (1,1,h) x (-1,1,0) = (-h,-h,2); through the centroid
  // (0.5, 0.5, h/4) every corner then deviates by (h/2) / |(-h,-h,2)|.
  const double h = 0.01;
  const std::vector<Vec3> quad{{0, 0, 0}, {1, 0, 0}, {1, 1, h}, {0, 1, 0}};
  EXPECT_NEAR(planarity_deviation_m(quad), 0.5 * h / std::sqrt(4 + 2 * h * h), 1e-15);
  EXPECT_DOUBLE_EQ(planarity_deviation_m({{0, 0, 0}, {1, 0, 5}, {0, 1, 0}}), 0.0);
}

TEST(Polygon, TriangulatesConcavePolygonKeepingWinding) {
  // L-shape (area 3) in the x-z plane, wound both ways.
  std::vector<Vec3> l{{0, 0, 0}, {2, 0, 0}, {2, 0, 1}, {1, 0, 1}, {1, 0, 2}, {0, 0, 2}};
  EXPECT_NEAR(polygon_area_m2(l), 3.0, 1e-12);
  expect_valid_triangulation(l);
  EXPECT_EQ(triangulate_polygon(l).size(), 4u);
  std::vector<Vec3> reversed(l.rbegin(), l.rend());
  expect_valid_triangulation(reversed);

  // Comb with deep notches: many reflex vertices.
  std::vector<Vec3> comb;
  comb.push_back({0, 0, 0});
  for (int i = 0; i < 5; ++i) {
    comb.push_back({2.0 * i + 1.0, 0, 0});
    comb.push_back({2.0 * i + 1.0, 0.9, 0});
    comb.push_back({2.0 * i + 2.0, 0.9, 0});
    comb.push_back({2.0 * i + 2.0, 0, 0});
  }
  comb.push_back({11, 0, 0});
  comb.push_back({11, 1, 0});
  comb.push_back({0, 1, 0});
  // Area: 11 x 1 minus 5 notches of 1 x 0.9.
  EXPECT_NEAR(polygon_area_m2(comb), 11 - 5 * 0.9, 1e-12);
  // Both windings.
  std::vector<Vec3> comb_rev(comb.rbegin(), comb.rend());
  expect_valid_triangulation(comb);
  expect_valid_triangulation(comb_rev);
}

TEST(Polygon, TriangulationToleratesDuplicateAndCollinearVertices) {
  // Office wall strip with a repeated vertex, the closing vertex repeated, and a vertex in
  // the middle of an edge (as when two windows share a jamb line).
  const std::vector<Vec3> v{{0, 0, 0}, {0, 0, 0.9}, {0, 0, 0.9}, {3, 0, 0.9},
                            {6, 0, 0.9}, {6, 0, 0},  {3, 0, 0},   {0, 0, 0}};
  const auto tris = triangulate_polygon(v);
  EXPECT_EQ(tris.size(), 2u);
  expect_valid_triangulation(v);
}

TEST(Polygon, SelfIntersectingPolygonIsRejected) {
  // Bow-tie with unequal lobes.
  const std::vector<Vec3> bow{{0, 0, 0}, {2, 1, 0}, {2, 0, 0}, {0, 2, 0}};
  EXPECT_THROW(triangulate_polygon(bow), std::invalid_argument);
}

TEST(Polygon, RandomStarPolygonsTriangulate) {
  // Star-shaped polygons (random radius per angle) are simple; fixed seed.
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> radius(0.2, 2.0);
  for (int trial = 0; trial < 50; ++trial) {
    const int n = 3 + trial % 20;
    std::vector<Vec3> v;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * Pi * i / n;
      const double r = radius(rng);
      v.push_back({r * std::cos(a), 3.0, r * std::sin(a)});  // in the x-z plane
    }
    SCOPED_TRACE(trial);
    expect_valid_triangulation(v);
    EXPECT_EQ(triangulate_polygon(v).size(), static_cast<std::size_t>(n - 2));
  }
}

TEST(Polygon, LargeConcavePolygonTriangulates) {
  // 2000-vertex star (radii alternating 1 and 0.6): every other corner is reflex.
  // Area closed form: n triangles of sides r1, r2 at angle 2 pi / n: n/2 r1 r2 sin(2 pi/n).
  const int n = 2000;
  std::vector<Vec3> v;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * Pi * i / n, r = i % 2 ? 0.6 : 1.0;
    v.push_back({r * std::cos(a), r * std::sin(a), 0});
  }
  EXPECT_NEAR(polygon_area_m2(v), 0.5 * n * 0.6 * std::sin(2 * Pi / n), 1e-12);
  const auto tris = triangulate_polygon(v);
  EXPECT_EQ(tris.size(), static_cast<std::size_t>(n - 2));
  expect_valid_triangulation(v);
}

TEST(Polygon, ContainsAndDistanceToBoundary) {
  const std::vector<Vec3> l{{0, 0, 1}, {2, 0, 1}, {2, 1, 1}, {1, 1, 1}, {1, 2, 1}, {0, 2, 1}};
  EXPECT_TRUE(polygon_contains(l, {0.5, 0.5, 1}));
  EXPECT_TRUE(polygon_contains(l, {1.5, 0.5, 1}));
  EXPECT_TRUE(polygon_contains(l, {0.5, 1.5, 1}));
  EXPECT_FALSE(polygon_contains(l, {1.5, 1.5, 1}));  // the missing quadrant
  EXPECT_FALSE(polygon_contains(l, {-0.1, 0.5, 1}));
  EXPECT_FALSE(polygon_contains(l, {3, 3, 1}));
  // Same answer for the reversed winding.
  const std::vector<Vec3> rev(l.rbegin(), l.rend());
  EXPECT_TRUE(polygon_contains(rev, {0.5, 1.5, 1}));
  EXPECT_FALSE(polygon_contains(rev, {1.5, 1.5, 1}));

  EXPECT_NEAR(distance_to_polygon_boundary_m(l, {0.5, 0.5, 1}), 0.5, 1e-12);
  EXPECT_NEAR(distance_to_polygon_boundary_m(l, {0.2, 0.5, 1}), 0.2, 1e-12);
  // Outside, in the missing quadrant: nearest edge is x = 1.
  EXPECT_NEAR(distance_to_polygon_boundary_m(l, {1.3, 1.4, 1}), 0.3, 1e-12);
  EXPECT_NEAR(distance_to_polygon_boundary_m(l, {1.5, 0.5, 1}), 0.5, 1e-12);
}

}  // namespace
}  // namespace dayphoton
