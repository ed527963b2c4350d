// What the gather rounds (gather_accuracy_rounds.h) did for one grid: the record the
// accuracy outcome keeps per grid (accuracy_rounds.h) and summary.json reports
// (docs/outputs.md, `grids[].accuracy.gather`).
#pragma once

#include <cstddef>
#include <string>

namespace dayphoton::study {

struct GatherAccuracy {
  bool gathered = false;      ///< the grid is estimated by final gather (else nothing below applies)
  int first_rays = 0;         ///< gather rays per sensor the project asked for (a square)
  int rays = 0;               ///< gather rays per sensor of the grid's final estimate (a square)
  std::size_t rounds = 0;     ///< estimates with more rays after the photon rounds (0: none needed)
  /// "target met", "gather photon part" (the part more rays do not reduce is above the
  /// budget), "direct component", "gather ray limit", "round limit", "time budget".
  std::string stop_reason;
};

/// A receiver-plane grid's sensors next to a cut, estimated by final gather and left out of the
/// rounds' measure (accuracy_policy.h): what they reached after the last round, which the log,
/// summary.json (`grids[].accuracy.near_cut`) and the report state beside the grid's verdict.
struct NearCutReached {
  std::size_t sensors = 0;      ///< 0: none on the grid (nothing below applies)
  int gather_rays = 0;          ///< gather rays per sensor of their final estimate
  double largest_percent = 0;   ///< the largest relative standard error among them, %
  std::size_t rounds = 0;       ///< their gather rounds (gather_accuracy_rounds.h; 0: none needed)
  /// As GatherAccuracy::stop_reason: "target met", "gather photon part", "direct component",
  /// "gather ray limit", "round limit", "time budget"; empty before the gather rounds.
  std::string stop_reason;
};

}  // namespace dayphoton::study
