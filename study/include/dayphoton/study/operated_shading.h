// Operated shading: the IES LM-83-12 blinds rule (section 2.2.6) applied hour by hour to two
// cases of a study, the OPEN state (shading retracted) and the SHADED state.
//
// LM-83-12 2.2.6: "Blinds shall close whenever more than 2 % of analysis points receive
// direct sun"; "direct sun": "an interior horizontal measurement of 1,000 lux or more of
// direct beam sunlight that accounts for window transmittance and excludes the effect of any
// blinds, with no contribution from reflected light (i.e. a zero bounce analysis)" (quoted in
// ../shared/facts/sky-and-metrics.md section 5.3). Hence, per grid and step t:
//
//   sunlit(t) = #{ sensors s : D_open[t][s] >= direct_sun_threshold }      ("or more")
//   shaded(t) = 100 sunlit(t) > sunlit_limit_percent x sensors              ("more than")
//   E_operated[t] = shaded(t) ? E_shaded[t] : E_open[t]
//
// with D_open the open case's direct-sun-only, zero-bounce table (the one ASE uses:
// study/annual_sun.h) and E the cases' annual illuminance. Every metric of the operated
// result is computed on E_operated (sDA "with hourly blind operation"), ASE on D_open (LM-83:
// "with all operable shading devices retracted"). The rule is applied to every step of the
// year, occupied or not ("for each hour of the year"); a grid is one analysis area; all
// windows of a case are one window group (LM-83 allows groups to close separately).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/metrics/illuminance_table.h"
#include "dayphoton/study/annual_study.h"

namespace dayphoton::study {

/// The thresholds of the rule (LM-83 defaults).
struct ShadingRule {
  double direct_sun_threshold_lux = 1000;  ///< a sensor is sunlit at D >= this
  double sunlit_limit_percent = 2;         ///< shade when MORE than this share is sunlit
};

/// The rule for one step: `sunlit` of `sensors` points see direct sun. Exact for the integer
/// counts: 100 sunlit > limit x sensors, so exactly 2 % (1 of 50) stays open.
bool step_is_shaded(std::size_t sunlit, std::size_t sensors, double sunlit_limit_percent);

/// The decision of every step of one grid.
struct ShadingSchedule {
  std::size_t sensors = 0;
  std::vector<std::size_t> sunlit;  ///< per step: sensors with D >= threshold
  std::vector<char> shaded;         ///< per step: 1 = the shaded case's illuminance

  std::size_t shaded_steps() const;
  /// Shaded steps among those `occupied` marks (same length).
  std::size_t shaded_steps(const std::vector<char>& occupied) const;
};

/// The schedule from the open case's direct-sun-only, zero-bounce table (steps x sensors).
ShadingSchedule shading_schedule(const metrics::IlluminanceTable& open_direct_sun, const ShadingRule& rule);

/// Row t of `shaded` where schedule.shaded[t], else row t of `open`. Throws
/// std::invalid_argument if the tables or the schedule differ in shape.
metrics::IlluminanceTable operated_illuminance(const metrics::IlluminanceTable& open,
                                               const metrics::IlluminanceTable& shaded,
                                               const ShadingSchedule& schedule);

/// The operated result of one grid.
struct OperatedStudy {
  AnnualStudy study;  ///< illuminance and metrics of E_operated; ASE from D_open
  ShadingSchedule schedule;
  std::vector<char> occupied;  ///< per step, the occupancy of the metrics
  std::size_t shaded_occupied_hours = 0;
};

/// Schedule, operated table and every metric of compute_annual_study on it (EN 17037 over the
/// brightest half of `daylight_hours_quantity` unless empty); ASE from `open_direct_sun`.
/// `description` goes to the study's sky description. Throws std::invalid_argument on shape
/// mismatches.
OperatedStudy compute_operated_study(const metrics::IlluminanceTable& open,
                                     const metrics::IlluminanceTable& shaded,
                                     const metrics::IlluminanceTable& open_direct_sun, const ShadingRule& rule,
                                     const AnnualStudySettings& settings,
                                     const std::vector<double>& daylight_hours_quantity,
                                     const std::string& daylight_hours_source, const std::string& description);

/// shading_schedule.csv: `month,day,hour,occupied,sunlit_sensors,sunlit_percent,shaded`,
/// one row per step (sunlit_percent with 3 decimals; occupied and shaded 0/1). Atomic.
void write_shading_schedule_csv(const OperatedStudy& operated, const std::string& path);

/// The summary of the operation as a JSON object (text): the cases, the rule, shaded hours
/// (all steps and occupied), occupied hours.
std::string operation_json(const OperatedStudy& operated, const ShadingRule& rule, const std::string& open_case,
                           const std::string& shaded_case);

}  // namespace dayphoton::study
