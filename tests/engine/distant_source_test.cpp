// SourceSet (engine/distant_source.h): sky bins of a patch basis (ground bin 0 included) and
// sun discs. Checks: solid angles close to 4 pi (sky 2 pi + ground 2 pi) and the sun-disc
// closed form 2 pi (1 - cos a); every sample lands in the source it was drawn for
// (contains(), i.e. RADIANCE's bin rule or the cone); sun-disc samples are uniform in
// solid angle (moments and an inner-cone fraction against closed forms).
//
// Tolerances of the Monte Carlo checks: 4 standard deviations of the estimator, each
// computed in closed form for the exact distribution (comments at each test). Seeds are
// fixed, so the outcome is deterministic; 4 sigma is the margin a correct sampler would
// miss with probability < 1e-4 per check for a random seed.
#include "dayphoton/engine/distant_source.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/random.h"

namespace dayphoton::engine {
namespace {

TEST(SourceSet, SkyBinsFollowTheBasisAndCoverTheSphere) {
  for (int mf : {1, 2, 6}) {
    const sky::PatchBasis basis = sky::PatchBasis::reinhart(mf);
    const SourceSet set = SourceSet::sky_bins(basis);
    ASSERT_TRUE(set.has_basis());
    ASSERT_EQ(set.size(), static_cast<std::size_t>(basis.bin_count()));
    double sky_sr = 0.0;
    for (std::size_t i = 0; i < set.size(); ++i) {
      const DistantSource& s = set[i];
      EXPECT_EQ(s.kind, SourceKind::SkyBin);
      EXPECT_EQ(s.bin, static_cast<int>(i));
      EXPECT_EQ(s.direction, basis.centre(s.bin));
      EXPECT_GT(s.solid_angle_sr, 0.0);
      if (i > 0) sky_sr += s.solid_angle_sr;
    }
    EXPECT_DOUBLE_EQ(set[0].solid_angle_sr, 2.0 * Pi);  // ground: the lower hemisphere
    EXPECT_NEAR(sky_sr, 2.0 * Pi, 1e-12);
    EXPECT_NEAR(sky_sr + set[0].solid_angle_sr, 4.0 * Pi, 1e-12);
  }
  EXPECT_FALSE(SourceSet().has_basis());
  EXPECT_EQ(SourceSet().size(), 0u);
}

TEST(SourceSet, SkyBinSamplesLandInTheirBin) {
  // 8 x 8 jittered samples per bin: each must be a unit vector that
  // the basis puts back into the bin it was drawn for (and, for the ground, below the
  // horizon), and no neighbouring bin may claim it. (Samples exactly on a bin edge, u = 0,
  // are left out: there the round trip through sin/asin/atan2 may fall either side, a set
  // of measure zero that a jittered sampler reaches with probability 2^-53.)
  for (int mf : {1, 2}) {
    const SourceSet set = SourceSet::sky_bins(sky::PatchBasis::reinhart(mf));
    for (std::size_t p = 0; p < set.size(); ++p) {
      Rng rng(7, p, 0, RandomStream::Direct);
      for (int i = 0; i < 8; ++i) {
        for (int j = 0; j < 8; ++j) {
          const double u1 = (i + rng.uniform()) / 8.0;
          const double u2 = (j + rng.uniform()) / 8.0;
          const Vec3 w = set.sample_direction(p, u1, u2);
          ASSERT_NEAR(length(w), 1.0, 1e-12);
          ASSERT_TRUE(set.contains(p, w)) << "bin " << p << " u = " << u1 << ", " << u2;
          if (p + 1 < set.size()) {
            ASSERT_FALSE(set.contains(p + 1, w));
          }
          if (p > 0) {
            ASSERT_FALSE(set.contains(p - 1, w));
            ASSERT_GE(w.z, 0.0);
          } else {
            ASSERT_LT(w.z, 0.0);
          }
        }
      }
    }
  }
}

TEST(SourceSet, SunDiscSolidAngleAndContainment) {
  SourceSet set = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  const double sun_rad = 0.2665 * RadPerDeg;  // mean solar angular radius
  const Vec3 dir = normalize(Vec3{0.3, -0.5, 0.8});
  const std::size_t i = set.add_sun_disc(dir * 3.0, sun_rad);  // any length
  ASSERT_EQ(i, 146u);
  EXPECT_EQ(set[i].kind, SourceKind::SunDisc);
  EXPECT_NEAR(length(set[i].direction - dir), 0.0, 1e-15);
  // Small-angle series 2 pi (1 - cos a) = pi a^2 (1 - a^2 / 12 + a^4 / 360 - ...); the first
  // omitted term is a^6 / 20160 = 5e-19 relative.
  const double a2 = sun_rad * sun_rad;
  const double series = Pi * a2 * (1.0 - a2 / 12.0 + a2 * a2 / 360.0);
  EXPECT_NEAR(set[i].solid_angle_sr, series, 1e-14 * series);
  const std::size_t wide = set.add_sun_disc({0, 0, 1}, Pi / 3.0);
  EXPECT_NEAR(set[wide].solid_angle_sr, Pi, 1e-14);  // 2 pi (1 - cos 60 deg)
  const std::size_t all = set.add_sun_disc({0, 0, 1}, Pi);
  EXPECT_NEAR(set[all].solid_angle_sr, 4.0 * Pi, 1e-14);

  // Containment at the rim: just inside / just outside the angular radius.
  Vec3 t = normalize(cross(dir, Vec3{1, 0, 0}));
  auto at_angle = [&](double a) { return dir * std::cos(a) + t * std::sin(a); };
  EXPECT_TRUE(set.contains(i, dir));
  EXPECT_TRUE(set.contains(i, at_angle(sun_rad * (1 - 1e-9))));
  EXPECT_FALSE(set.contains(i, at_angle(sun_rad * (1 + 1e-9))));
  EXPECT_FALSE(set.contains(i, -dir));
  EXPECT_TRUE(set.contains(all, -dir));

  // Every sample of the small disc lies within it (centre directions on both sides of the
  // frame's z sign branch, and straight down where the frame is singular without it).
  for (const Vec3& centre : {dir, Vec3{0, 0, -1}, Vec3{0, 0, 1}, normalize(Vec3{1, 0, -1e-12})}) {
    SourceSet discs;
    const std::size_t d = discs.add_sun_disc(centre, sun_rad);
    Rng rng(11, d, 0, RandomStream::Direct);
    for (int n = 0; n < 2000; ++n) {
      const Vec3 w = discs.sample_direction(d, rng.uniform(), rng.uniform());
      ASSERT_NEAR(length(w), 1.0, 1e-12);
      ASSERT_TRUE(discs.contains(d, w));
    }
  }
}

TEST(SourceSet, SunDiscSamplesAreUniformInSolidAngle) {
  // For directions uniform in the cone of half-angle a, c = cos(theta) is uniform on
  // [cos a, 1], and phi is uniform and independent of c. With N independent samples:
  //   mean c:                 (1 + cos a) / 2,   sigma = (1 - cos a) / sqrt(12 N)
  //   mean sin(theta) cos(phi) and sin(theta) sin(phi) along the frame axes: 0,
  //                           sigma = sqrt(E[sin^2 theta] / (2 N)),
  //                           E[sin^2 theta] = 1 - E[c^2] = 1 - (1 + cos a + cos^2 a) / 3
  //   fraction within a/2:    q = (1 - cos(a/2)) / (1 - cos a),  sigma = sqrt(q (1 - q) / N)
  // (a binomial count; a wrong warp, e.g. theta uniform, gives q = 0.5 instead of 0.2529).
  constexpr int N = 200000;
  const double a = 40.0 * RadPerDeg;
  const double ca = std::cos(a);
  for (const Vec3& centre : {normalize(Vec3{-0.2, 0.7, 0.4}), Vec3{0, 0, -1}}) {
    SourceSet set;
    const std::size_t d = set.add_sun_disc(centre, a);
    // Any orthonormal pair perpendicular to the centre serves for the azimuth moments.
    const Vec3 e1 = normalize(cross(centre, std::fabs(centre.x) < 0.9 ? Vec3{1, 0, 0}
                                                                       : Vec3{0, 1, 0}));
    const Vec3 e2 = cross(centre, e1);
    Rng rng(2024, d, 1, RandomStream::Direct);
    double sum_c = 0, sum_1 = 0, sum_2 = 0, inner = 0;
    for (int n = 0; n < N; ++n) {
      const Vec3 w = set.sample_direction(d, rng.uniform(), rng.uniform());
      const double c = dot(w, centre);
      sum_c += c;
      sum_1 += dot(w, e1);
      sum_2 += dot(w, e2);
      if (c >= std::cos(0.5 * a)) inner += 1.0;
    }
    const double sigma_c = (1.0 - ca) / std::sqrt(12.0 * N);
    EXPECT_NEAR(sum_c / N, 0.5 * (1.0 + ca), 4.0 * sigma_c);
    const double sin2 = 1.0 - (1.0 + ca + ca * ca) / 3.0;
    const double sigma_t = std::sqrt(sin2 / (2.0 * N));
    EXPECT_NEAR(sum_1 / N, 0.0, 4.0 * sigma_t);
    EXPECT_NEAR(sum_2 / N, 0.0, 4.0 * sigma_t);
    const double q = (1.0 - std::cos(0.5 * a)) / (1.0 - ca);
    EXPECT_NEAR(inner / N, q, 4.0 * std::sqrt(q * (1.0 - q) / N));
  }
}

TEST(SourceSet, RejectsBadDiscsAndIndices) {
  SourceSet set;
  EXPECT_THROW(set.add_sun_disc({0, 0, 0}, 0.01), std::invalid_argument);
  EXPECT_THROW(set.add_sun_disc({NAN, 0, 1}, 0.01), std::invalid_argument);
  EXPECT_THROW(set.add_sun_disc({0, 0, 1}, 0.0), std::invalid_argument);
  EXPECT_THROW(set.add_sun_disc({0, 0, 1}, -0.1), std::invalid_argument);
  EXPECT_THROW(set.add_sun_disc({0, 0, 1}, 4.0), std::invalid_argument);
  EXPECT_THROW(set.add_sun_disc({0, 0, 1}, NAN), std::invalid_argument);
  EXPECT_EQ(set.size(), 0u);
  EXPECT_THROW(set.sample_direction(0, 0.5, 0.5), std::out_of_range);
  EXPECT_THROW(set.contains(0, {0, 0, 1}), std::out_of_range);
  const SourceSet sky = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  EXPECT_THROW(sky.sample_direction(146, 0.5, 0.5), std::out_of_range);
}

}  // namespace
}  // namespace dayphoton::engine
