// The visibility clip on receiver planes: the cuts a scene makes in a work plane
// (plane_cuts.h), the region of a disc its centre sees (plane_visibility.h) against the exact
// clip of receiver_plane.h, and the estimate's keeping to a sensor's side of a partition
// (daylight_coefficients.h) on deterministic photon lattices with closed-form fields.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/plane_cuts.h"
#include "dayphoton/engine/plane_visibility.h"
#include "dayphoton/engine/receiver_plane.h"
#include "dayphoton/engine/scene.h"
#include "photon_lattice.h"
#include "test_scenes.h"

namespace dayphoton::engine {
namespace {

const std::vector<PlanePoint> Square4 = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};

ReceiverPlane plane_with_cuts(const std::vector<PlanePoint>& outline, std::vector<PlaneSegment> cuts) {
  ReceiverPlane p(0.8, true, outline);
  p.set_interior_cuts(std::move(cuts));
  return p;
}

TEST(PlaneVisibility, NoneWhereNothingCutsTheDisc) {
  // A convex room without cuts, and a cut farther than the radius: the outline clip is exact.
  const ReceiverPlane room(0.8, true, Square4);
  EXPECT_FALSE(PlaneVisibility::around(room, 1, 1, 0.5).has_value());
  const ReceiverPlane cut = plane_with_cuts(Square4, {{{3, 0.5}, {3, 3.5}}});
  EXPECT_FALSE(PlaneVisibility::around(cut, 1, 1, 1.9).has_value());
  EXPECT_TRUE(PlaneVisibility::around(cut, 1, 1, 2.1).has_value());
}

TEST(PlaneVisibility, PseudoAngleSectorsAreMonotonicInTheAngle) {
  // Every direction lands in the wedge whose angular interval holds it: sector_of increases
  // with the angle, from 0 at angle 0 to Sectors - 1 just below 2 pi.
  int previous = 0;
  for (int i = 0; i < 100000; ++i) {
    const double t = 2 * Pi * (i + 0.5) / 100000;
    const int k = PlaneVisibility::sector_of(std::cos(t), std::sin(t));
    ASSERT_GE(k, previous) << "angle " << t;
    ASSERT_LT(k, PlaneVisibility::Sectors);
    previous = k;
  }
  EXPECT_EQ(PlaneVisibility::sector_of(1, 0), 0);
  EXPECT_EQ(previous, PlaneVisibility::Sectors - 1);
}

TEST(PlaneVisibility, AStraightCutLeavesTheClippedDiscsMoments) {
  // A cut along y = 2 across the room, 0.3 m from the centre (2.1, 1.7): the region the centre
  // sees is the disc clipped to y < 2, whose moments the outline clip computes exactly (an
  // outline that ends at y = 2). The wedges follow the line to within their width squared:
  // (2 pi / 1024)^2 ~ 4e-5 of the disc's scale.
  const ReceiverPlane cut = plane_with_cuts(Square4, {{{0, 2}, {4, 2}}});
  const ReceiverPlane half(0.8, true, {{0, 0}, {4, 0}, {4, 2}, {0, 2}});
  const double x = 2.1, y = 1.7;
  const std::optional<PlaneVisibility> v = PlaneVisibility::around(cut, x, y, 1.0);
  ASSERT_TRUE(v.has_value());
  for (double r : {0.25, 0.5, 0.9}) {
    const AreaMoments a = v->moments(r), b = half.clipped_disc_moments(x, y, r);
    const double r2 = r * r, r4 = r2 * r2;
    EXPECT_NEAR(a.area / r2, b.area / r2, 1e-4) << r;
    EXPECT_NEAR(a.mx / (r2 * r), b.mx / (r2 * r), 1e-4) << r;
    EXPECT_NEAR(a.my / (r2 * r), b.my / (r2 * r), 1e-4) << r;
    EXPECT_NEAR(a.mxx / r4, b.mxx / r4, 1e-4) << r;
    EXPECT_NEAR(a.mxy / r4, b.mxy / r4, 1e-4) << r;
    EXPECT_NEAR(a.myy / r4, b.myy / r4, 1e-4) << r;
    EXPECT_NEAR(v->area_m2(r), a.area, 1e-12);
    const ScaledMoments4 m4 = v->moments4(r), e4 = half.clipped_disc_moments4(x, y, r);
    for (int i = 0; i < 15; ++i) EXPECT_NEAR(m4.value[i], e4.value[i], 1e-4) << "r " << r << ", moment " << i;
  }
  // At 0.25 m the cut is out of reach: the whole disc.
  EXPECT_NEAR(v->area_m2(0.25), Pi * 0.0625, 1e-12);
}

TEST(PlaneVisibility, ThePointsSeenFillTheRegionsArea) {
  // The photons counted (sees) and the region integrated (area_m2) are one set: the share of
  // uniform points in the disc that the centre sees, times the disc's area, is the region's
  // area within 4 binomial standard errors: a short partition in the arm of an L-shaped room.
  const std::vector<PlanePoint> ell = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
  const ReceiverPlane plane = plane_with_cuts(ell, {{{2.2, 0.2}, {2.2, 0.8}}});
  const double x = 1.6, y = 0.5, r = 1.2;
  const std::optional<PlaneVisibility> v = PlaneVisibility::around(plane, x, y, 1.5);
  ASSERT_TRUE(v.has_value());
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1, 1);
  int inside = 0, seen = 0;
  while (inside < 400000) {
    const double dx = u(rng) * r, dy = u(rng) * r;
    if (dx * dx + dy * dy > r * r) continue;
    ++inside;
    if (v->sees(x + dx, y + dy)) ++seen;
  }
  const double p = double(seen) / inside, full = Pi * r * r;
  const double area = v->area_m2(r);
  std::printf("seen share %.5f, region %.5f of the disc\n", p, area / full);
  EXPECT_NEAR(p, area / full, 4 * std::sqrt(p * (1 - p) / inside));
  // Hidden: behind the partition, and the far arm around the re-entrant corner (1, 1).
  EXPECT_FALSE(v->sees(2.5, 0.5));
  EXPECT_FALSE(v->sees(0.9, 1.3));
  EXPECT_TRUE(v->sees(0.5, 0.5));
  EXPECT_TRUE(v->sees(0.5, 1.2));
  EXPECT_TRUE(v->sees(2.1, 0.9));
  EXPECT_LT(area, plane.disc_area_inside_m2(x, y, r) - 0.05);
}

