// Which grids the accuracy rounds chase: see accuracy_policy.h.
#include "dayphoton/study/accuracy_policy.h"

#include <algorithm>

#include "dayphoton/engine/plane_cuts.h"
#include "accuracy_round_loop.h"

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

bool near_cut_gathered_in_rounds(const std::vector<int>& plane_of_grid, bool gather) {
  for (std::size_t g = 0; g < plane_of_grid.size(); ++g)
    if (!grid_chased_by_photons(plane_of_grid, gather, g)) return true;
  return false;
}

std::size_t near_cut_count(const std::vector<int>& plane_of_grid, const std::vector<std::size_t>* near_cut_sensors,
                           std::size_t g) {
  const int plane = g < plane_of_grid.size() ? plane_of_grid[g] : -1;
  if (!near_cut_sensors || plane < 0 || std::size_t(plane) >= near_cut_sensors->size()) return 0;
  return (*near_cut_sensors)[std::size_t(plane)];
}

std::vector<std::size_t> near_cut_rows(const std::vector<engine::ReceiverPlane>& planes,
                                       const std::vector<int>& plane_of_grid,
                                       const std::vector<std::size_t>* near_cut_sensors,
                                       const std::vector<SensorPoint>& points, std::size_t g) {
  if (near_cut_count(plane_of_grid, near_cut_sensors, g) == 0) return {};
  return engine::sensors_near_cuts(planes.at(std::size_t(plane_of_grid[g])), points);
}

NearCutReached take_out_near_cut_rows(const std::vector<std::size_t>& rows, std::vector<double>& value,
                                      const std::vector<double>& stderr_value) {
  NearCutReached out;
  out.sensors = rows.size();
  for (std::size_t i : rows) {
    if (i >= value.size()) continue;
    if (value[i] > 0 && i < stderr_value.size())
      out.largest_percent = std::max(out.largest_percent, 100.0 * stderr_value[i] / value[i]);
    value[i] = 0;
  }
  return out;
}

std::string near_cut_note(const NearCutReached& reached, double target_percent) {
  if (reached.sensors == 0) return "";
  if (reached.stop_reason.empty() && reached.gather_rays == 0)  // a round that does not gather them
    return "; " + std::to_string(reached.sensors) + " sensors next to a cut, gathered after the photon rounds";
  std::string s = "; " + std::to_string(reached.sensors) + " sensors next to a cut gathered, largest " +
                  round_number(reached.largest_percent) + " %";
  if (reached.stop_reason.empty()) return s;  // a round's measure
  if (reached.rounds > 0)
    s += " at " + std::to_string(reached.gather_rays) + " gather rays (" + std::to_string(reached.rounds) +
         " gather round(s))";
  if (reached.largest_percent > target_percent) s += " > target " + round_number(target_percent) + " %: " + reached.stop_reason;
  return s;
}

}  // namespace dayphoton::study
