#include "dayphoton/study/project_metric_settings.h"

namespace dayphoton::study {

metrics::MetricSettings metric_settings(const project::MetricsSettings& m) {
  metrics::MetricSettings s;
  s.da_threshold_lux = m.da_threshold_lux;
  s.udi_lower_lux = m.udi_lower_lux;
  s.udi_upper_original_lux = m.udi_upper_original_lux;
  s.udi_upper_revised_lux = m.udi_upper_revised_lux;
  s.sda_time_fraction = m.sda_time_fraction;
  s.ase_threshold_lux = m.ase_threshold_lux;
  s.ase_hours = m.ase_hours;
  return s;
}

namespace {

metrics::DayHours day_hours(const project::OccupancySpec::Windows& windows) {
  metrics::DayHours hours;
  for (const auto& [start, end] : windows) hours.push_back({start, end});
  return hours;
}

}  // namespace

metrics::OccupancyPlan occupancy_plan(const project::OccupancySpec& o, const project::MetricsSettings& m) {
  if (!o.given) return metrics::OccupancyPlan::daily_hours(m.occupancy_start_h, m.occupancy_end_h);
  metrics::OccupancyPlan plan;
  plan.location = o.location;
  if (!o.file.empty()) {
    plan.kind = metrics::OccupancyPlan::Kind::Hourly;
    plan.hourly = o.hourly;
    plan.hourly_source = o.file;
    return plan;
  }
  plan.kind = metrics::OccupancyPlan::Kind::Weekly;
  for (std::size_t d = 0; d < 7; ++d) plan.week[d] = day_hours(o.week[d]);
  plan.holiday_hours = day_hours(o.holiday_hours);
  for (const project::OccupancySpec::Holiday& h : o.holidays)
    plan.holidays.push_back({h.from_month, h.from_day, h.to_month, h.to_day});
  if (o.january_1 >= 0) plan.january_1 = static_cast<metrics::Weekday>(o.january_1);
  plan.daylight_saving = metrics::parse_daylight_saving(o.daylight_saving).value_or(metrics::DaylightSaving::None);
  return plan;
}

AnnualStudySettings annual_settings_of(const project::Project& project, const weather::HourlyWeather* weather,
                                       metrics::MetricSettings::Openings openings, const std::string& sensor_set) {
  AnnualStudySettings settings;
  settings.metrics = metric_settings(project.metrics);
  settings.metrics.en17037_openings = openings;
  const project::OccupancySpec* spec = &project.metrics.occupancy;
  for (const project::GridSpec& g : project.sensors.grids)
    if (g.name == sensor_set && g.occupancy.given) spec = &g.occupancy;
  for (const project::PointsSpec& p : project.sensors.points)
    if (p.name == sensor_set && p.occupancy.given) spec = &p.occupancy;
  settings.occupancy = occupancy_plan(*spec, project.metrics);
  if (weather) settings.calendar = weather_calendar(*weather);
  return settings;
}

std::vector<std::string> occupancy_summary(const project::Project& project, const weather::HourlyWeather& weather) {
  std::vector<std::string> lines;
  const std::vector<metrics::TimeStamp> steps = time_stamps(weather);
  auto add = [&](const std::string& label, const std::string& set) {
    // The schedule only: the openings do not change it.
    const AnnualStudySettings settings =
        annual_settings_of(project, &weather, metrics::MetricSettings::Openings::VerticalOrInclined, set);
    const metrics::OccupancySchedule schedule = occupancy_schedule(settings, steps);
    lines.push_back(label + ": " + settings.occupancy.description() + "; " + std::to_string(schedule.occupied_count()) +
                    " occupied hours of " + std::to_string(steps.size()));
  };
  if (project.metrics.occupancy.given) add("occupancy", "");
  for (const project::GridSpec& g : project.sensors.grids)
    if (g.occupancy.given) add("occupancy of " + g.name, g.name);
  for (const project::PointsSpec& p : project.sensors.points)
    if (p.occupancy.given) add("occupancy of " + p.name, p.name);
  return lines;
}

}  // namespace dayphoton::study