// The moments summed wedge by wedge, as a disc's are defined (plane_visibility.h): the whole
// disc less, for every wedge cut within max_radius_m short of r, its unit moments times
// 1 - (reach / r)^(n+2); and, per moment, the sum of the magnitudes of its terms, the scale
// its rounding is measured against.
struct DirectMoments {
  ScaledMoments4 value, scale;
};
DirectMoments direct_wedge_sum(const PlaneVisibility& v, double max_radius_m, double r) {
  DirectMoments d;
  for (int k = 0; k < PlaneVisibility::Sectors; ++k) {
    const ScaledMoments4& w = PlaneVisibility::unit_wedge_moments(k);
    for (int i = 0; i < 15; ++i) {
      d.value.value[i] += w.value[i];
      d.scale.value[i] += std::fabs(w.value[i]);
    }
  }
  for (int k = 0; k < PlaneVisibility::Sectors; ++k) {
    const double reach = v.reach_m(k);
    if (!(reach < max_radius_m) || !(reach < r)) continue;
    const ScaledMoments4& w = PlaneVisibility::unit_wedge_moments(k);
    for (int a = 0; a <= 4; ++a)
      for (int b = 0; a + b <= 4; ++b) {
        const double term = w.at(a, b) * (1 - std::pow(reach / r, a + b + 2));
        d.value.at(a, b) -= term;
        d.scale.at(a, b) += std::fabs(term);
      }
  }
  return d;
}

