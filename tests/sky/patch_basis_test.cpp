// Patch basis tests: counts and solid angles against ../shared/facts/sky-and-metrics.md
// section 4.1-4.2 (tables and ladybug's coefficient lists quoted there), RADIANCE's
// orientation (patch 2 east of north), the cal files' bin rule, and sampling (consistency
// and chi-square uniformity, fixed seeds).
#include "dayphoton/sky/patch_basis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "dayphoton/core/units.h"

using namespace dayphoton;
using namespace dayphoton::sky;

namespace {

Vec3 dir(double alt_deg, double az_deg) {
  const double a = deg_to_rad(alt_deg), z = deg_to_rad(az_deg);
  return {std::cos(a) * std::sin(z), std::cos(a) * std::cos(z), std::sin(a)};
}

// Upper 0.999 quantile of chi-square with df degrees of freedom (Wilson-Hilferty; accurate
// to <0.5 % for df > 30, which is all we use).
double chi2_critical_999(int df) {
  const double z = 3.090232;  // standard normal 0.999 quantile
  const double k = 2.0 / (9.0 * df);
  return df * std::pow(1.0 - k + z * std::sqrt(k), 3.0);
}

}  // namespace

TEST(PatchBasisTest, Counts) {
  EXPECT_EQ(PatchBasis::tregenza().bin_count(), 146);
  for (int mf : {1, 2, 4, 6}) {
    const PatchBasis b = PatchBasis::reinhart(mf);
    EXPECT_EQ(b.bin_count(), 144 * mf * mf + 2);
    EXPECT_EQ(b.row_count(), 7 * mf + 1);
    EXPECT_EQ(b.row(b.row_count() - 1).first_bin, 144 * mf * mf + 1);  // cap last
  }
  EXPECT_THROW(PatchBasis::reinhart(0), std::invalid_argument);
  EXPECT_THROW(PatchBasis::tregenza().solid_angle_sr(146), std::out_of_range);
}

TEST(PatchBasisTest, SolidAnglesSumToHemisphere) {
  for (int mf : {1, 2, 4, 6}) {
    const PatchBasis b = PatchBasis::reinhart(mf);
    double sum = 0.0;
    for (int i = 1; i < b.bin_count(); ++i) sum += b.solid_angle_sr(i);
    EXPECT_NEAR(sum, 2.0 * Pi, 1e-12) << "MF " << mf;
    EXPECT_DOUBLE_EQ(b.solid_angle_sr(0), 2.0 * Pi);
  }
}

// Facts 4.1: Tregenza bands (first index, count, per-patch solid angle). The ladybug
// coefficients are printed to 10 decimals: tolerance 1e-9 sr.
TEST(PatchBasisTest, TregenzaBandTable) {
  const PatchBasis t = PatchBasis::tregenza();
  const int first[8] = {1, 31, 61, 85, 109, 127, 139, 145};
  const int count[8] = {30, 30, 24, 24, 18, 12, 6, 1};
  const double omega[8] = {0.0435449227, 0.0416418006, 0.0473984151, 0.0406730411,
                           0.0428934136, 0.0445221864, 0.0455168385, 0.0344199465};
  ASSERT_EQ(t.row_count(), 8);
  for (int r = 0; r < 8; ++r) {
    EXPECT_EQ(t.row(r).first_bin, first[r]);
    EXPECT_EQ(t.row(r).patch_count, count[r]);
    EXPECT_NEAR(rad_to_deg(t.row(r).altitude_min_rad), 12.0 * r, 1e-12);
    for (int j = 0; j < count[r]; ++j) EXPECT_NEAR(t.solid_angle_sr(first[r] + j), omega[r], 1e-9);
  }
  EXPECT_NEAR(rad_to_deg(t.row_height_rad()), 12.0, 1e-12);
}

// Facts 4.2: MF 2 rows (first index, count, per-patch solid angle printed to 8 decimals).
TEST(PatchBasisTest, ReinhartMf2RowTable) {
  const PatchBasis b = PatchBasis::reinhart(2);
  const int first[15] = {1, 61, 121, 181, 241, 289, 337, 385, 433, 469, 505, 529, 553, 565, 577};
  const int count[15] = {60, 60, 60, 60, 48, 48, 48, 48, 36, 36, 24, 24, 12, 12, 1};
  const double omega[15] = {0.01132220, 0.01118945, 0.01092553, 0.01053351, 0.01252249,
                            0.01173128, 0.01080253, 0.00974713, 0.01143661, 0.00974296,
                            0.01190262, 0.00905126, 0.01218756, 0.00612971, 0.00921483};
  for (int r = 0; r < 15; ++r) {
    SCOPED_TRACE(r);
    EXPECT_EQ(b.row(r).first_bin, first[r]);
    EXPECT_EQ(b.row(r).patch_count, count[r]);
    EXPECT_NEAR(b.solid_angle_sr(first[r]), omega[r], 1e-8);
  }
  EXPECT_NEAR(rad_to_deg(b.row_height_rad()), 6.206897, 1e-6);
}

