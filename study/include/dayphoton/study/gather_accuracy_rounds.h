// The accuracy target for grids estimated by final gather (docs/photon-tracing.md "Accuracy
// target", "Gathered grids"): after the photon rounds (accuracy_rounds.h), which do not chase
// such a grid (accuracy_policy.h), a gathered grid above the target is estimated again with
// more gather rays per sensor, in rounds, until the target is met or a limit stops them.
//
// The model. A gathered sensor's DF variance is V = V_d + V_g(N): V_d the direct component's
// (shadow rays; the same every round), V_g the gather's at N rays (engine/final_gather.h,
// "Variance": the photons' part by groups of paths plus the rays' part). As final_gather.h
// ("How the variance falls with the rays") derives, V_g(N') = alpha + beta / N': alpha the
// photons' part read by pairs of different rays (it stays, and only more photons lower it),
// measured at N as GatheredCoefficients::fixed_photon_variance; beta = (V_g(N) - alpha) N the
// rest (the rays' part, and the photons' part of each group's terms on one ray). A sensor above
// the aim (AccuracyRoundAim x the target) with budget B = (aim D)^2 - V_d needs
// N' = beta / (B - alpha) rays if B > alpha; if not it is photon-limited (0 < B <= alpha) or
// direct-limited (B <= 0). The grid takes the largest N' over its sensors at or below the
// measure's percentile (accuracy_rounds.h), at most GatherMaxGrowth times the current count
// per round and GatherMaxRays in all, rounded up to a square (the gather's k x k strata).
// Every estimate is a whole new one (the strata change with k) with its own variance, and the
// last is the grid's result: its reported standard error is that estimate's. The photon
// rounds' estimate of the grid is made again once at the project's rays, for its alpha (the
// same coefficients).
//
// Stops (GatherAccuracy::stop_reason): "target met"; "gather photon part" (every sensor
// still above the aim is photon-limited: more photons, or a larger gather_bandwidth, would
// lower it; the rounds do not trace more photons for it); "direct component" (only
// direct-limited sensors remain: direct_samples_per_bin); "gather ray limit" (GatherMaxRays
// reached); "round limit" (GatherMaxRounds); "time budget" (AccuracyGoal::max_seconds,
// from the last estimate's time per ray; the first process's clock, round_work.h).
//
// Determinism: the gather of a sensor is a pure function of (seed, sensor, rays), its
// estimates go by sensor blocks through RoundWork, and every decision reads only the joined
// results, so the bytes are those of one thread and one process for any thread and rank count.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "dayphoton/engine/photon_rounds.h"
#include "dayphoton/study/accuracy_rounds.h"
#include "dayphoton/study/round_work.h"

namespace dayphoton::study {

/// Gather rounds after the photon rounds, at most.
constexpr std::size_t GatherMaxRounds = 6;
/// No grid's gather rays grow more than this factor in one round.
constexpr double GatherMaxGrowth = 16.0;
/// Gather rays per sensor at most (the range of simulation.gather_rays).
constexpr int GatherMaxRays = 65536;

/// The next gather ray count of a grid (header comment), from its sensors' DF (percent), direct
/// variance, gather variance and its fixed part alpha (DF percent squared) at `rays`.
/// `aim_percent`: the relative standard error aimed at. Returns the count (a square, <=
/// GatherMaxRays; `rays` itself when no sensor can be helped) and counts the sensors that rays
/// cannot help.
struct GatherRayPlan {
  int rays = 0;
  std::size_t sensors_constrained = 0;      ///< at or below the percentile, above the aim
  std::size_t sensors_photon_limited = 0;   ///< of those, alpha alone fills the budget
  std::size_t sensors_direct_limited = 0;   ///< of those, the direct variance alone does
};
GatherRayPlan next_gather_rays(const std::vector<double>& df_percent, const std::vector<double>& direct_variance,
                               const std::vector<double>& gather_variance, const std::vector<double>& fixed_variance,
                               int rays, double aim_percent, double percentile);

/// The gather rounds of every gathered grid of `result` above the target (header comment):
/// replaces those grids' coefficients, reached_percent and grid_status in result.outcome, and
/// fills result.outcome.gather (every grid; gathered = false for the others). `records`: the
/// photon rounds' final photons; `direct`, `direct_variance`: each grid's direct part (the
/// whole grid's rows); `seconds_so_far`: the rounds' time before (for the time budget).
/// Collective through `work` like the photon rounds.
void run_gather_accuracy_rounds(const AccuracyCase& c, const AccuracyGoal& goal,
                                const std::vector<engine::SourcePhotonRecord>& records,
                                const std::vector<std::vector<Vec3>>& direct,
                                const std::vector<std::vector<double>>& direct_variance, double seconds_so_far,
                                RoundWork& work, const std::function<void(const std::string&)>& log,
                                AccuracyResult& result);

/// The words the run log adds for a gathered grid (" (final gather, 4096 rays per sensor, 2
/// gather round(s) from 1024: target met)"), empty for another grid.
std::string gather_accuracy_note(const AccuracyOutcome& outcome, std::size_t grid);

}  // namespace dayphoton::study
