// The Klems angle basis (core/klems_basis.h): the LBNL full basis' patches, their projected
// solid angles (which sum to pi over a hemisphere), patch lookup and in-patch sampling.
#include "dayphoton/core/klems_basis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "dayphoton/core/units.h"

using namespace dayphoton;

TEST(KlemsBasis, FullBasisHas145PatchesInNineRings) {
  const KlemsBasis b = KlemsBasis::full();
  EXPECT_EQ(b.size(), 145);
  ASSERT_EQ(b.rings().size(), 9u);
  const int counts[] = {1, 8, 16, 20, 24, 24, 24, 16, 12};
  for (int r = 0; r < 9; ++r) EXPECT_EQ(b.rings()[static_cast<std::size_t>(r)].phi_count, counts[r]);
  EXPECT_EQ(b.first_of_ring(8), 133);
}

TEST(KlemsBasis, ProjectedSolidAnglesSumToPi) {
  const KlemsBasis b = KlemsBasis::full();
  double sum = 0;
  for (int i = 0; i < b.size(); ++i) sum += b.projected_solid_angle(i);
  EXPECT_NEAR(sum, Pi, 1e-12);
  // The polar cap: pi sin^2(5 deg) = 0.0238639.
  EXPECT_NEAR(b.projected_solid_angle(0), 0.0238639, 1e-7);
  // Ring 2 (5-15 deg, 8 patches): pi (sin^2 15 - sin^2 5) / 8.
  EXPECT_NEAR(b.projected_solid_angle(1), Pi * (std::pow(std::sin(deg_to_rad(15)), 2) - std::pow(std::sin(deg_to_rad(5)), 2)) / 8,
              1e-15);
}

TEST(KlemsBasis, PatchesAreCentredOnTheirAzimuth) {
  const KlemsBasis b = KlemsBasis::full();
  auto dir = [](double theta_deg, double phi_deg) {
    const double t = deg_to_rad(theta_deg), p = deg_to_rad(phi_deg);
    return Vec3{std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
  };
  EXPECT_EQ(b.patch(dir(0, 0)), 0);
  EXPECT_EQ(b.patch(dir(4.9, 123)), 0);
  EXPECT_EQ(b.patch(dir(10, 0)), 1);
  EXPECT_EQ(b.patch(dir(10, 22)), 1);     // sector 0 spans -22.5 .. 22.5 degrees
  EXPECT_EQ(b.patch(dir(10, 23)), 2);
  EXPECT_EQ(b.patch(dir(10, 350)), 1);
  EXPECT_EQ(b.patch(dir(10, 337)), 8);
  EXPECT_EQ(b.patch(dir(89.9, 0)), 133);
  EXPECT_EQ(b.patch(dir(80, 180)), 139);  // 12 sectors of 30 degrees: 180 is sector 6
  // The sign of z does not matter: both hemispheres use the same basis.
  Vec3 down = dir(40, 100);
  down.z = -down.z;
  EXPECT_EQ(b.patch(down), b.patch(dir(40, 100)));
}

TEST(KlemsBasis, SamplesFallInTheirPatch) {
  const KlemsBasis b = KlemsBasis::full();
  for (int i = 0; i < b.size(); ++i)
    for (double u1 : {0.001, 0.5, 0.999})
      for (double u2 : {0.001, 0.5, 0.999}) {
        const Vec3 v = b.sample(i, u1, u2);
        EXPECT_NEAR(length(v), 1.0, 1e-12);
        EXPECT_GE(v.z, 0.0);
        EXPECT_EQ(b.patch(v), i) << "patch " << i << " u " << u1 << " " << u2;
      }
}

TEST(KlemsBasis, SamplingIsUniformInProjectedSolidAngle) {
  // sin^2 theta of the samples is uniform over the ring: its mean is the midpoint.
  const KlemsBasis b = KlemsBasis::full();
  const int patch = b.first_of_ring(4);  // 35-45 degrees
  double mean = 0;
  const int n = 1000;
  for (int k = 0; k < n; ++k) {
    const Vec3 v = b.sample(patch, (k + 0.5) / n, 0.5);
    mean += 1 - v.z * v.z;
  }
  mean /= n;
  const double lo = std::pow(std::sin(deg_to_rad(35)), 2), hi = std::pow(std::sin(deg_to_rad(45)), 2);
  EXPECT_NEAR(mean, 0.5 * (lo + hi), 1e-6);
}

TEST(KlemsBasis, RejectsRingsThatDoNotTileTheHemisphere) {
  EXPECT_THROW(KlemsBasis({{0, deg_to_rad(10), 1}, {deg_to_rad(12), deg_to_rad(90), 8}}), std::invalid_argument);
  EXPECT_THROW(KlemsBasis({{0, deg_to_rad(10), 1}, {deg_to_rad(10), deg_to_rad(80), 8}}), std::invalid_argument);
  EXPECT_THROW(KlemsBasis({{0, deg_to_rad(10), 1}, {deg_to_rad(10), deg_to_rad(90), 1}}), std::invalid_argument);
  EXPECT_THROW(KlemsBasis({{0, deg_to_rad(90), 0}}), std::invalid_argument);
  EXPECT_NO_THROW(KlemsBasis({{0, deg_to_rad(90), 1}}));
}
