#include "dayphoton/metrics/occupancy.h"

#include <algorithm>
#include <numeric>

namespace dayphoton::metrics {

OccupancySchedule OccupancySchedule::daily_hours(const std::vector<TimeStamp>& steps, double start_h,
                                                 double end_h) {
  std::vector<bool> occupied(steps.size());
  for (std::size_t i = 0; i < steps.size(); ++i)
    occupied[i] = steps[i].hour >= start_h && steps[i].hour < end_h;
  return OccupancySchedule(std::move(occupied));
}

OccupancySchedule OccupancySchedule::brightest_half(const std::vector<double>& daylight_quantity) {
  std::vector<std::size_t> order(daylight_quantity.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return daylight_quantity[a] > daylight_quantity[b];
  });
  std::vector<bool> occupied(daylight_quantity.size(), false);
  for (std::size_t i = 0; i < order.size() / 2; ++i) occupied[order[i]] = true;
  return OccupancySchedule(std::move(occupied));
}

std::size_t OccupancySchedule::occupied_count() const {
  return static_cast<std::size_t>(std::count(m_occupied.begin(), m_occupied.end(), true));
}

}  // namespace dayphoton::metrics
