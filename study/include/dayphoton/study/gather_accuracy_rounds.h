// The accuracy target for grids estimated by final gather (docs/photon-tracing.md "Accuracy
// target", "Gathered grids"): after the photon rounds (accuracy_rounds.h), which do not chase
// such a grid (accuracy_policy.h), a gathered grid above the target is estimated again with
// more gather rays per sensor, in rounds, until the target is met or a limit stops them.
//
// The model. A gathered sensor's DF variance is V = V_d + V_g(N): V_d the direct component's
// (shadow rays; the same every round until a raise, below), V_g the gather's at N rays
// (engine/final_gather.h, "Variance": the photons' part by groups of paths plus the rays'
// part). As final_gather.h ("How the variance falls with the rays") derives, V_g(N') = alpha + beta / N': alpha the
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
// A plane's sensors next to a cut (accuracy_policy.h), inside a grid the photons serve, which
// the photon rounds neither gather nor measure, are gathered here once from the last round's
// photons at the project's rays (the estimate that used to be the rounds'), and get the same
// rounds over their rows alone (engine::gather_photon_coefficients_at; sensor blocks of those
// rows, the gather map the gathered grids' own, built once), on the largest of their
// relative errors (the 100th percentile: the verdict states that largest), with the same stops
// but no raise of shadow rays and no request for photons; the rows reached replace theirs in
// the grid's coefficients (AccuracyResult::near_cut for the sun rounds' own) and
// AccuracyOutcome::near_cut records their rays, rounds, stop and largest error.
//
// Stops (GatherAccuracy::stop_reason): "target met"; "gather photon part" (every sensor
// still above the aim is photon-limited: more photons, or a larger gather_bandwidth, would
// lower it); "direct component" (only direct-limited sensors remain and no raise of their
// shadow rays is given: direct_samples_per_bin); "direct rays limit" (below);
// "gather ray limit" (GatherMaxRays reached); "round limit" (GatherMaxRounds gather rounds on
// the same photons); "time budget" (AccuracyGoal::max_seconds, from the last estimate's time
// per ray; the first process's clock, round_work.h).
//
// More photons for the photon part. A grid that stopped on "gather photon part" or "gather ray
// limit" asks the photon rounds for more photons (next_gather_photons): the fixed part alpha is
// the photons' variance read through a kernel of fixed size (the gather's bandwidth is not
// rescaled), so source p's share alpha_p falls as 1/N_p like a receiver plane's (accuracy_rounds.h)
// while the rays' part V_g - alpha stays. Of the budget B the photons get B_p = B - R, R the
// rays' part left to the rays: what it is now at N rays, but at most B / 2 (more rays then
// take the rest, at most 2 beta / B of them), and never less than it would be at the ray limit
// (beta / GatherMaxRays); a sensor with alpha > B_p > 0 takes Neyman's allocation of B_p over
// the sources (raise_to_neyman_scale), at most AccuracyMaxGrowth per round; the grid asks for
// the largest factor of each source over its sensors at or below the percentile. The photon
// rounds (accuracy_round_loop.h, RoundLoopFinish) trace that as a further round within their
// budgets and round limit and call the gather rounds again, each grid starting from the rays
// it reached. If they cannot, the grid's stop names why: "photon budget", "time budget" or
// "photon round limit" (refuse_gather_photons).
//
// More shadow rays for the direct part. A grid whose ray plan leaves direct-limited sensors
// (B <= 0) when no more rays can be had (none would help, or the gather ray or round limit
// is reached) raises its shadow rays per bin by the photon rounds' rule (next_direct_round,
// accuracy_rounds.h: k -> 2k or 4k strata per bin, at most MaxDirectSamplesPerBin) through
// GatherDirectRaise, which traces the grid's direct part again by sensor blocks through the
// work; the grid's estimate takes the new direct part (its gather part is unchanged) and the
// gather rounds go on. Stops: "direct rays limit" when such sensors remain at the limit and
// none is photon-limited; "time budget" when the raise's predicted time does not fit.
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

