// The metric settings of a project (docs/project-format.md `metrics`) as the annual study
// takes them: thresholds and the occupancy plan, with the calendar of the weather file.
// `dayphoton run` and `dayphoton annual --project` both go through here, so that they
// evaluate the same metrics for the same project.
#pragma once

#include "dayphoton/metrics/annual_metrics.h"
#include "dayphoton/metrics/occupancy_plan.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/annual_study.h"
#include "dayphoton/weather/epw_reader.h"

namespace dayphoton::study {

/// The thresholds.
metrics::MetricSettings metric_settings(const project::MetricsSettings& m);

/// The occupancy: the `occupancy` schedule if written, else the daily window.
metrics::OccupancyPlan occupancy_plan(const project::MetricsSettings& m);

/// Thresholds, occupancy and, when `epw` is given, its calendar.
AnnualStudySettings annual_settings_of(const project::Project& project, const weather::EpwFile* epw);

}  // namespace dayphoton::study
