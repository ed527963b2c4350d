// Sun bins (engine/sun_bins.h): the bilinear (altitude, azimuth) stencil on the Reinhart
// grid and the choice of bins for a set of hourly suns. Every check here is exact or
// deterministic: weights are a partition of unity, exact for functions linear in (altitude,
// azimuth), second order for smooth functions, continuous; the bins are exactly the patches
// the suns' stencils use.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/sun_bins.h"
#include "dayphoton/sky/solar_position.h"

namespace dayphoton::engine {
namespace {

Vec3 from_angles(double altitude_rad, double azimuth_rad) {
  return {std::sin(azimuth_rad) * std::cos(altitude_rad), std::cos(azimuth_rad) * std::cos(altitude_rad),
          std::sin(altitude_rad)};
}

double altitude_of(const Vec3& d) { return std::asin(std::clamp(d.z / length(d), -1.0, 1.0)); }
double azimuth_of(const Vec3& d) {
  double a = std::atan2(d.x, d.y);
  return a < 0 ? a + 2 * Pi : a;
}

/// Random directions above the horizon, uniform in solid angle, fixed seed.
std::vector<Vec3> random_suns(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> out;
  while (static_cast<int>(out.size()) < n) {
    const double z = u(rng), phi = 2 * Pi * u(rng);
    if (z <= 1e-6) continue;
    const double r = std::sqrt(1 - z * z);
    out.push_back({r * std::sin(phi), r * std::cos(phi), z});
  }
  return out;
}

template <typename F>
double interpolate(const sky::PatchBasis& basis, const Vec3& sun, const F& f) {
  const SunStencil s = patch_stencil(basis, sun);
  double v = 0;
  for (int k = 0; k < s.count; ++k) v += s.weight[k] * f(basis.centre(s.index[k]));
  return v;
}

TEST(SunBins, StencilIsAPartitionOfUnityOverAtMostFourSkyPatches) {
  for (int mf : {1, 2, 6}) {
    const sky::PatchBasis basis = sky::PatchBasis::reinhart(mf);
    for (const Vec3& sun : random_suns(20000, 11)) {
      const SunStencil s = patch_stencil(basis, sun);
      ASSERT_GE(s.count, 1);
      ASSERT_LE(s.count, 4);
      double sum = 0;
      std::set<int> seen;
      for (int k = 0; k < s.count; ++k) {
        EXPECT_GT(s.weight[k], 0.0);
        EXPECT_GE(s.index[k], 1);  // never the ground bin
        EXPECT_LT(s.index[k], basis.bin_count());
        EXPECT_TRUE(seen.insert(s.index[k]).second) << "a patch listed twice";
        sum += s.weight[k];
      }
      EXPECT_NEAR(sum, 1.0, 1e-12);
    }
  }
}

TEST(SunBins, SunAtAPatchCentreUsesThatPatch) {
  const sky::PatchBasis basis = sky::PatchBasis::reinhart(6);
  for (int bin = 1; bin < basis.bin_count(); ++bin) {
    const SunStencil s = patch_stencil(basis, basis.centre(bin));
    double own = 0;
    for (int k = 0; k < s.count; ++k)
      if (s.index[k] == bin) own = s.weight[k];
    EXPECT_NEAR(own, 1.0, 1e-9) << "patch " << bin;  // only rounding may leak to a neighbour
  }
}

TEST(SunBins, ExactForFunctionsLinearInAltitudeAndAzimuth) {
  // f = a + b h + c phi at the patch centres (phi in [0, 2 pi)); suns more than one patch
  // width away from north, so that no cell straddles the azimuth wrap where f jumps, and
  // below the top row's centre (the cap has no azimuth).
  for (int mf : {1, 3, 6}) {
    const sky::PatchBasis basis = sky::PatchBasis::reinhart(mf);
    const double top = (basis.row_count() - 1.5) * basis.row_height_rad();
    auto f = [&](const Vec3& d) { return 0.7 + 2.0 * altitude_of(d) - 0.3 * azimuth_of(d); };
    int checked = 0;
    for (const Vec3& sun : random_suns(5000, 12)) {
      const double h = altitude_of(sun), phi = azimuth_of(sun);
      if (h >= top) continue;
      const int r0 = std::max(0, static_cast<int>(std::floor(h / basis.row_height_rad() - 0.5)));
      const double widest = 2 * Pi / std::min(basis.row(r0).patch_count, basis.row(r0 + 1).patch_count);
      if (phi < widest || phi > 2 * Pi - widest) continue;
      const double expected = h < 0.5 * basis.row_height_rad()
                                  ? 0.7 + 2.0 * (0.5 * basis.row_height_rad()) - 0.3 * phi  // lowest row alone
                                  : f(sun);
      EXPECT_NEAR(interpolate(basis, sun, f), expected, 1e-9);
      ++checked;
    }
    EXPECT_GT(checked, 3000);
  }
}

TEST(SunBins, SecondOrderForSmoothFunctions) {
  // A smooth function of direction (a bright lobe 40 deg from the zenith): the largest
  // interpolation error over 4000 suns between 5 and 80 deg altitude falls by ~4 per halving
  // of the patch size if the scheme is second order (~2 if first order). From MF 2 to MF 8
  // (two halvings) second order gives ~16: require more than 8, which first order cannot give.
  const Vec3 axis = from_angles(deg_to_rad(50), deg_to_rad(200));
  auto f = [&](const Vec3& d) { return std::exp(3.0 * dot(d, axis)); };
  auto worst = [&](int mf) {
    const sky::PatchBasis basis = sky::PatchBasis::reinhart(mf);
    double e = 0;
    for (const Vec3& sun : random_suns(4000, 13)) {
      const double h = rad_to_deg(altitude_of(sun));
      if (h < 5 || h > 80) continue;
      e = std::max(e, std::fabs(interpolate(basis, sun, f) - f(sun)));
    }
    return e;
  };
  const double e2 = worst(2), e4 = worst(4), e8 = worst(8);
  EXPECT_GT(e2 / e4, 2.8) << e2 << " " << e4;
  EXPECT_GT(e2 / e8, 8.0) << e2 << " " << e8;
}

TEST(SunBins, ContinuousAcrossCellEdgesRowsTheCapAndNorth) {
  // The interpolant of a smooth function moves by O(epsilon) when the sun does: checked at
  // row centres (where the bracketing rows change), at patch centres (bracketing patches
  // change), across north (azimuth wrap), across the top row centre (cap) and at the lowest
  // row centre (clamped below).
  const sky::PatchBasis basis = sky::PatchBasis::reinhart(6);
  auto f = [](const Vec3& d) { return std::exp(2.0 * d.x - d.y + 0.5 * d.z); };
  const double eps = 1e-7, alpha = basis.row_height_rad();
  std::vector<std::pair<double, double>> points;  // (altitude, azimuth) on an edge
  for (int r = 0; r < basis.row_count() - 1; ++r)
    for (double az : {0.0, 0.3, 2.0, 4.0})
      points.push_back({(r + 0.5) * alpha, az});
  for (int j = 0; j < 5; ++j) points.push_back({10.3 * alpha, j * 2 * Pi / basis.row(10).patch_count});
  for (const auto& [h, az] : points) {
    const double below = interpolate(basis, from_angles(h - eps, az), f);
    const double above = interpolate(basis, from_angles(h + eps, az), f);
    const double left = interpolate(basis, from_angles(h, az - eps), f);
    const double right = interpolate(basis, from_angles(h, az + eps), f);
    // |f| <= e^2.3 and its patch-to-patch slope is below e^2.3 * 2.3 / alpha per radian.
    const double bound = 10 * eps * std::exp(2.3) * 2.3 / alpha;
    EXPECT_NEAR(below, above, bound) << "altitude " << h << " azimuth " << az;
    EXPECT_NEAR(left, right, bound) << "altitude " << h << " azimuth " << az;
  }
}

TEST(SunBins, CapAndHorizon) {
  const sky::PatchBasis basis = sky::PatchBasis::reinhart(6);
  const int cap = basis.bin_count() - 1;
  const SunStencil zenith = patch_stencil(basis, {0, 0, 1});
  ASSERT_EQ(zenith.count, 1);
  EXPECT_EQ(zenith.index[0], cap);
  // Halfway between the top row's centre and the zenith: half the weight on the cap.
  const double h = (basis.row_count() - 1.0) * basis.row_height_rad();
  const SunStencil high = patch_stencil(basis, from_angles(h, 1.0));
  double on_cap = 0;
  for (int k = 0; k < high.count; ++k)
    if (high.index[k] == cap) on_cap = high.weight[k];
  EXPECT_NEAR(on_cap, 0.5, 1e-9);
  // Below the lowest row centre: that row alone, no extrapolation.
  const SunStencil low = patch_stencil(basis, from_angles(0.2 * basis.row_height_rad(), 1.0));
  for (int k = 0; k < low.count; ++k) EXPECT_EQ(basis.row_of_bin(low.index[k]), 0);
  EXPECT_THROW(patch_stencil(basis, {1, 0, 0}), std::invalid_argument);
  EXPECT_THROW(patch_stencil(basis, {0, 1, -0.1}), std::invalid_argument);
  EXPECT_THROW(patch_stencil(basis, {0, 0, 0}), std::invalid_argument);
}

TEST(SunBins, BinsAreExactlyThePatchesTheSunsStencilsUse) {
  // The suns of one hour of the day over a year (an analemma) and of noon: the bins include
  // every patch a sun lies in, every stencil resolves, and no bin is unused.
  std::vector<Vec3> suns;
  for (int day = 0; day < 365; day += 3) {
    const double declination = deg_to_rad(23.44) * std::sin(2 * Pi * (day - 80) / 365.0);
    for (double hour_angle_deg : {0.0, -45.0}) {
      const double lat = deg_to_rad(37.72), w = deg_to_rad(hour_angle_deg);
      // Sun direction in (east, north, up) from declination and hour angle (textbook).
      const Vec3 d{-std::cos(declination) * std::sin(w),
                   std::cos(lat) * std::sin(declination) - std::sin(lat) * std::cos(declination) * std::cos(w),
                   std::sin(lat) * std::sin(declination) + std::cos(lat) * std::cos(declination) * std::cos(w)};
      suns.push_back(d);
    }
  }
  const SunBins bins = SunBins::for_suns(suns, 6);
  std::set<int> patches;
  for (std::size_t i = 0; i < bins.size(); ++i) {
    if (i > 0) {
      EXPECT_LT(bins.patch(i - 1), bins.patch(i));
    }
    patches.insert(bins.patch(i));
    EXPECT_NEAR(length(bins.direction(i) - bins.basis().centre(bins.patch(i))), 0.0, 1e-15);
  }
  std::set<int> used;
  for (const Vec3& sun : suns) {
    EXPECT_TRUE(patches.count(bins.basis().find_bin(sun))) << "the patch a sun lies in is a bin";
    const SunStencil s = bins.weights(sun);
    const SunStencil p = patch_stencil(bins.basis(), sun);
    ASSERT_EQ(s.count, p.count);
    for (int k = 0; k < s.count; ++k) {
      EXPECT_EQ(bins.patch(static_cast<std::size_t>(s.index[k])), p.index[k]);
      EXPECT_EQ(s.weight[k], p.weight[k]);
      used.insert(p.index[k]);
    }
  }
  EXPECT_EQ(used, patches);
  // Far from these suns (the northern sky) there are no bins.
  EXPECT_THROW(bins.weights(from_angles(deg_to_rad(30), deg_to_rad(0))), std::out_of_range);

  const SourceSet discs = bins.sources(sky::SunHalfAngle_rad);
  ASSERT_EQ(discs.size(), bins.size());
  for (std::size_t i = 0; i < discs.size(); ++i) {
    EXPECT_EQ(discs[i].kind, SourceKind::SunDisc);
    EXPECT_NEAR(length(discs[i].direction - bins.direction(i)), 0.0, 1e-12);
    EXPECT_NEAR(discs[i].solid_angle_sr, 2 * Pi * (1 - std::cos(sky::SunHalfAngle_rad)), 1e-15);
  }
  EXPECT_THROW(SunBins::for_suns(suns, 0), std::invalid_argument);
}

}  // namespace
}  // namespace dayphoton::engine
