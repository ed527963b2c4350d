// Which grids the accuracy rounds chase with photons (accuracy_rounds.h, sun_accuracy_rounds.h).
//
// A grid on a receiver plane or estimated from surface photons follows the 1/N model of the
// rounds: with the kernel kept at the reference size (GridPhotons::set_source_scale) a source's
// variance at a sensor falls as 1/N_p. A grid estimated by final gather does not: the gather's
// error is partly its rays' (final_gather.h), which photons do not reduce, and its kernel is not
// rescaled. Measured on projects/wall_sensors with the standard preset (docs/photon-tracing.md
// "Accuracy target"): the gathered wall grids were at 1.1-1.2 % after the pilot and stayed there
// over the rounds while the work plane fell from 2.5 % to 1.5 %. So the rounds' measure does not
// chase a gathered grid: its error is measured after every round, and after the photon rounds
// the gather rounds raise its rays (gather_accuracy_rounds.h; its status is then "met" or "above
// target"); only the part rays cannot lower, the photons the gather reads, asks for further
// photon rounds (next_gather_photons). The sun bins' rounds still report it as "not reachable
// by photons".
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace dayphoton::study {

/// Whether the rounds trace photons for grid g: it lies on a receiver plane
/// (plane_of_grid[g] >= 0) or the case estimates off-plane grids from surface photons.
bool grid_chased_by_photons(const std::vector<int>& plane_of_grid, bool gather, std::size_t g);

/// A grid's status after the rounds: "met" (reached <= target), "above target" (chased, not
/// met: the stop reason says why), or "not reachable by photons" (not chased, above target).
std::string accuracy_grid_status(bool chased, double reached_percent, double target_percent);

/// The run's stop reason when every chased grid met the target: "target met" if every grid
/// did, else "not reachable by photons" (some gathered grid is above it).
std::string met_stop_reason(const std::vector<std::string>& grid_status);

}  // namespace dayphoton::study