TEST(PlaneVisibility, PrefixSumMomentsEqualTheWedgeSum) {
  // Random rooms (a square or an L with its re-entrant corner) with 1-8 random partitions, a
  // random centre and widest radius: at radii below the nearest reach, at and between the
  // sorted reaches (each PrefixStride-th and its neighbours, where the sums kept and the
  // wedges summed one by one meet, and at random), and beyond the farthest, the moments of
  // every order equal the wedge-by-wedge sum to 1e-12 of the sum of its terms' magnitudes.
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> u(0, 1);
  const std::vector<PlanePoint> ell = {{0, 0}, {12, 0}, {12, 5}, {5, 5}, {5, 12}, {0, 12}};
  const std::vector<PlanePoint> square = {{0, 0}, {12, 0}, {12, 12}, {0, 12}};
  int checked = 0, cut_radii = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const std::vector<PlanePoint>& outline = trial % 2 == 0 ? ell : square;
    std::vector<PlaneSegment> cuts;
    const int count = 1 + int(u(rng) * 8);
    for (int c = 0; c < count; ++c) {
      const PlanePoint a{0.5 + 11 * u(rng), 0.5 + 4 * u(rng)};
      const double angle = 2 * Pi * u(rng), length = 0.3 + 4 * u(rng);
      cuts.push_back({a, {a.x + length * std::cos(angle), a.y + length * std::sin(angle)}});
    }
    const ReceiverPlane plane = plane_with_cuts(outline, cuts);
    const double x = 0.2 + 11.6 * u(rng), y = 0.2 + 4.6 * u(rng), max_radius_m = 0.5 + 15 * u(rng);
    const std::optional<PlaneVisibility> v = PlaneVisibility::around(plane, x, y, max_radius_m);
    if (!v) continue;
    std::vector<double> reaches;
    for (int k = 0; k < PlaneVisibility::Sectors; ++k)
      if (v->reach_m(k) < max_radius_m) reaches.push_back(v->reach_m(k));
    std::sort(reaches.begin(), reaches.end());
    std::vector<double> radii = {1e-60, 1e60, 2 * max_radius_m};
    if (!reaches.empty()) {
      radii.push_back(0.5 * reaches.front());
      radii.push_back(1.5 * reaches.back());
      for (std::size_t j = 0; j < reaches.size(); ++j) {
        const std::size_t phase = j % PlaneVisibility::PrefixStride;
        if (phase == 0 || phase + 1 == PlaneVisibility::PrefixStride || u(rng) < 0.02) {
          radii.push_back(reaches[j]);
          if (j + 1 < reaches.size()) radii.push_back(0.5 * (reaches[j] + reaches[j + 1]));
        }
      }
    }
    for (double r : radii) {
      const DirectMoments d = direct_wedge_sum(*v, max_radius_m, r);
      if (d.value.at(0, 0) < Pi * (1 - 1e-12)) ++cut_radii;
      const ScaledMoments4 m4 = v->moments4(r);
      const AreaMoments m2 = v->moments(r);
      const double r2 = r * r, r3 = r2 * r, r4 = r2 * r2;
      const double order2[6] = {m2.area / r2, m2.mx / r3, m2.my / r3, m2.mxx / r4, m2.mxy / r4, m2.myy / r4};
      for (int i = 0; i < 15; ++i) {
        ASSERT_NEAR(m4.value[i], d.value.value[i], 1e-12 * d.scale.value[i])
            << "trial " << trial << ", r " << r << ", moment " << i;
        if (i < 6 && r > 1e-50 && r < 1e50) {
          ASSERT_NEAR(order2[i], d.value.value[i], 1e-12 * d.scale.value[i]) << "trial " << trial << ", r " << r;
        }
      }
      if (r > 1e-50 && r < 1e50) {
        ASSERT_NEAR(v->area_m2(r) / r2, d.value.at(0, 0), 1e-12 * d.scale.at(0, 0)) << "trial " << trial << ", r " << r;
      }
      ++checked;
    }
  }
  std::printf("%d radii on random visibilities, %d of them cut\n", checked, cut_radii);
  EXPECT_GT(cut_radii, 2000);
}

TEST(PlaneCuts, APartitionCutsTheWorkPlaneTheWallsAndALowDeskDoNot) {
  // A 4 x 4 x 3 m room with a 1.4 m partition along y = 2 (x 0.5-3.5) and a desk top at
  // 0.75 m: the 0.8 m plane is cut by the partition alone (the walls lie on the outline, the
  // desk below the plane).
  SceneDescription d = test::box_room({4, 4, 3});
  test::add_surface(d, "partition", 0, {{0.5, 2, 0}, {3.5, 2, 0}, {3.5, 2, 1.4}, {0.5, 2, 1.4}});
  test::add_surface(d, "desk", 0, {{1, 0.5, 0.75}, {2, 0.5, 0.75}, {2, 1.2, 0.75}, {1, 1.2, 0.75}});
  const Scene scene = Scene::build(d);
  const ReceiverPlane plane(0.8, true, Square4);
  const std::vector<PlaneSegment> cuts = interior_plane_cuts(scene, plane);
  ASSERT_FALSE(cuts.empty());
  double length = 0;
  for (const PlaneSegment& s : cuts) {
    EXPECT_NEAR(s.a.y, 2, 1e-12);
    EXPECT_NEAR(s.b.y, 2, 1e-12);
    length += std::hypot(s.b.x - s.a.x, s.b.y - s.a.y);
  }
  EXPECT_NEAR(length, 3.0, 1e-9);  // the partition's width, once (two triangles, one each)
  // The same partition only 0.7 m tall does not reach the plane.
  SceneDescription low = test::box_room({4, 4, 3});
  test::add_surface(low, "partition", 0, {{0.5, 2, 0}, {3.5, 2, 0}, {3.5, 2, 0.7}, {0.5, 2, 0.7}});
  EXPECT_TRUE(interior_plane_cuts(Scene::build(low), plane).empty());
}

