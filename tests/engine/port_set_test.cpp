// PortSet sampling is uniform by area (STYLE.md A.10 (b), pbrt's Chi2Test pattern):
// chi-square tests over grids of equal-area cells on a rectangular port (the office window)
// and on a tilted concave L-shaped port, plus moment tests against closed-form centroids and
// second moments, pdf = 1/area, and no sample off the port.
//
// Chi-square critical values: Wilson-Hilferty approximation of the chi-square quantile,
// chi2_{1-alpha}(k) ~ k (1 - 2/(9k) + z_{1-alpha} sqrt(2/(9k)))^3, alpha = 1e-3
// (z = 3.0902); with fixed seeds the outcome is deterministic, alpha is the probability that
// a correct sampler would have failed for a random seed.
#include "dayphoton/engine/port_set.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "dayphoton/core/polygon.h"
#include "dayphoton/engine/scene.h"
#include "test_scenes.h"

namespace dayphoton::engine {
namespace {

constexpr double ZAlpha1e3 = 3.0902;

double chi2_critical(int dof, double z) {
  const double k = dof;
  const double a = 2.0 / (9.0 * k);
  return k * std::pow(1.0 - a + z * std::sqrt(a), 3);
}

double chi2_statistic(const std::vector<double>& observed, double expected_per_cell) {
  double chi2 = 0;
  for (double o : observed) chi2 += (o - expected_per_cell) * (o - expected_per_cell) / expected_per_cell;
  return chi2;
}

TEST(PortSet, ChiSquareCriticalValueMatchesTables) {
  // Published quantiles (e.g. NIST/SEMATECH e-Handbook, table 1.3.6.7.4): chi2_0.999(10) =
  // 29.588, chi2_0.999(50) = 86.661. Wilson-Hilferty overestimates these upper quantiles
  // slightly (0.6 % at k = 10, 0.1 % at k = 50), which makes the tests below marginally
  // conservative.
  EXPECT_NEAR(chi2_critical(10, ZAlpha1e3), 29.588, 0.01 * 29.588);
  EXPECT_NEAR(chi2_critical(50, ZAlpha1e3), 86.661, 0.01 * 86.661);
  EXPECT_GE(chi2_critical(10, ZAlpha1e3), 29.588);
}

TEST(PortSet, OfficeWindowSamplesAreUniform) {
  const Scene scene = Scene::build(test::office_room());
  ASSERT_EQ(scene.ports().size(), 1u);
  const PortSet& ports = scene.ports();
  // Window: x 1..5, y = 0, z 0.9..2.4; 8 x 6 cells of 0.5 m x 0.25 m.
  constexpr int Nx = 8, Nz = 6, N = 240000;
  std::vector<double> counts(Nx * Nz, 0.0);
  std::mt19937_64 rng(20240601);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < N; ++i) {
    const PortSample s = ports.sample(0, u(rng), u(rng));
    ASSERT_DOUBLE_EQ(s.pdf_per_m2, 1.0 / 6.0);
    ASSERT_EQ(s.normal, ports[0].normal);
    ASSERT_NEAR(s.position.y, 0.0, 1e-15);
    ASSERT_GE(s.position.x, 1.0 - 1e-12);
    ASSERT_LE(s.position.x, 5.0 + 1e-12);
    ASSERT_GE(s.position.z, 0.9 - 1e-12);
    ASSERT_LE(s.position.z, 2.4 + 1e-12);
    const int ix = std::min(Nx - 1, static_cast<int>((s.position.x - 1.0) / 0.5));
    const int iz = std::min(Nz - 1, static_cast<int>((s.position.z - 0.9) / 0.25));
    counts[static_cast<std::size_t>(iz * Nx + ix)] += 1;
  }
  const double chi2 = chi2_statistic(counts, double(N) / (Nx * Nz));
  EXPECT_LT(chi2, chi2_critical(Nx * Nz - 1, ZAlpha1e3)) << "chi2 = " << chi2;
}

// A concave L-shaped port in a tilted plane: local coordinates (a, b) on orthonormal axes
// e1, e2 through O; the L is [0,2]x[0,1] + [0,1]x[1,2] (area 3 m^2, centroid (5/6, 5/6),
// E[a^2] = E[b^2] = 1 by integration). 4 x 4 cells of 0.5 m: 12 inside, 4 outside.
TEST(PortSet, ConcaveTiltedPortSamplesAreUniform) {
  const Vec3 O{1, 2, 3};
  const Vec3 e1 = normalize(Vec3(1, 1, 0));
  const Vec3 e2 = normalize(Vec3(-1, 1, 1));
  auto P = [&](double a, double b) { return O + e1 * a + e2 * b; };
  SceneDescription d;
  test::add_material(d, "glass", MaterialType::Glass, 0);
  test::add_surface(d, "L", 0, {P(0, 0), P(2, 0), P(2, 1), P(1, 1), P(1, 2), P(0, 2)}, true);
  const Scene scene = Scene::build(d);
  const Port& port = scene.ports()[0];
  EXPECT_NEAR(port.area_m2, 3.0, 1e-12);
  EXPECT_NEAR(length(port.normal - cross(e1, e2)), 0, 1e-12);
  EXPECT_NEAR(length(port.centroid - P(5.0 / 6.0, 5.0 / 6.0)), 0, 1e-12);
  EXPECT_EQ(port.triangles.size(), 4u);

  constexpr int N = 120000;
  std::vector<double> inside(12, 0.0);
  int outside = 0;
  double sum_a = 0, sum_b = 0, sum_a2 = 0, sum_b2 = 0, sum_a4 = 0, sum_b4 = 0;
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < N; ++i) {
    const PortSample s = scene.ports().sample(0, u(rng), u(rng));
    ASSERT_DOUBLE_EQ(s.pdf_per_m2, 1.0 / 3.0);
    const Vec3 r = s.position - O;
    ASSERT_NEAR(dot(r, port.normal), 0, 1e-12);  // in the plane
    const double a = dot(r, e1), b = dot(r, e2);
    ASSERT_TRUE(polygon_contains({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}},
                                 {a, b, 0}) ||
                distance_to_polygon_boundary_m(
                    {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}}, {a, b, 0}) < 1e-12)
        << a << ' ' << b;
    const int ia = std::clamp(static_cast<int>(a / 0.5), 0, 3);
    const int ib = std::clamp(static_cast<int>(b / 0.5), 0, 3);
    if (ia >= 2 && ib >= 2) {
      ++outside;
    } else {
      // Number the 12 inside cells: rows ib 0,1 have 4 cells, rows 2,3 have 2.
      const int cell = ib < 2 ? ib * 4 + ia : 8 + (ib - 2) * 2 + ia;
      inside[static_cast<std::size_t>(cell)] += 1;
    }
    sum_a += a;
    sum_b += b;
    sum_a2 += a * a;
    sum_b2 += b * b;
    sum_a4 += a * a * a * a;
    sum_b4 += b * b * b * b;
  }
  EXPECT_EQ(outside, 0);
  const double chi2 = chi2_statistic(inside, N / 12.0);
  EXPECT_LT(chi2, chi2_critical(11, ZAlpha1e3)) << "chi2 = " << chi2;

  // Moments: |sample mean - exact| < 4 standard errors (two-sided p ~ 6e-5 each).
  auto expect_mean = [&](double sum, double sum_sq, double exact, const char* what) {
    const double mean = sum / N;
    const double se = std::sqrt((sum_sq / N - mean * mean) / N);
    EXPECT_LT(std::abs(mean - exact), 4 * se) << what << ": " << mean << " vs " << exact;
  };
  expect_mean(sum_a, sum_a2, 5.0 / 6.0, "E[a]");
  expect_mean(sum_b, sum_b2, 5.0 / 6.0, "E[b]");
  expect_mean(sum_a2, sum_a4, 1.0, "E[a^2]");
  expect_mean(sum_b2, sum_b4, 1.0, "E[b^2]");
}

TEST(PortSet, RejectsBadIndexAndZeroArea) {
  PortSet ports;
  EXPECT_THROW(ports.sample(0, 0.5, 0.5), std::out_of_range);
  Surface flat;
  flat.name = "flat";
  flat.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  EXPECT_THROW(ports.add(0, flat, {{0, 1, 2}}), std::invalid_argument);
  Surface tri;
  tri.name = "tri";
  tri.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_EQ(ports.add(3, tri, {{0, 1, 2}}), 0);
  EXPECT_EQ(ports.port_of_surface(3), 0);
  EXPECT_EQ(ports.port_of_surface(0), -1);
  EXPECT_DOUBLE_EQ(ports.total_area_m2(), 0.5);
  // Extreme uniform numbers stay on the triangle.
  for (double u1 : {0.0, 0.999999999999}) {
    for (double u2 : {0.0, 0.999999999999}) {
      const Vec3 p = ports.sample(0, u1, u2).position;
      EXPECT_GE(p.x, -1e-12);
      EXPECT_GE(p.y, -1e-12);
      EXPECT_LE(p.x + p.y, 1 + 1e-12);
    }
  }
}

}  // namespace
}  // namespace dayphoton::engine
