// The run's metric settings, site and ground from its results model; see
// recorded_metric_settings.h.
#include "dayphoton/study/recorded_metric_settings.h"

#include <filesystem>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/input_file.h"
#include "dayphoton/metrics/calendar.h"

namespace dayphoton::study {

namespace {

namespace fs = std::filesystem;

metrics::DayHours day_hours(const OccupancySummary::Windows& windows) {
  metrics::DayHours hours;
  for (const auto& [start, end] : windows) hours.push_back({start, end});
  return hours;
}

}  // namespace

std::optional<RecordedGrid> find_recorded_grid(const std::string& grid_dir) {
  fs::path grid = fs::absolute(grid_dir).lexically_normal();
  if (!grid.has_filename()) grid = grid.parent_path();  // "grid/" -> "grid"
  fs::path dir = grid;
  for (int up = 0; up < RecordedResultsMaxLevelsUp && dir.has_parent_path() && dir != dir.parent_path(); ++up) {
    dir = dir.parent_path();
    const fs::path path = dir / ResultsFileName;
    if (!input_file_problem(path.string()).empty()) continue;  // absent, or a FIFO: not waited on
    RecordedGrid r;
    r.results_path = path.string();
    r.model = read_results_model(dir.string());
    const std::string folder = grid.lexically_relative(dir).generic_string();
    for (const CaseResult& c : r.model.cases)
      for (const GridResult& g : c.grids)
        if (!r.grid && g.folder == folder) r.grid = g;
    return r;
  }
  return std::nullopt;
}

AnnualStudySettings recorded_annual_settings(const AnnualSummary& a, const SourceLocation& where) {
  AnnualStudySettings settings;
  metrics::MetricSettings& m = settings.metrics;
  m.da_threshold_lux = a.da_threshold_lux;
  m.udi_lower_lux = a.udi_lower_lux;
  m.udi_upper_original_lux = a.udi_upper_original_lux;
  m.udi_upper_revised_lux = a.udi_upper_revised_lux;
  m.sda_time_fraction = a.sda_time_fraction;
  m.ase_threshold_lux = a.ase_threshold_lux;
  m.ase_hours = a.ase_hours;
  const std::optional<metrics::MetricSettings::Openings> openings = metrics::parse_en17037_openings(a.en17037_openings);
  if (!openings) throw InputError(where, "en17037 openings '" + a.en17037_openings + "' is not one of the kinds dayphoton writes");
  m.en17037_openings = *openings;

  const OccupancySummary& o = a.occupancy;
  metrics::OccupancyPlan& plan = settings.occupancy;
  plan.location = where;
  if (o.kind == "daily") {
    plan.kind = metrics::OccupancyPlan::Kind::Daily;
    plan.daily = {o.start_h, o.end_h};
  } else if (o.kind == "weekly") {
    plan.kind = metrics::OccupancyPlan::Kind::Weekly;
    for (std::size_t d = 0; d < 7; ++d) plan.week[d] = day_hours(o.week[d]);
    plan.holiday_hours = day_hours(o.holiday_hours);
    for (const OccupancySummary::Holiday& h : o.holidays)
      plan.holidays.push_back({h.from_month, h.from_day, h.to_month, h.to_day});
  } else if (o.kind == "hourly") {
    plan.kind = metrics::OccupancyPlan::Kind::Hourly;
    plan.hourly.reserve(o.hourly.size());
    for (char c : o.hourly) plan.hourly.push_back(c == '1');
    plan.hourly_source = o.hourly_source;
  } else {
    throw InputError(where, "occupancy kind '" + o.kind + "' is not daily, weekly or hourly");
  }
  if (!o.january_1.empty()) {
    const std::optional<metrics::Weekday> day = metrics::parse_weekday(o.january_1);
    if (!day) throw InputError(where, "occupancy january_1 '" + o.january_1 + "' is not a weekday");
    plan.january_1 = *day;
  }
  const std::optional<metrics::DaylightSaving> dst = metrics::parse_daylight_saving(o.daylight_saving);
  if (!dst) throw InputError(where, "occupancy daylight_saving '" + o.daylight_saving + "' is not none, eu or us");
  plan.daylight_saving = *dst;
  return settings;
}

std::optional<SunSite> recorded_sun_site(const ResultsModel& model, const std::string& results_path,
                                         const weather::HourlyWeather& weather) {
  if (!model.sun_site) return std::nullopt;
  project::Site site;
  site.from_weather = model.sun_from_weather;
  site.latitude_deg = (*model.sun_site)[0];
  site.longitude_deg = (*model.sun_site)[1];
  site.time_zone_h = (*model.sun_site)[2];
  site.elevation_m = (*model.sun_site)[3];
  return recorded_sun_site(site, results_path, weather);
}

}  // namespace dayphoton::study