TEST(PlaneCuts, ASeamAtThePlanesHeightCutsItADeskTopThereDoesNot) {
  // A partition of two panels meeting at the plane's height (0-0.8 m and 0.8-1.4 m, x 0.5-3.5
  // at y = 2): no triangle has vertices strictly on both sides, yet the seam is a wall across
  // the plane, 3 m long. A desk box whose top is the plane (x 1-2, y 0.5-1.2, 0-0.8 m) touches
  // it from below only: no cut.
  SceneDescription d = test::box_room({4, 4, 3});
  test::add_surface(d, "lower", 0, {{0.5, 2, 0}, {3.5, 2, 0}, {3.5, 2, 0.8}, {0.5, 2, 0.8}});
  test::add_surface(d, "upper", 0, {{0.5, 2, 0.8}, {3.5, 2, 0.8}, {3.5, 2, 1.4}, {0.5, 2, 1.4}});
  test::add_surface(d, "desk_top", 0, {{1, 0.5, 0.8}, {2, 0.5, 0.8}, {2, 1.2, 0.8}, {1, 1.2, 0.8}});
  test::add_surface(d, "desk_south", 0, {{1, 0.5, 0}, {2, 0.5, 0}, {2, 0.5, 0.8}, {1, 0.5, 0.8}});
  test::add_surface(d, "desk_east", 0, {{2, 0.5, 0}, {2, 1.2, 0}, {2, 1.2, 0.8}, {2, 0.5, 0.8}});
  const ReceiverPlane plane(0.8, true, Square4);
  const std::vector<PlaneSegment> cuts = interior_plane_cuts(Scene::build(d), plane);
  ASSERT_EQ(cuts.size(), 1u);
  EXPECT_NEAR(cuts[0].a.y, 2, 1e-12);
  EXPECT_NEAR(cuts[0].b.y, 2, 1e-12);
  EXPECT_NEAR(std::fabs(cuts[0].b.x - cuts[0].a.x), 3.0, 1e-12);
}

TEST(PlaneCuts, ACutPartlyInsideTheOutlineKeepsItsPartInside) {
  // A grid outline smaller than the room (the square 0-4 m of an 8 x 8 m room): a partition
  // along y = 2 from x = 3 to 6.5 m cuts the plane inside over x 3-4 m, though the middle of
  // its triangles' cuts (x 3-5 and 5-6.5: the quad's diagonal meets the plane at x = 5) lies
  // outside; it hides the sensors at x 3.5 m behind it from those in front. Kept: that part,
  // 1 m. One outside the outline altogether (x 5-7 m), and the room's walls, are left out.
  SceneDescription d = test::box_room({8, 8, 3});
  test::add_surface(d, "partition", 0, {{3, 2, 0}, {6.5, 2, 0}, {6.5, 2, 1.4}, {3, 2, 1.4}});
  test::add_surface(d, "outside", 0, {{5, 3, 0}, {7, 3, 0}, {7, 3, 1.4}, {5, 3, 1.4}});
  const ReceiverPlane plane(0.8, true, Square4);
  const std::vector<PlaneSegment> cuts = interior_plane_cuts(Scene::build(d), plane);
  ASSERT_EQ(cuts.size(), 1u);
  EXPECT_NEAR(cuts[0].a.y, 2, 1e-12);
  EXPECT_NEAR(cuts[0].b.y, 2, 1e-12);
  EXPECT_NEAR(std::min(cuts[0].a.x, cuts[0].b.x), 3, 1e-12);
  EXPECT_NEAR(std::max(cuts[0].a.x, cuts[0].b.x), 4, 1e-12);
  ReceiverPlane with = plane;
  with.set_interior_cuts(cuts);
  const std::optional<PlaneVisibility> v = PlaneVisibility::around(with, 3.5, 1.8, 1.0);
  ASSERT_TRUE(v.has_value());
  EXPECT_FALSE(v->sees(3.5, 2.3));
  EXPECT_TRUE(v->sees(3.5, 1.3));

  // A triangle whose cut runs from (0.5, -1) to (7, 5.5): both ends and the middle outside
  // an L-shaped outline; the stretch from (1.5, 0) to (2.5, 1) crosses its lower arm.
  const std::vector<PlanePoint> ell = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
  const double f = 0.8 / 3;  // the cut's height on the triangle's sides, from the base
  const Vec3 apex{3.75, 2.25, 3};
  auto base = [&](double x, double y) {
    return Vec3{apex.x + (x - apex.x) / (1 - f), apex.y + (y - apex.y) / (1 - f), 0};
  };
  SceneDescription slanted = test::box_room({8, 8, 3});
  test::add_surface(slanted, "slanted", 0, {base(0.5, -1), base(7, 5.5), apex});
  const std::vector<PlaneSegment> crossing = interior_plane_cuts(Scene::build(slanted), ReceiverPlane(0.8, true, ell));
  ASSERT_EQ(crossing.size(), 1u);
  EXPECT_NEAR(std::min(crossing[0].a.x, crossing[0].b.x), 1.5, 1e-9);
  EXPECT_NEAR(std::max(crossing[0].a.x, crossing[0].b.x), 2.5, 1e-9);
  EXPECT_NEAR(std::min(crossing[0].a.y, crossing[0].b.y), 0, 1e-9);
  EXPECT_NEAR(std::max(crossing[0].a.y, crossing[0].b.y), 1, 1e-9);
}

