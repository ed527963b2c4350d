// Verdict uncertainty (study/verdict_uncertainty.h) on a hand-built year of 24 hours: one sky
// patch of radiance L, sensors whose hourly illuminance and standard error are set by hand.
#include "dayphoton/study/verdict_uncertainty.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dayphoton/core/units.h"

namespace dayphoton::study {
namespace {

TEST(VerdictUncertainty, SensorsWithinTwoSigmaOfTheDaVerdictAreCounted) {
  constexpr std::size_t Steps = 24;
  const double radiance = 50.0;  // W/(sr m^2), grey
  AnnualSky sky;
  sky.matrix = RadianceMatrix(1, Steps, 3);
  for (std::size_t t = 0; t < Steps; ++t) {
    sky.steps.push_back({1, 1, double(t) + 0.5});  // occupied 08:00-18:00: 10 hours
    for (int c = 0; c < 3; ++c) sky.matrix.at(0, t, c) = static_cast<float>(radiance);
  }
  AnnualStudySettings settings;  // DA300, sDA fraction 50 %
  // Standard error 10 lux at every sensor: variance of the coefficient's luminance
  // (10 / (179 L))^2.
  const double sigma_lux = 10.0;
  const double v = std::pow(sigma_lux / (RadianceWhiteEfficacy_lm_per_W * radiance), 2);
  // Sensor 0 at 310 lx every hour: 2 sigma below is 290 (DA 0 %), above 330 (DA 100 %): open.
  // Sensor 1 at 400 lx: 380 .. 420, DA 100 % either way. Sensor 2 at 310 lx in 4 of the 10
  // occupied hours and 400 in the others: DA 60 % .. 100 %, passes either way.
  AnnualStudy study;
  study.illuminance = metrics::IlluminanceTable(sky.steps, 3);
  int occupied = 0;
  for (std::size_t t = 0; t < Steps; ++t) {
    const bool in = sky.steps[t].hour >= 8 && sky.steps[t].hour < 18;
    study.illuminance.lux(t, 0) = 310.0f;
    study.illuminance.lux(t, 1) = 400.0f;
    study.illuminance.lux(t, 2) = in && occupied < 4 ? 310.0f : 400.0f;
    occupied += in ? 1 : 0;
  }
  const VerdictUncertainty u = verdict_uncertainty(study, sky, {v, v, v}, nullptr, settings);
  EXPECT_EQ(u.da_verdicts_uncertain, 1u);
  EXPECT_NEAR(u.mean_occupied_stderr_lux, sigma_lux, 1e-9);
  // Half the standard error: sensor 0's band 300 .. 320 still reaches the threshold
  // ("at least" 300 lx), so no verdict is open.
  const VerdictUncertainty half = verdict_uncertainty(study, sky, {v / 4, v / 4, v / 4}, nullptr, settings);
  EXPECT_EQ(half.da_verdicts_uncertain, 0u);
  EXPECT_THROW(verdict_uncertainty(study, sky, {v, v}, nullptr, settings), std::invalid_argument);
}

}  // namespace
}  // namespace dayphoton::study
