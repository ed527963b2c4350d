// Verdict uncertainty (study/verdict_uncertainty.h) on a hand-built year of 24 hours: one sky
// patch of radiance L, sensors whose hourly illuminance and standard error are set by hand.
#include "dayphoton/study/verdict_uncertainty.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/metrics/occupancy.h"

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
  EXPECT_FALSE(u.da_verdicts_uncertain_area_percent);  // equal shares: the count's share
  EXPECT_NEAR(u.mean_occupied_stderr_lux, sigma_lux, 1e-9);
  // Sensors standing for 0.2, 1 and 1 m^2 (a Honeybee mesh's column of trimmed cells): the
  // open verdict is 0.2 / 2.2 of the area, the most sDA can move by.
  AnnualStudySettings weighted = settings;
  weighted.sensor_area_m2 = {0.2, 1.0, 1.0};
  const VerdictUncertainty w = verdict_uncertainty(study, sky, {v, v, v}, nullptr, weighted);
  EXPECT_EQ(w.da_verdicts_uncertain, 1u);
  ASSERT_TRUE(w.da_verdicts_uncertain_area_percent);
  EXPECT_NEAR(*w.da_verdicts_uncertain_area_percent, 100.0 * 0.2 / 2.2, 1e-12);
  weighted.sensor_area_m2 = {1.0, 1.0};
  EXPECT_THROW(verdict_uncertainty(study, sky, {v, v, v}, nullptr, weighted), std::invalid_argument);
  // Half the standard error: sensor 0's band 300 .. 320 still reaches the threshold
  // ("at least" 300 lx), so no verdict is open.
  const VerdictUncertainty half = verdict_uncertainty(study, sky, {v / 4, v / 4, v / 4}, nullptr, settings);
  EXPECT_EQ(half.da_verdicts_uncertain, 0u);
  EXPECT_THROW(verdict_uncertainty(study, sky, {v, v}, nullptr, settings), std::invalid_argument);
}


/// The hourly variance table of every sensor, as the verdicts were first computed (a steps x
/// sensors table): the reference the blocked computation must equal exactly.
VerdictUncertainty reference(const AnnualStudy& study, const AnnualSky& sky, const std::vector<double>& sky_variance,
                             const SunBinVariance& sun, const AnnualStudySettings& settings) {
  const std::size_t n_steps = study.illuminance.step_count(), n_sensors = study.illuminance.sensor_count();
  const std::size_t bins = sky.matrix.rows();
  const double efficacy2 = RadianceWhiteEfficacy_lm_per_W * RadianceWhiteEfficacy_lm_per_W;
  const metrics::OccupancySchedule occupancy = occupancy_schedule(settings, sky.steps);
  std::vector<double> variance(n_steps * n_sensors, 0.0), radiance2(bins);
  for (std::size_t t = 0; t < n_steps; ++t) {
    if (!occupancy.occupied(t)) continue;
    for (std::size_t p = 0; p < bins; ++p) {
      const double l = RgbLuminanceWeights.x * sky.matrix.at(p, t, 0) + RgbLuminanceWeights.y * sky.matrix.at(p, t, 1) +
                       RgbLuminanceWeights.z * sky.matrix.at(p, t, 2);
      radiance2[p] = l * l;
    }
    for (std::size_t s = 0; s < n_sensors; ++s) {
      double v = 0;
      for (std::size_t p = 0; p < bins; ++p) v += radiance2[p] * sky_variance[s * bins + p];
      variance[t * n_sensors + s] = efficacy2 * v;
    }
  }
  const std::size_t n_bins = sun.bins->size();
  for (const sky::SunRecord& record : *sun.suns) {
    if (!occupancy.occupied(record.step)) continue;
    const engine::SunStencil st = sun.bins->weights(record.direction);
    for (std::size_t s = 0; s < n_sensors; ++s) {
      double v = 0;
      for (int k = 0; k < st.count; ++k)
        v += st.weight[k] * st.weight[k] * (*sun.variance)[s * n_bins + std::size_t(st.index[k])];
      variance[record.step * n_sensors + s] += efficacy2 * record.disc_radiance * record.disc_radiance * v;
    }
  }
  VerdictUncertainty out;
  const std::size_t occupied = occupancy.occupied_count();
  double sum_variance = 0;
  for (std::size_t s = 0; s < n_sensors; ++s) {
    std::size_t low = 0, high = 0;
    for (std::size_t t = 0; t < n_steps; ++t) {
      if (!occupancy.occupied(t)) continue;
      const double e = study.illuminance.lux(t, s), v = variance[t * n_sensors + s];
      const double band = VerdictSigmas * std::sqrt(v);
      low += e - band >= settings.metrics.da_threshold_lux ? 1 : 0;
      high += e + band >= settings.metrics.da_threshold_lux ? 1 : 0;
      sum_variance += v;
    }
    const double need = settings.metrics.sda_time_fraction * double(occupied);
    if ((double(low) >= need) != (double(high) >= need)) ++out.da_verdicts_uncertain;
  }
  out.mean_occupied_stderr_lux = std::sqrt(sum_variance / (double(occupied) * double(n_sensors)));
  return out;
}

