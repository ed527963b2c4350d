// OccupancySchedule: which time steps count for the annual metrics. The default is the
// LM-83 analysis period as tools commonly implement it: 08:00-18:00 local STANDARD time
// (no daylight-saving shift), every day, i.e. the hourly records whose mid-hour stamp lies
// in [8, 18): 8.5 .. 17.5 = EPW hours 9..18, 3650 hours in a 365-day year. See docs/metrics.md
// and ../shared/facts/sky-and-metrics.md sections 5.3 and 5.5 for why standard time.
#pragma once

#include <vector>

#include "dayphoton/metrics/illuminance_table.h"

namespace dayphoton::metrics {

class OccupancySchedule {
 public:
  /// Occupied when start_h <= stamp.hour < end_h (hours of local standard time).
  static OccupancySchedule daily_hours(const std::vector<TimeStamp>& steps, double start_h = 8.0,
                                       double end_h = 18.0);
  /// The EN 17037 "daylight hours": the half of the steps (rounded down) with the largest
  /// `daylight_quantity` (diffuse horizontal illuminance of the weather file, as Ladybug
  /// Tools do); ties broken by the earlier step so the choice is deterministic.
  static OccupancySchedule brightest_half(const std::vector<double>& daylight_quantity);

  explicit OccupancySchedule(std::vector<bool> occupied) : m_occupied(std::move(occupied)) {}

  bool occupied(std::size_t step) const { return m_occupied[step]; }
  std::size_t step_count() const { return m_occupied.size(); }
  std::size_t occupied_count() const;

 private:
  std::vector<bool> m_occupied;
};

}  // namespace dayphoton::metrics
