// The metric settings `dayphoton annual` takes from a run's results.json: every kind of
// occupancy plan survives the results model (builder -> JSON -> reader -> plan) with the same
// occupied hours, the thresholds too; an hourly plan that does not fit another weather file is
// an error located at results.json; a grid folder finds its run's record (a variant's too).
#include "dayphoton/study/recorded_metric_settings.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/study/results_model_builder.h"

using namespace dayphoton;
using namespace dayphoton::study;
namespace fs = std::filesystem;

namespace {

/// The mid-hour stamps of a year of 365 days.
std::vector<metrics::TimeStamp> year_steps() {
  constexpr int DaysInMonth[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  std::vector<metrics::TimeStamp> steps;
  for (int m = 1; m <= 12; ++m)
    for (int d = 1; d <= DaysInMonth[m - 1]; ++d)
      for (int h = 0; h < 24; ++h) steps.push_back({m, d, h + 0.5});
  return steps;
}

/// The annual summary the run records for `settings` (results_model_builder's add_annual),
/// written to results.json text and read back.
AnnualSummary recorded(const AnnualStudySettings& settings) {
  AnnualStudy study;
  study.illuminance = metrics::IlluminanceTable(year_steps(), 1);
  study.sensors.resize(1);
  GridResult grid;
  grid.name = "desks";
  grid.folder = "desks";
  grid.positions_m = {Vec3{0, 0, 0.8}};
  grid.normals = {Vec3{0, 0, 1}};
  grid.lattice.columns = grid.lattice.rows = 1;
  grid.lattice.column_of = grid.lattice.row_of = {0};
  add_annual(grid, study, settings, AnnualOutputs{false, false});
  ResultsModel model;
  model.cases.push_back(results_case("base", "", "", {}));
  model.cases[0].grids.push_back(grid);
  const ResultsModel back = parse_results_json(results_json(model), "results.json");
  return *back.cases.at(0).grids.at(0).annual;
}

void expect_same_schedule(const metrics::OccupancyPlan& a, const metrics::OccupancyPlan& b,
                          const metrics::WeatherCalendar& calendar) {
  const std::vector<metrics::TimeStamp> steps = year_steps();
  const metrics::OccupancySchedule sa = a.schedule(steps, calendar), sb = b.schedule(steps, calendar);
  ASSERT_EQ(sa.step_count(), sb.step_count());
  for (std::size_t t = 0; t < sa.step_count(); ++t) ASSERT_EQ(sa.occupied(t), sb.occupied(t)) << "step " << t;
  EXPECT_GT(sa.occupied_count(), 0u);
  EXPECT_EQ(a.description(), b.description());
}

const metrics::WeatherCalendar Calendar{metrics::Weekday::Sunday, "test", -8};

}  // namespace

TEST(RecordedMetricSettings, AWeeklyPlanWithHolidaysAndDaylightSavingComesBackAsRun) {
  AnnualStudySettings settings;
  settings.metrics.da_threshold_lux = 500;
  settings.metrics.udi_lower_lux = 150;
  settings.metrics.udi_upper_original_lux = 2500;
  settings.metrics.udi_upper_revised_lux = 3500;
  settings.metrics.sda_time_fraction = 0.6;
  settings.metrics.ase_threshold_lux = 900;
  settings.metrics.ase_hours = 200;
  metrics::OccupancyPlan& plan = settings.occupancy;
  plan.kind = metrics::OccupancyPlan::Kind::Weekly;
  for (int d = 0; d < 5; ++d) plan.week[d] = {{8, 12}, {13, 15.5}};
  plan.week[2] = {{8, 12}};
  plan.holiday_hours = {{9.25, 10.75}};
  plan.holidays = {{12, 20, 1, 3}, {7, 1, 8, 31}};
  plan.january_1 = metrics::Weekday::Tuesday;
  plan.daylight_saving = metrics::DaylightSaving::Us;

  const AnnualStudySettings back = recorded_annual_settings(recorded(settings), SourceLocation{"results.json", 0, 0});
  const metrics::MetricSettings& m = back.metrics;
  EXPECT_EQ(m.da_threshold_lux, 500);
  EXPECT_EQ(m.udi_lower_lux, 150);
  EXPECT_EQ(m.udi_upper_original_lux, 2500);
  EXPECT_EQ(m.udi_upper_revised_lux, 3500);
  EXPECT_EQ(m.sda_time_fraction, 0.6);
  EXPECT_EQ(m.ase_threshold_lux, 900);
  EXPECT_EQ(m.ase_hours, 200);
  EXPECT_EQ(back.occupancy.kind, metrics::OccupancyPlan::Kind::Weekly);
  expect_same_schedule(plan, back.occupancy, Calendar);
  // Without its own weekday of 1 January, the weather file's is used, as in the run.
  plan.january_1.reset();
  const AnnualStudySettings calendar_day = recorded_annual_settings(recorded(settings), SourceLocation{"results.json", 0, 0});
  EXPECT_FALSE(calendar_day.occupancy.january_1);
  expect_same_schedule(plan, calendar_day.occupancy, Calendar);
}

TEST(RecordedMetricSettings, DailyAndHourlyPlansComeBackAsRun) {
  AnnualStudySettings daily;
  daily.occupancy = metrics::OccupancyPlan::daily_hours(7.5, 16.75);
  const AnnualStudySettings daily_back = recorded_annual_settings(recorded(daily), SourceLocation{"results.json", 0, 0});
  EXPECT_EQ(daily_back.occupancy.kind, metrics::OccupancyPlan::Kind::Daily);
  expect_same_schedule(daily.occupancy, daily_back.occupancy, Calendar);

  AnnualStudySettings hourly;
  hourly.occupancy.kind = metrics::OccupancyPlan::Kind::Hourly;
  std::mt19937 random(7);
  for (std::size_t t = 0; t < 8760; ++t) hourly.occupancy.hourly.push_back(random() % 3 == 0);
  hourly.occupancy.hourly_source = "schedule.csv";
  const AnnualStudySettings hourly_back = recorded_annual_settings(recorded(hourly), SourceLocation{"results.json", 0, 0});
  EXPECT_EQ(hourly_back.occupancy.hourly_source, "schedule.csv");
  expect_same_schedule(hourly.occupancy, hourly_back.occupancy, Calendar);
  // Another weather file's length: an error at results.json, not a shifted schedule.
  std::vector<metrics::TimeStamp> leap = year_steps();
  leap.resize(8784, leap.back());
  try {
    hourly_back.occupancy.schedule(leap, Calendar);
    ADD_FAILURE() << "an hourly schedule of 8760 values fits 8784 steps";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("results.json"), std::string::npos) << e.what();
  }
}