// Facts 4.2: MF 4 and MF 6 spot values and zenith caps (printed to 6-8 decimals).
TEST(PatchBasisTest, ReinhartMf4Mf6SpotValues) {
  const PatchBasis b4 = PatchBasis::reinhart(4);
  EXPECT_NEAR(b4.solid_angle_sr(1), 0.00288439, 1e-8);
  EXPECT_EQ(b4.row(27).patch_count, 24);
  EXPECT_NEAR(b4.solid_angle_sr(b4.row(27).first_bin), 0.00079477, 1e-8);
  EXPECT_EQ(b4.row(8).patch_count, 96);
  EXPECT_EQ(b4.row(16).patch_count, 72);
  EXPECT_NEAR(b4.solid_angle_sr(2305), 0.002386, 1e-6);
  const PatchBasis b6 = PatchBasis::reinhart(6);
  EXPECT_NEAR(b6.solid_angle_sr(5185), 0.001073, 1e-6);
  EXPECT_NEAR(rad_to_deg(b6.row_height_rad()), 2.117647, 1e-6);
  EXPECT_NEAR(PatchBasis::tregenza().solid_angle_sr(145), 0.034420, 1e-6);
  EXPECT_NEAR(PatchBasis::reinhart(2).solid_angle_sr(577), 0.009215, 1e-6);
}

// Facts 4.1 orientation: patch 1 centred on north, patch 2 12 deg toward EAST (the code,
// not the gendaymtx man page). A sun due east at 30 deg altitude is in band 3 (24 patches
// of 15 deg, first index 61): 61 + 90/15 = 67; due west: 61 + 270/15 = 79.
TEST(PatchBasisTest, OrientationAndDueEastSun) {
  const PatchBasis t = PatchBasis::tregenza();
  EXPECT_NEAR(t.centre(1).x, 0.0, 1e-15);
  EXPECT_GT(t.centre(1).y, 0.0);
  EXPECT_GT(t.centre(2).x, 0.0);  // east
  EXPECT_EQ(t.find_bin(dir(6, 12)), 2);
  EXPECT_EQ(t.find_bin(dir(6, -12)), 30);
  EXPECT_EQ(t.find_bin(dir(30, 90)), 67);
  EXPECT_EQ(t.find_bin(dir(30, 270)), 79);
  EXPECT_EQ(t.find_bin(dir(42, 90)), 85 + 6);
  EXPECT_EQ(t.find_bin(Vec3{1.0, 0.0, std::tan(deg_to_rad(30.0))}), 67);  // not unit length
  EXPECT_EQ(t.find_bin(Vec3{0, 0, 1}), 145);
  EXPECT_EQ(t.find_bin(dir(84.5, 200)), 145);
  EXPECT_EQ(t.find_bin(Vec3{0.3, 0.2, -0.01}), 0);
  EXPECT_EQ(t.find_bin(Vec3{0, -1, 0}), 1 + 15);  // horizon belongs to the sky (alt >= 0)
  // Patch 1 spans -6..+6 deg: the west edge of patch 30 at 354 deg.
  EXPECT_EQ(t.find_bin(dir(6, 353.9)), 30);
  EXPECT_EQ(t.find_bin(dir(6, 354.1)), 1);
  EXPECT_EQ(t.find_bin(dir(6, 5.9)), 1);
  EXPECT_EQ(t.find_bin(dir(6, 6.1)), 2);
  // The cal files' wrap test (359.9999 - inc/2): [353.9999, 354) already goes to patch 1.
  EXPECT_EQ(t.find_bin(dir(6, 353.99995)), 1);
  EXPECT_EQ(t.find_bin(dir(6, 353.9998)), 30);
}

TEST(PatchBasisTest, CentresAndBoundsAreConsistent) {
  for (int mf : {1, 2, 4, 6}) {
    const PatchBasis b = PatchBasis::reinhart(mf);
    for (int i = 0; i < b.bin_count(); ++i) {
      ASSERT_EQ(b.find_bin(b.centre(i)), i) << "MF " << mf << " bin " << i;
      const PatchBounds bd = b.bounds(i);
      const Vec3 c = b.centre(i);
      if (i > 0 && b.row(b.row_of_bin(i)).patch_count > 1) {
        EXPECT_NEAR(std::asin(c.z), 0.5 * (bd.altitude_min_rad + bd.altitude_max_rad), 1e-12);
        double az = std::atan2(c.x, c.y);
        if (i != b.row(b.row_of_bin(i)).first_bin && az < 0) az += 2.0 * Pi;
        EXPECT_NEAR(az, 0.5 * (bd.azimuth_min_rad + bd.azimuth_max_rad), 1e-12);
      }
      // Solid angle from the bounds.
      const double omega = (bd.azimuth_max_rad - bd.azimuth_min_rad) *
                            (std::sin(bd.altitude_max_rad) - std::sin(bd.altitude_min_rad));
      EXPECT_NEAR(omega, b.solid_angle_sr(i), 1e-12);
    }
  }
}