/// The photons one gathered grid asks for (header comment), from its sensors' DF (percent),
/// direct variance, gather variance and the gather's fixed part by source ([sensor x sources +
/// source], (DF percent)^2) at `rays`; `cost`: each source's rays so far.
struct GatherPhotonPlan {
  std::vector<double> scale;  ///< per source: photons relative to now (>= 1, <= max_growth)
  std::size_t sensors = 0;    ///< sensors whose photon part is above their share of the budget
};
GatherPhotonPlan next_gather_photons(const std::vector<double>& df_percent, const std::vector<double>& direct_variance,
                                     const std::vector<double>& gather_variance,
                                     const std::vector<double>& fixed_per_source, int rays,
                                     const std::vector<double>& cost, double aim_percent, double percentile,
                                     double max_growth = AccuracyMaxGrowth);

/// What the gathered grids ask of the photon rounds after their gather rounds.
struct GatherPhotonRequest {
  std::vector<double> scale;       ///< per source, the largest factor any grid asks for (empty: none)
  std::vector<std::size_t> grids;  ///< the grids that ask
};

/// How the gather rounds raise a gathered grid's shadow rays (header comment), given by the
/// photon rounds that own each grid's direct part.
struct GatherDirectRaise {
  std::function<int(std::size_t grid)> samples_per_bin;  ///< the grid's shadow rays per bin now
  /// Traces the grid's direct part at `samples_per_bin` (collective, through the work) into the
  /// `direct` given to run_gather_accuracy_rounds.
  std::function<void(std::size_t grid, int samples_per_bin)> raise;
  std::function<double(double rays)> seconds;  ///< a raise's predicted time (the first process's clock)
  bool port_sampling = false;                  ///< engine::DirectOptions::port_sampling (its rays' count)
  explicit operator bool() const { return bool(raise); }
};

/// The gather rounds of every gathered grid of `result` above the target (header comment):
/// replaces those grids' coefficients, reached_percent and grid_status in result.outcome, fills
/// result.outcome.gather (every grid; gathered = false for the others; a second call after more
/// photons starts each grid from the rays it reached and adds to its rounds), and settles the
/// case's stop reason from result.outcome.stop_reason, the photon rounds' (settle_case_stop).
/// `records`: the photon rounds' photons so far; `direct`: each grid's direct part (the whole
/// grid's rows of direct, direct_variance and direct_on_skies, copy_direct_rows; empty for
/// none: zeros; `raise_direct`, if given, replaces a raised grid's);
/// `seconds_so_far`: the rounds' time before (for the time budget). Collective through `work`
/// like the photon rounds. Returns the photons the grids ask for.
GatherPhotonRequest run_gather_accuracy_rounds(const AccuracyCase& c, const AccuracyGoal& goal,
                                const std::vector<engine::SourcePhotonRecord>& records,
                                const std::vector<engine::DaylightCoefficients>& direct, double seconds_so_far,
                                RoundWork& work, const std::function<void(const std::string&)>& log,
                                AccuracyResult& result, const GatherDirectRaise& raise_direct = {});

/// The photon rounds did not trace what `request` asked for, for `reason` ("photon budget",
/// "time budget", "round limit"): the asking grids' stop becomes it ("photon round limit" for
/// the photon rounds' limit), and the case's stop is settled again from `photon_stop`.
void refuse_gather_photons(AccuracyOutcome& outcome, const GatherPhotonRequest& request, const std::string& reason,
                           const std::string& photon_stop);

/// The case's stop reason: `photon_stop` (the photon rounds'), unless that is "not reachable
/// by photons" (only gathered grids were left above the target, met_stop_reason): then the
/// first such grid's own gather stop, or "target met" if they all met it.
void settle_case_stop(AccuracyOutcome& outcome, const std::string& photon_stop);

/// The words the run log adds for a gathered grid (" (final gather, 4096 rays per sensor, 2
/// gather round(s) from 1024: target met)"), empty for another grid.
std::string gather_accuracy_note(const AccuracyOutcome& outcome, std::size_t grid);
/// The same from the grids' gather rounds alone (the sun rounds' outcome, sun_accuracy_rounds.h).
std::string gather_accuracy_note(const std::vector<GatherAccuracy>& gather, std::size_t grid);

}  // namespace dayphoton::study