TEST(RecordedMetricSettings, AGridFolderFindsItsRunsRecord) {
  const fs::path dir = fs::temp_directory_path() / ("dayphoton_recorded_grid_" + std::to_string(std::random_device{}()));
  fs::remove_all(dir);
  fs::create_directories(dir / "variants" / "dark" / "desks");
  fs::create_directories(dir / "desks");
  ResultsModel model;
  model.cases.push_back(results_case("base", "", "", {}));
  model.cases.push_back(results_case("variant", "dark", "variants/dark", {}));
  for (CaseResult& c : model.cases) {
    GridResult g;
    g.name = "desks";
    g.folder = c.folder.empty() ? "desks" : c.folder + "/desks";
    g.annual = AnnualSummary{};
    g.annual->da_threshold_lux = c.folder.empty() ? 300 : 400;
    g.annual->occupancy.kind = "daily";
    c.grids.push_back(g);
  }
  write_results_model(model, dir.string());
  const std::optional<RecordedGrid> base = find_recorded_grid((dir / "desks").string());
  ASSERT_TRUE(base && base->grid);
  EXPECT_EQ(base->grid->annual->da_threshold_lux, 300);
  const std::optional<RecordedGrid> variant = find_recorded_grid((dir / "variants" / "dark" / "desks/").string());
  ASSERT_TRUE(variant && variant->grid);
  EXPECT_EQ(variant->grid->annual->da_threshold_lux, 400);
  EXPECT_EQ(fs::path(variant->results_path), dir / "results.json");
  // A grid folder the model does not list: the model, no grid.
  fs::create_directories(dir / "other");
  const std::optional<RecordedGrid> other = find_recorded_grid((dir / "other").string());
  ASSERT_TRUE(other);
  EXPECT_FALSE(other->grid);
  // Moved out of its results folder: nothing recorded.
  const fs::path alone = dir / "alone" / "a" / "b" / "c" / "desks";
  fs::create_directories(alone);
  EXPECT_FALSE(find_recorded_grid(alone.string()));
  fs::remove_all(dir);
}