/// The photon lattice (photon_lattice.h) of E(x, y) on the 4 x 4 m plane cut along `cuts`.
template <typename Field>
GridPhotons lattice(Field irradiance, std::vector<PlaneSegment> cuts) {
  return test::lattice_photons_on(plane_with_cuts(Square4, std::move(cuts)), irradiance);
}

std::vector<double> estimates(const GridPhotons& grid, const std::vector<SensorPoint>& sensors, std::size_t bandwidth,
                              bool clip, bool quadratic) {
  CoefficientOptions o;
  o.density.bandwidth = bandwidth;
  o.visibility_clip = clip;
  if (quadratic) o.quadratic_fit_sources = {0};
  std::vector<double> out;
  for (const Vec3& g : test::estimate_coefficients(grid, sensors, o).global) out.push_back(g.x);
  return out;
}

TEST(DaylightCoefficients, VisibilityClipKeepsEachSideOfAPartition) {
  // Closed form: the light on a work plane jumps at a partition along y = 2 (x 0.5-3.5),
  // E = 1 on the shaded side (y < 2) and 3 + y on the lit side, on the deterministic 1 cm
  // lattice. Sensors 0.19 m either side of it with discs of 4000 photons (radius ~0.36 m).
  // Clipped, each side's estimate is its own field (local-linear, exact for these linear
  // fields up to the lattice's count error, 2e-3 as the wall tests); unclipped, the disc
  // spans the partition and the shaded side reads the lit side's light (here 2-3 times too
  // high). With the local-quadratic fit the same holds.
  auto field = [](double x, double y) { return y < 2 && x > 0.5 && x < 3.5 ? 1.0 : 3.0 + y; };
  const GridPhotons grid = lattice(field, {{{0.5, 2}, {3.5, 2}}});
  const std::vector<SensorPoint> sensors = {{{2.0037, 1.8061, 0.8}, {0, 0, 1}},   // shaded side
                                            {{1.9963, 2.1939, 0.8}, {0, 0, 1}}};  // lit side
  for (bool quadratic : {false, true}) {
    const std::vector<double> clipped = estimates(grid, sensors, 4000, true, quadratic);
    const std::vector<double> spread = estimates(grid, sensors, 4000, false, quadratic);
    std::printf("quadratic %d: clipped %.5f %.5f, unclipped %.5f %.5f\n", int(quadratic), clipped[0], clipped[1],
                spread[0], spread[1]);
    EXPECT_NEAR(clipped[0] / 1.0, 1.0, 2e-3) << quadratic;
    EXPECT_NEAR(clipped[1] / (3.0 + 2.1939), 1.0, 2e-3) << quadratic;
    EXPECT_GT(spread[0], 1.5) << quadratic;  // the bias the clip removes
  }
  // Away from the partition (its reach beyond every disc), the clip changes nothing.
  const std::vector<SensorPoint> far = {{{2.0037, 0.5061, 0.8}, {0, 0, 1}}};
  EXPECT_EQ(estimates(grid, far, 4000, true, false), estimates(grid, far, 4000, false, false));
}

}  // namespace
}  // namespace dayphoton::engine
