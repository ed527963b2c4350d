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
//
// A receiver plane's sensors next to a cut (engine/plane_cuts.h, "Sensors next to a cut") are
// estimated by final gather inside their grid. The same holds for them: their error is mostly
// the gather's rays', which photons do not lower, so the rounds' measure of the grid leaves
// them out (the grid's percentile, the photon and shadow-ray plans are over its plane rows).
// A round gathers them only where a gathered grid builds the round's gather map anyway
// (near_cut_gathered_in_rounds); otherwise their rows hold the plane's estimate until the
// gather rounds (gather_accuracy_rounds.h) gather them once from the last round's photons,
// so that a room of work planes builds its gather map once, not every round and again for a
// raise (the column room at 64 gather rays: 33.1 -> 24 CPU s). Each row's standard error is
// its own gather's (final_gather.h "Variance"); the gather rounds raise their gather rays, over
// the rows alone, until the largest of their relative errors meets the target or a gather limit
// stops them; the grid's verdict states those rows apart: their count and largest relative
// error in the rounds' last log line per grid (near_cut_note), in summary.json
// (`grids[].accuracy.near_cut`, with "above target" and the gather stop where the largest is)
// and in the report's accuracy statement, which then says the target is met by the sensors it
// measures only.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/engine/receiver_plane.h"
#include "dayphoton/study/gather_accuracy.h"

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

/// Whether a round's measure gathers the planes' sensors next to a cut (header comment): when
/// some grid of the case is estimated by final gather (`gather` and a grid off the planes), whose
/// map they read.
bool near_cut_gathered_in_rounds(const std::vector<int>& plane_of_grid, bool gather);

/// How many of grid g's sensors are gathered next to a cut: near_cut_sensors (per plane,
/// CaseLayout::near_cut_sensors; null: none) of its plane, 0 off a plane.
std::size_t near_cut_count(const std::vector<int>& plane_of_grid, const std::vector<std::size_t>* near_cut_sensors,
                           std::size_t g);

/// The rows of grid g (on plane plane_of_grid[g] of `planes`, with `points` its sensors) that are
/// gathered next to a cut (header comment): none off a plane or when near_cut_sensors (per
/// plane, CaseLayout::near_cut_sensors) is null or counts none on its plane.
std::vector<std::size_t> near_cut_rows(const std::vector<engine::ReceiverPlane>& planes,
                                       const std::vector<int>& plane_of_grid,
                                       const std::vector<std::size_t>* near_cut_sensors,
                                       const std::vector<SensorPoint>& points, std::size_t g);

/// Takes `rows` out of the rounds' measure (their `value`, DF or annual value, set to 0: the
/// measure's percentile counts only sensors with light) and returns what they reached: their
/// count and the largest relative standard error of `stderr_value` (gather_rays left 0).
NearCutReached take_out_near_cut_rows(const std::vector<std::size_t>& rows, std::vector<double>& value,
                                      const std::vector<double>& stderr_value);

/// The log's words on them: in a round that does not gather them (reached.stop_reason empty,
/// gather_rays 0) "; 12 sensors next to a cut, gathered after the photon rounds", in one that
/// does "; 12 sensors next to a cut gathered, largest 1.4 %"; after their gather rounds "; 12 sensors next to
/// a cut gathered, largest 1.4 %", with " at 1936 gather rays (1 gather round(s))" where they
/// raised the rays and " > target 1 %: gather ray limit" where the largest is above
/// `target_percent`; "" without any.
std::string near_cut_note(const NearCutReached& reached, double target_percent);

}  // namespace dayphoton::study
