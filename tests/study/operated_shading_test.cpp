// Operated shading (study/operated_shading.h, LM-83-12 2.2.6) on synthetic tables whose
// answers are known exactly (no Monte Carlo, no tolerance):
// - the rule at its boundaries: exactly 2 % of the points sunlit stays open, one more point
//   shades; a sensor at exactly 1000 lx counts as sunlit, just below does not;
// - each hour takes the whole row of the chosen case (shaded or open), never a mix;
// - the operated metrics are those of the operated table, ASE those of the open case's direct
//   sun (not of the operated illuminance); shaded hours are counted in and out of occupancy;
// - shape mismatches throw; the schedule file has one exact row per step.
#include "dayphoton/study/operated_shading.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include "../temp_folder.h"

using namespace dayphoton;
using namespace dayphoton::study;
namespace fs = std::filesystem;

namespace {

/// One day, 24 hourly steps stamped at mid-hour (0.5 .. 23.5).
std::vector<metrics::TimeStamp> one_day() {
  std::vector<metrics::TimeStamp> steps;
  for (int h = 0; h < 24; ++h) steps.push_back({6, 21, h + 0.5});
  return steps;
}

metrics::IlluminanceTable filled(std::size_t sensors, float lux) {
  metrics::IlluminanceTable t(one_day(), sensors);
  for (std::size_t i = 0; i < t.step_count(); ++i)
    for (std::size_t s = 0; s < sensors; ++s) t.lux(i, s) = lux;
  return t;
}

TEST(OperatedShading, TwoPercentBoundaryIsStrict) {
  // 50 points: 1 sunlit is exactly 2 % (stays open), 2 are 4 %.
  EXPECT_FALSE(step_is_shaded(0, 50, 2.0));
  EXPECT_FALSE(step_is_shaded(1, 50, 2.0));
  EXPECT_TRUE(step_is_shaded(2, 50, 2.0));
  // 70 points (projects/blinds): 2 % is 1.4 points, so 1 stays open and 2 shade.
  EXPECT_FALSE(step_is_shaded(1, 70, 2.0));
  EXPECT_TRUE(step_is_shaded(2, 70, 2.0));
  // 100 points: 2 sunlit = 2 % exactly, open; 3 shade.
  EXPECT_FALSE(step_is_shaded(2, 100, 2.0));
  EXPECT_TRUE(step_is_shaded(3, 100, 2.0));
  // A limit of 0: any sunlit point shades; 100 %: never.
  EXPECT_TRUE(step_is_shaded(1, 1000, 0.0));
  EXPECT_FALSE(step_is_shaded(0, 1000, 0.0));
  EXPECT_FALSE(step_is_shaded(1000, 1000, 100.0));
}

TEST(OperatedShading, ThousandLuxCountsAsDirectSun) {
  metrics::IlluminanceTable direct = filled(50, 0.0f);
  direct.lux(10, 3) = 1000.0f;  // step 10: one point at exactly 1000 lx = 2 %: open
  direct.lux(11, 3) = 1000.0f;  // step 11: two points at exactly 1000 lx = 4 %: shaded
  direct.lux(11, 40) = 1000.0f;
  direct.lux(12, 3) = std::nextafter(1000.0f, 0.0f);  // step 12: two just below: not sunlit
  direct.lux(12, 40) = std::nextafter(1000.0f, 0.0f);
  for (std::size_t s = 0; s < 50; ++s) direct.lux(13, s) = 5e4f;  // step 13: all sunlit
  const ShadingSchedule sch = shading_schedule(direct, ShadingRule{});
  ASSERT_EQ(sch.shaded.size(), 24u);
  EXPECT_EQ(sch.sensors, 50u);
  EXPECT_EQ(sch.sunlit[10], 1u);
  EXPECT_EQ(sch.sunlit[11], 2u);
  EXPECT_EQ(sch.sunlit[12], 0u);
  EXPECT_EQ(sch.sunlit[13], 50u);
  for (std::size_t t = 0; t < 24; ++t) EXPECT_EQ(sch.shaded[t], (t == 11 || t == 13) ? 1 : 0) << "step " << t;
  EXPECT_EQ(sch.shaded_steps(), 2u);

  // Other thresholds follow the settings: at 999 lx step 12 is sunlit too.
  ShadingRule lower;
  lower.direct_sun_threshold_lux = 999.0;
  EXPECT_EQ(shading_schedule(direct, lower).shaded[12], 1);
}

TEST(OperatedShading, EachHourTakesTheWholeRowOfItsCase) {
  const std::size_t n = 5;
  metrics::IlluminanceTable open(one_day(), n), shaded(one_day(), n);
  for (std::size_t t = 0; t < 24; ++t)
    for (std::size_t s = 0; s < n; ++s) {
      open.lux(t, s) = float(1000 * t + s);
      shaded.lux(t, s) = -float(1000 * t + s) - 1;
    }
  ShadingSchedule sch;
  sch.sensors = n;
  sch.sunlit.assign(24, 0);
  sch.shaded.assign(24, 0);
  sch.shaded[0] = sch.shaded[9] = sch.shaded[23] = 1;
  const metrics::IlluminanceTable op = operated_illuminance(open, shaded, sch);
  ASSERT_EQ(op.step_count(), 24u);
  ASSERT_EQ(op.sensor_count(), n);
  for (std::size_t t = 0; t < 24; ++t)
    for (std::size_t s = 0; s < n; ++s)
      EXPECT_EQ(op.lux(t, s), sch.shaded[t] ? shaded.lux(t, s) : open.lux(t, s)) << t << "," << s;
  EXPECT_EQ(op.steps()[9].hour, 9.5);
}

TEST(OperatedShading, MetricsFromTheOperatedTableAseFromTheOpenDirectSun) {
  const std::size_t n = 50;
  // Open: 500 lx all day; shaded: 100 lx. Direct sun (open case): points 0 and 1 at 2000 lx
  // in the occupied steps 10..13 (hours 10.5..13.5) and at 6.5 (unoccupied): shaded there.
  const metrics::IlluminanceTable open = filled(n, 500.0f), shaded = filled(n, 100.0f);
  metrics::IlluminanceTable direct = filled(n, 0.0f);
  for (std::size_t t : {6u, 10u, 11u, 12u, 13u})
    for (std::size_t s : {0u, 1u}) direct.lux(t, s) = 2000.0f;
  AnnualStudySettings settings;  // occupancy 8-18: steps 8..17, 10 hours
  settings.metrics.ase_hours = 3;  // points 0 and 1 have 4 occupied direct-sun hours: fail
  const std::vector<double> quantity(24, 1.0);
  const OperatedStudy r =
      compute_operated_study(open, shaded, direct, ShadingRule{}, settings, quantity, "test quantity", "synthetic");

  EXPECT_EQ(r.schedule.shaded_steps(), 5u);
  EXPECT_EQ(r.shaded_occupied_hours, 4u);
  EXPECT_EQ(r.study.occupied_hours, 10u);
  EXPECT_EQ(r.study.sky_description, "synthetic");
  // DA300 of every sensor: 6 of 10 occupied hours at 500 lx, 4 shaded at 100 lx.
  ASSERT_EQ(r.study.sensors.size(), n);
  for (const metrics::SensorMetrics& m : r.study.sensors) {
    EXPECT_DOUBLE_EQ(m.da_percent, 60.0);
    EXPECT_DOUBLE_EQ(m.udi_below_percent, 0.0);
    EXPECT_DOUBLE_EQ(m.mean_occupied_lux, (6 * 500.0 + 4 * 100.0) / 10.0);
  }
  EXPECT_DOUBLE_EQ(r.study.grid.sda_percent, 100.0);
  // ASE from the open direct sun: 2 of 50 points fail = 4 %. The operated illuminance never
  // reaches 1000 lx, so an ASE taken from it would be 0.
  ASSERT_EQ(r.study.ase_hours.size(), n);
  EXPECT_EQ(r.study.ase_hours[0], 4);
  EXPECT_EQ(r.study.ase_hours[2], 0);
  EXPECT_DOUBLE_EQ(r.study.grid.ase_percent, 4.0);
  EXPECT_EQ(r.study.grid.en17037.size(), 3u);

  // The JSON summary carries the counts and the cases.
  const nlohmann::json j = nlohmann::json::parse(operation_json(r, ShadingRule{}, "raised", "closed"));
  EXPECT_EQ(j["open"], "raised");
  EXPECT_EQ(j["shaded"], "closed");
  EXPECT_EQ(j["shaded_hours"], 5);
  EXPECT_EQ(j["shaded_occupied_hours"], 4);
  EXPECT_EQ(j["occupied_hours"], 10);
  EXPECT_EQ(j["sunlit_limit_percent"], 2.0);
  EXPECT_EQ(j["direct_sun_threshold_lux"], 1000.0);

  // With one sunlit point (2 %) nothing is shaded and the operated table is the open one.
  metrics::IlluminanceTable one = filled(n, 0.0f);
  for (std::size_t t : {10u, 11u}) one.lux(t, 0) = 2000.0f;
  const OperatedStudy r1 = compute_operated_study(open, shaded, one, ShadingRule{}, settings, {}, "", "");
  EXPECT_EQ(r1.schedule.shaded_steps(), 0u);
  for (const metrics::SensorMetrics& m : r1.study.sensors) EXPECT_DOUBLE_EQ(m.da_percent, 100.0);
  EXPECT_TRUE(r1.study.grid.en17037.empty());
}

TEST(OperatedShading, ShapeMismatchesThrow) {
  const metrics::IlluminanceTable a = filled(4, 1.0f), b = filled(5, 1.0f);
  const ShadingSchedule sch = shading_schedule(a, ShadingRule{});
  EXPECT_THROW(operated_illuminance(a, b, sch), std::invalid_argument);
  EXPECT_THROW(operated_illuminance(b, b, sch), std::invalid_argument);
  EXPECT_THROW(compute_operated_study(a, a, b, ShadingRule{}, AnnualStudySettings{}, {}, "", ""),
               std::invalid_argument);
  EXPECT_THROW(compute_operated_study(a, a, a, ShadingRule{}, AnnualStudySettings{}, std::vector<double>(3, 1.0), "", ""),
               std::invalid_argument);
}

TEST(OperatedShading, ScheduleFileHasOneRowPerStep) {
  const std::size_t n = 50;
  metrics::IlluminanceTable direct = filled(n, 0.0f);
  direct.lux(9, 0) = direct.lux(9, 1) = 1500.0f;  // hour 9.5, occupied, 4 %: shaded
  direct.lux(20, 0) = 1500.0f;                     // hour 20.5, unoccupied, 2 %: open
  const OperatedStudy r = compute_operated_study(filled(n, 10.0f), filled(n, 5.0f), direct, ShadingRule{},
                                                 AnnualStudySettings{}, {}, "", "");
  const fs::path dir = test::process_temp_dir() / "operated_shading_test";
  fs::create_directories(dir);
  const std::string path = (dir / "shading_schedule.csv").string();
  write_shading_schedule_csv(r, path);
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 25u);
  EXPECT_EQ(lines[0], "month,day,hour,occupied,sunlit_sensors,sunlit_percent,shaded");
  EXPECT_EQ(lines[1], "6,21,0.5,0,0,0.000,0");
  EXPECT_EQ(lines[10], "6,21,9.5,1,2,4.000,1");
  EXPECT_EQ(lines[21], "6,21,20.5,0,1,2.000,0");
  fs::remove_all(dir);
}

}  // namespace
