// The metric settings of a project (docs/project-format.md `metrics`) as the annual study
// takes them: thresholds and the occupancy plan, with the calendar of the weather file.
// `dayphoton run` and `dayphoton annual --project` both go through here, so that they
// evaluate the same metrics for the same project.
#pragma once

#include <string>
#include <vector>

#include "dayphoton/metrics/annual_metrics.h"
#include "dayphoton/metrics/occupancy_plan.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/annual_study.h"
#include "dayphoton/weather/hourly_weather.h"

namespace dayphoton::study {

/// The thresholds.
metrics::MetricSettings metric_settings(const project::MetricsSettings& m);

/// The occupancy: `spec` if written, else the daily window of `m`.
metrics::OccupancyPlan occupancy_plan(const project::OccupancySpec& spec, const project::MetricsSettings& m);

/// Thresholds, occupancy and, when `weather` is given, its calendar. The occupancy is the sensor
/// set's own (`sensors.grids[].occupancy`, `sensors.points[].occupancy`) when the set named
/// `sensor_set` has one, else the project's (`metrics.occupancy`, else the daily window).
/// `openings`: the model's daylight openings (daylight_openings.h), for EN 17037's rule.
AnnualStudySettings annual_settings_of(const project::Project& project, const weather::HourlyWeather* weather,
                                       metrics::MetricSettings::Openings openings, const std::string& sensor_set = "");

/// For `check`: one line per schedule the project writes (`metrics.occupancy` and each sensor
/// set's own), "occupancy[ of <set>]: <description>; N occupied hours of M", evaluated on the
/// weather file, so that a schedule that does not fit it (a CSV of another length, no weekday
/// of 1 January) is an InputError before any run. Empty when the project uses the daily window.
std::vector<std::string> occupancy_summary(const project::Project& project, const weather::HourlyWeather& weather);

}  // namespace dayphoton::study