TEST(VerdictUncertainty, BlocksOfSensorsGiveTheValuesOfTheWholeHourlyTable) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  constexpr std::size_t Steps = 72, Sensors = 53, Bins = 5;
  AnnualSky sky;
  sky.matrix = RadianceMatrix(Bins, Steps, 3);
  for (std::size_t t = 0; t < Steps; ++t) sky.steps.push_back({3, int(1 + t / 24), double(t % 24) + 0.5});
  for (float& v : sky.matrix.data()) v = float(40.0 * u(random));
  AnnualStudy study;
  study.illuminance = metrics::IlluminanceTable(sky.steps, Sensors);
  for (std::size_t t = 0; t < Steps; ++t)
    for (std::size_t s = 0; s < Sensors; ++s) study.illuminance.lux(t, s) = float(250.0 + 100.0 * u(random));
  std::vector<double> sky_variance(Sensors * Bins);
  for (double& v : sky_variance) v = 1e-3 * u(random);
  std::vector<sky::SunRecord> suns;
  std::vector<Vec3> directions;
  for (std::size_t k = 0; k < 20; ++k) {
    sky::SunRecord sun;
    sun.step = 24 * (k / 7) + 8 + k % 7;
    const double alt = 0.3 + u(random), az = 6.28 * u(random);
    sun.direction = Vec3{std::cos(alt) * std::sin(az), std::cos(alt) * std::cos(az), std::sin(alt)};
    sun.disc_radiance = 1e3 * u(random);
    suns.push_back(sun);
    directions.push_back(sun.direction);
  }
  const engine::SunBins bins = engine::SunBins::for_suns(directions, 1);
  std::vector<float> sun_variance(Sensors * bins.size());
  for (float& v : sun_variance) v = float(1e-9 * u(random));
  const SunBinVariance sun{&sun_variance, &bins, &suns};
  AnnualStudySettings settings;
  const VerdictUncertainty expected = reference(study, sky, sky_variance, sun, settings);
  EXPECT_GT(expected.da_verdicts_uncertain, 0u);
  for (std::size_t block_values : {std::size_t(1), std::size_t(30 * 7), VerdictSensorBlockValues}) {
    const VerdictUncertainty got = verdict_uncertainty(study, sky, sky_variance, &sun, settings, block_values);
    EXPECT_EQ(got.da_verdicts_uncertain, expected.da_verdicts_uncertain) << block_values;
    EXPECT_EQ(got.mean_occupied_stderr_lux, expected.mean_occupied_stderr_lux) << block_values;
  }
}

}  // namespace
}  // namespace dayphoton::study