TEST(PatchBasisTest, SamplesLandInTheirBin) {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int mf : {1, 2, 4}) {
    const PatchBasis b = PatchBasis::reinhart(mf);
    for (int i = 0; i < b.bin_count(); ++i)
      for (int k = 0; k < 64; ++k) {
        const Vec3 d = b.sample_direction(i, u(rng), u(rng));
        ASSERT_NEAR(length(d), 1.0, 1e-12);
        ASSERT_EQ(b.find_bin(d), i) << "MF " << mf << " bin " << i;
      }
  }
}

// Uniform directions on the sphere land in bin b with probability Omega_b / (4 pi) (ground
// 1/2): a chi-square test over all bins checks find_bin against solid_angle_sr, including
// the row boundaries and azimuth offsets. 2e6 samples, fixed seed, alpha = 0.001.
TEST(PatchBasisTest, FindBinFrequenciesMatchSolidAngles) {
  for (int mf : {1, 2}) {
    const PatchBasis b = PatchBasis::reinhart(mf);
    std::mt19937_64 rng(12345 + mf);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int n = 2000000;
    std::vector<double> count(static_cast<std::size_t>(b.bin_count()), 0.0);
    for (int k = 0; k < n; ++k) {
      const double z = 2.0 * u(rng) - 1.0, phi = 2.0 * Pi * u(rng);
      const double r = std::sqrt(1.0 - z * z);
      count[static_cast<std::size_t>(b.find_bin({r * std::cos(phi), r * std::sin(phi), z}))] += 1;
    }
    double chi2 = 0.0;
    for (int i = 0; i < b.bin_count(); ++i) {
      const double expected = n * b.solid_angle_sr(i) / (4.0 * Pi);
      const double diff = count[static_cast<std::size_t>(i)] - expected;
      chi2 += diff * diff / expected;
    }
    EXPECT_LT(chi2, chi2_critical_999(b.bin_count() - 1)) << "MF " << mf;
  }
}

// sample_direction is uniform in solid angle: bin the returned directions on an 8 x 8 grid
// of equal solid angle (uniform in sin altitude and in azimuth over the bin's bounds),
// 25 600 samples (400 expected per cell), chi-square with 63 dof at alpha = 0.001.
// Bins tried: the north patch (azimuth wraps through 0), an east patch, an MF 4 patch,
// the zenith cap and the ground.
TEST(PatchBasisTest, SampleDirectionChiSquareUniform) {
  struct Case {
    int mf, bin;
  } cases[] = {{1, 1}, {1, 67}, {1, 145}, {1, 0}, {4, 1000}, {2, 505}};
  for (const Case& c : cases) {
    const PatchBasis b = PatchBasis::reinhart(c.mf);
    const PatchBounds bd = b.bounds(c.bin);
    std::mt19937_64 rng(777 + c.bin);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int grid = 8, n = 25600;
    std::vector<double> cells(grid * grid, 0.0);
    const double z0 = std::sin(bd.altitude_min_rad), z1 = std::sin(bd.altitude_max_rad);
    for (int k = 0; k < n; ++k) {
      const Vec3 d = b.sample_direction(c.bin, u(rng), u(rng));
      double az = std::atan2(d.x, d.y);
      while (az < bd.azimuth_min_rad) az += 2.0 * Pi;
      while (az >= bd.azimuth_max_rad) az -= 2.0 * Pi;
      const int iz = std::min(grid - 1, static_cast<int>((d.z - z0) / (z1 - z0) * grid));
      const int ia = std::min(grid - 1, static_cast<int>((az - bd.azimuth_min_rad) /
                                                          (bd.azimuth_max_rad - bd.azimuth_min_rad) * grid));
      ASSERT_GE(iz, 0);
      ASSERT_GE(ia, 0);
      cells[static_cast<std::size_t>(iz * grid + ia)] += 1;
    }
    const double expected = static_cast<double>(n) / (grid * grid);
    double chi2 = 0.0;
    for (double o : cells) chi2 += (o - expected) * (o - expected) / expected;
    EXPECT_LT(chi2, chi2_critical_999(grid * grid - 1)) << "MF " << c.mf << " bin " << c.bin;
    EXPECT_DOUBLE_EQ(b.pdf_sr(c.bin), 1.0 / b.solid_angle_sr(c.bin));
  }
}
