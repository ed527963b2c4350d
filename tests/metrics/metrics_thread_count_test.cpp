// The per-sensor metrics, the ASE hours and EN 17037 are computed over blocks of sensors in
// parallel (metrics/src/annual_metrics.cpp): every value must be the one a sensor alone gives
// (a one-sensor table) and the same bytes for one thread and for several.
#include "dayphoton/metrics/annual_metrics.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cstring>
#include <random>

using namespace dayphoton::metrics;

namespace {

constexpr std::size_t Sensors = 1500, Steps = 400;  // several blocks of 256 sensors

IlluminanceTable random_table(unsigned seed) {
  std::vector<TimeStamp> steps;
  for (std::size_t t = 0; t < Steps; ++t) steps.push_back({1 + int(t / 24 / 28) % 12, 1 + int(t / 24) % 28, double(t % 24) + 0.5});
  IlluminanceTable table(steps, Sensors);
  std::mt19937 random(seed);
  // Each sensor's values up to its own scale (100 to 2,000 lux), so that its median falls
  // below some EN 17037 targets and above others.
  std::uniform_real_distribution<float> fraction(0.0f, 1.0f);
  for (std::size_t t = 0; t < Steps; ++t)
    for (std::size_t s = 0; s < Sensors; ++s) table.lux(t, s) = float(100 + s * 37 % 1900) * fraction(random);
  return table;
}

OccupancySchedule every_other_hour_and_then_some() {
  std::vector<bool> occupied(Steps);
  for (std::size_t t = 0; t < Steps; ++t) occupied[t] = t % 2 == 0 || t % 7 == 3;
  return OccupancySchedule(occupied);
}

struct Results {
  std::vector<SensorMetrics> sensors;
  std::vector<int> ase;
  std::vector<En17037Result> en17037;
};

Results compute(const IlluminanceTable& table, const OccupancySchedule& occupancy, std::size_t threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  std::vector<double> weights(table.sensor_count());
  for (std::size_t s = 0; s < weights.size(); ++s) weights[s] = 0.5 + double(s % 5);
  return {compute_sensor_metrics(table, occupancy), ase_hours_per_sensor(table, occupancy),
          en17037_daylight_provision(table, occupancy, weights)};
}

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

}  // namespace

TEST(MetricsThreadCount, OneThreadAndSeveralGiveTheSameBytes) {
  const IlluminanceTable table = random_table(17);
  const OccupancySchedule occupancy = every_other_hour_and_then_some();
  const Results one = compute(table, occupancy, 1), several = compute(table, occupancy, 4);
  EXPECT_TRUE(same_bytes(one.sensors, several.sensors));
  EXPECT_TRUE(same_bytes(one.ase, several.ase));
  ASSERT_EQ(one.en17037.size(), several.en17037.size());
  for (std::size_t l = 0; l < one.en17037.size(); ++l) {
    EXPECT_EQ(one.en17037[l].target_area_percent, several.en17037[l].target_area_percent);
    EXPECT_EQ(one.en17037[l].minimum_target_area_percent, several.en17037[l].minimum_target_area_percent);
    EXPECT_EQ(one.en17037[l].passes, several.en17037[l].passes);
  }
  // The random table is not degenerate: the levels split the sensors (none all or nothing).
  EXPECT_GT(one.en17037[0].target_area_percent, 0.0);
  EXPECT_LT(one.en17037[2].target_area_percent, 100.0);
}

TEST(MetricsThreadCount, EverySensorHasTheValuesItHasAlone) {
  const IlluminanceTable table = random_table(5);
  const OccupancySchedule occupancy = every_other_hour_and_then_some();
  const std::vector<SensorMetrics> all = compute_sensor_metrics(table, occupancy);
  const std::vector<int> ase = ase_hours_per_sensor(table, occupancy);
  for (std::size_t s : {std::size_t(0), std::size_t(255), std::size_t(256), std::size_t(1000), Sensors - 1}) {
    IlluminanceTable alone(table.steps(), 1);
    for (std::size_t t = 0; t < Steps; ++t) alone.lux(t, 0) = table.lux(t, s);
    const std::vector<SensorMetrics> one = compute_sensor_metrics(alone, occupancy);
    EXPECT_EQ(std::memcmp(&one[0], &all[s], sizeof(SensorMetrics)), 0) << "sensor " << s;
    EXPECT_EQ(ase_hours_per_sensor(alone, occupancy)[0], ase[s]) << "sensor " << s;
  }
}
