// Daylight factor from coefficients (study/daylight_factor.h): a hand-computed RGB case, the
// closed-form uniform-sky oracle (an unobstructed horizontal sensor has DF = 100 %), shape
// errors, and the grid statistics' conventions (median of even and odd counts, uniformity,
// thresholds counted with >=).
#include "dayphoton/study/daylight_factor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "dayphoton/core/units.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/sky/sky_model.h"

using namespace dayphoton;
using namespace dayphoton::study;

TEST(DaylightFactor, HandComputedRgbCase) {
  // 2 sensors x 3 bins. Sensor 0 sees bin 1 only, grey 0.5; sensor 1 sees the ground (bin 0)
  // in red and bin 2 in blue.
  RadianceMatrix c(2, 3), sky(3, 1);
  for (int k = 0; k < 3; ++k) c.at(0, 1, k) = 0.5f;
  c.at(1, 0, 0) = 1.0f;
  c.at(1, 2, 2) = 2.0f;
  for (int k = 0; k < 3; ++k) {
    sky.at(0, 0, k) = 2.0f;
    sky.at(1, 0, k) = 1.0f;
    sky.at(2, 0, k) = 1.0f;
  }
  // Sensor 0: 179 x 0.5 x (0.265 + 0.670 + 0.065) x 1 = 89.5 lx; sensor 1: 179 x (0.265 x 1 x 2
  // + 0.065 x 2 x 1) = 179 x 0.66 = 118.14 lx. E_h = 8950 lx.
  const std::vector<double> df = daylight_factor_percent(c, sky, 8950.0);
  ASSERT_EQ(df.size(), 2u);
  EXPECT_NEAR(df[0], 1.0, 1e-12);
  EXPECT_NEAR(df[1], 100.0 * 118.14 / 8950.0, 1e-12);
}

TEST(DaylightFactor, UnobstructedHorizontalSensorUnderAUniformSkyIs100Percent) {
  // The coefficient of an unobstructed upward sensor for a patch is its projected solid
  // angle, integral of cos(theta) d omega = (azimuth width) (sin^2 h1 - sin^2 h0) / 2, which
  // sums to pi over the hemisphere; a uniform sky of luminance L gives E = pi L = E_h.
  const sky::PatchBasis basis = sky::PatchBasis::tregenza();
  RadianceMatrix c(1, static_cast<std::size_t>(basis.bin_count()));
  double total = 0;
  for (int bin = 1; bin < basis.bin_count(); ++bin) {
    const sky::PatchBounds b = basis.bounds(bin);
    const double proj = (b.azimuth_max_rad - b.azimuth_min_rad) *
                        (std::pow(std::sin(b.altitude_max_rad), 2) - std::pow(std::sin(b.altitude_min_rad), 2)) / 2;
    total += proj;
    for (int k = 0; k < 3; ++k) c.at(0, static_cast<std::size_t>(bin), k) = static_cast<float>(proj);
  }
  ASSERT_NEAR(total, Pi, 1e-12);
  const auto uniform = sky::make_uniform_sky(10000.0 / Pi);
  const RadianceMatrix vector = sky::sky_vector(*uniform, basis, Vec3{0, 0, 0});
  const std::vector<double> df = daylight_factor_percent(c, vector, 10000.0);
  // Float storage of the coefficients and the vector: relative error ~1e-7 per element.
  EXPECT_NEAR(df[0], 100.0, 1e-4);
}

TEST(DaylightFactor, RejectsMismatchedShapesAndBadIlluminance) {
  RadianceMatrix c(2, 3), sky3(3, 1), sky4(4, 1), two_columns(3, 2), grey(3, 1, 1);
  EXPECT_THROW(daylight_factor_percent(c, sky4, 1000), std::invalid_argument);
  EXPECT_THROW(daylight_factor_percent(c, two_columns, 1000), std::invalid_argument);
  EXPECT_THROW(daylight_factor_percent(c, grey, 1000), std::invalid_argument);
  EXPECT_THROW(daylight_factor_percent(c, sky3, 0), std::invalid_argument);
  EXPECT_THROW(daylight_factor_percent(c, sky3, std::nan("")), std::invalid_argument);
  EXPECT_NO_THROW(daylight_factor_percent(c, sky3, 1000));
}

TEST(GridStatistics, OddCountMedianAndBasicStatistics) {
  const GridStatistics g = grid_statistics({4.0, 1.0, 3.0, 2.0, 5.0}, {});
  EXPECT_DOUBLE_EQ(g.mean, 3.0);
  EXPECT_DOUBLE_EQ(g.median, 3.0);
  EXPECT_DOUBLE_EQ(g.min, 1.0);
  EXPECT_DOUBLE_EQ(g.max, 5.0);
  EXPECT_DOUBLE_EQ(g.uniformity, 1.0 / 3.0);
  EXPECT_TRUE(g.area_at_or_above_percent.empty());
}

TEST(GridStatistics, EvenCountMedianIsTheMeanOfTheMiddlePair) {
  const GridStatistics g = grid_statistics({10.0, 1.0, 2.0, 4.0}, {});
  EXPECT_DOUBLE_EQ(g.median, 3.0);  // (2 + 4) / 2
  EXPECT_DOUBLE_EQ(g.mean, 4.25);
  EXPECT_DOUBLE_EQ(g.uniformity, 1.0 / 4.25);
}

TEST(GridStatistics, ValueExactlyAtTheThresholdCounts) {
  // 2.0 exactly meets ">= 2 %"; 1.9999 does not.
  const GridStatistics g = grid_statistics({1.9999, 2.0, 3.0, 0.5}, {2.0, 3.0, 3.0001, 0.0});
  ASSERT_EQ(g.area_at_or_above_percent.size(), 4u);
  EXPECT_DOUBLE_EQ(g.area_at_or_above_percent[0].first, 2.0);
  EXPECT_DOUBLE_EQ(g.area_at_or_above_percent[0].second, 50.0);
  EXPECT_DOUBLE_EQ(g.area_at_or_above_percent[1].second, 25.0);
  EXPECT_DOUBLE_EQ(g.area_at_or_above_percent[2].second, 0.0);
  EXPECT_DOUBLE_EQ(g.area_at_or_above_percent[3].second, 100.0);
}

TEST(GridStatistics, ZeroMeanGivesZeroUniformityAndEmptyOrNonFiniteThrows) {
  EXPECT_DOUBLE_EQ(grid_statistics({0.0, 0.0}, {}).uniformity, 0.0);
  EXPECT_THROW(grid_statistics({}, {2.0}), std::invalid_argument);
  EXPECT_THROW(grid_statistics({1.0, std::nan("")}, {}), std::invalid_argument);
}
