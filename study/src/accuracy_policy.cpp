// Which grids the accuracy rounds chase: see accuracy_policy.h.
#include "dayphoton/study/accuracy_policy.h"

namespace dayphoton::study {

bool grid_chased_by_photons(const std::vector<int>& plane_of_grid, bool gather, std::size_t g) {
  return (g < plane_of_grid.size() && plane_of_grid[g] >= 0) || !gather;
}

std::string accuracy_grid_status(bool chased, double reached_percent, double target_percent) {
  if (reached_percent <= target_percent) return "met";
  return chased ? "above target" : "not reachable by photons";
}

std::string met_stop_reason(const std::vector<std::string>& grid_status) {
  for (const std::string& s : grid_status)
    if (s != "met") return "not reachable by photons";
  return "target met";
}

}  // namespace dayphoton::study
