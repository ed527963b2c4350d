// The loop the accuracy rounds share (docs/photon-tracing.md "Accuracy target"): the sky
// sources' rounds (accuracy_rounds.h) and the sun bins' (sun_accuracy_rounds.h) differ only in
// what they measure after each round; the pilot, the allocation of attempts per source, the
// stops and the log lines are this one loop.
//
// Round 1, the pilot, grows every source's attempt prefix [0, A) by the doublings of
// engine::next_pilot_attempts to a quarter of its reference count (AccuracyPilotFraction);
// then the measure estimates the grids from the photons so far and returns the variances of
// the grids the photons serve; next_round_scale turns them into each source's next count
// (Neyman's allocation), a round extends every growing source's prefix, and so on. Stops:
// every chased grid met the target, the photon budget (stored photons of the loop's sources),
// the time budget (rank 0's clock: the one decision that depends on the machine), the round
// limit, no source that can help ("no light", or "direct component" when a sensor's direct
// variance alone exceeds its budget and nothing raises its shadow rays, "direct rays limit"
// when the sky's direct round (RoundDirect) has raised them to their limit). When it would
// stop, the grids it does not chase (final gather, RoundLoopFinish) take their turn on the
// photons so far and may ask for more: a further round then traces what they ask for (within
// the same budgets and round limit) and the loop goes on.
//
// Every trace (the pilot's doublings, each round's extension) is one call of RoundWork::trace
// (round_work.h), so under MPI the attempt ranges are shared over the ranks and summed on every
// rank; the measure estimates through RoundWork::estimate. Every rank runs this loop alike and
// takes the same decisions.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/photon_rounds.h"
#include "dayphoton/engine/receiver_plane.h"
#include "dayphoton/study/accuracy_rounds.h"
#include "dayphoton/study/round_work.h"

namespace dayphoton::study {

/// The sources a loop traces.
struct RoundSources {
  /// Per source: its photons at the reference count (photons_per_bin times its factor); the
  /// pilot aims at AccuracyPilotFraction of it, and the kernel's scale is relative to it.
  std::vector<double> reference;
  std::size_t max_prepass_attempts_per_target = 0;  ///< the pilot's give-up (TracingOptions)
  /// A source's record before its first attempt (engine::empty_source_record, or a zero
  /// bound flux for a source not traced).
  std::function<engine::SourcePhotonRecord(std::size_t source)> empty_record;
  /// Attempts [first, last) of a source (engine::round_attempt_range): pure, thread-safe.
  RoundWork::RangeTracer trace;
};

/// What a measure found after a round.
struct RoundMeasurement {
  std::vector<GridVariance> chased;      ///< the grids the photons serve (accuracy_policy.h)
  std::vector<std::string> grid_status;  ///< per grid (accuracy_grid_status)
  bool met = false;                      ///< every chased grid at or below the target
  std::string grids;                     ///< the round's log line per grid: " floor 1.2 %, desk 0.9 %"
};

/// Estimates every grid from the records after round `round` (1 = the pilot); `scale` is each
/// source's photons relative to its reference count (GridPhotons::set_source_scale).
using RoundMeasure = std::function<RoundMeasurement(std::size_t round,
                                                    const std::vector<engine::SourcePhotonRecord>& records,
                                                    const std::vector<double>& scale)>;

/// The words of the log lines: "<name> round 2: ... photons, ... attempts; <measure> (95th
/// percentile)<grids> (target 1 %)", "<name>: target met after 2 round(s)".
struct RoundLoopText {
  std::string name;     ///< "accuracy", "sun accuracy"
  std::string measure;  ///< "DF relative standard error"
};

struct RoundLoopOutcome {
  std::size_t rounds = 0;
  std::uint64_t photons = 0;  ///< stored photons of every source
  std::uint64_t attempts = 0;
  std::string stop_reason;
  std::vector<std::uint64_t> pilot_attempts, final_attempts;  ///< per source
};

/// The grids the loop's measure does not chase (the gathered grids of gather_accuracy_rounds.h):
/// their own rounds on the photons traced so far, and what they ask of the photon rounds.
struct RoundLoopFinish {
  /// Runs whenever the loop would stop (its outcome's stop reason set), before the closing log
  /// line, with the sources' records; it may change the stop reason. Returns the factor by which
  /// each source's photons should grow for those grids (empty, or no factor above 1: none).
  /// The loop traces that as a further round when the grids it chases stopped on their own
  /// (target met, direct component, no light) and no budget or the round limit is in the way;
  /// then it measures and runs this again.
  std::function<std::vector<double>(RoundLoopOutcome& outcome, const std::vector<engine::SourcePhotonRecord>& records)>
      finish;
  /// Runs when the loop does not trace what `finish` asked for, with the reason ("photon
  /// budget", "time budget", "round limit"); it may change the outcome's stop reason.
  std::function<void(RoundLoopOutcome& outcome, const std::string& reason)> refused;
  explicit operator bool() const { return bool(finish); }
};

/// The direct part's own round decision (the sky's rounds: next_direct_round in
/// accuracy_rounds.h; the sun bins' rounds have none). After a round's measure, when the
/// round limit and the budgets let another round run: `plan` decides from the photon plan
/// (next_round_scale) and the sources' costs whether the next round also raises some grids'
/// shadow rays, with the photon plan that goes with the raise; `seconds` predicts the raise's
/// time (the first process's clock); `apply` traces it (collective, through the work) after the
/// round's photons. A raise that does not fit the time budget is not made (the photon plan
/// without it then applies); a round may raise the shadow rays alone. When neither photons
/// nor shadow rays can help, the stop is "direct rays limit" if sensors are above their
/// budget by the direct part at MaxDirectSamplesPerBin (plan_policy.h).
struct RoundDirect {
  std::function<DirectRoundPlan(const std::vector<double>& cost, const RoundPlan& photons, double aim_percent)> plan;
  std::function<double(const DirectRoundPlan&)> seconds;
  std::function<void(std::size_t round, const DirectRoundPlan&)> apply;
};

/// The loop (header comment). `start` is when the rounds' time budget began.
RoundLoopOutcome run_round_loop(const RoundSources& sources, const AccuracyGoal& goal, const RoundMeasure& measure,
                                const RoundLoopText& text, const std::function<void(const std::string&)>& log,
                                RoundWork& work, std::chrono::steady_clock::time_point start,
                                const RoundLoopFinish& finish = {}, const RoundDirect& direct = {});

/// Every record's photons with their flux (engine::scaled_source_photons) merged in source
/// order, in one copy (engine::scaled_merged_photons); with `relabel`, source p's photons
/// labelled p (a source traced alone as source 0, as each sun bin is).
engine::TracedPhotons round_photons(const std::vector<engine::SourcePhotonRecord>& records, bool relabel);

/// The outcome's sentence of the run log and the report: "<measure> (95th percentile of the
/// sensors) 0.93 % <= target 1 %<detail>: target met after 3 round(s), 4100000 photons".
std::string round_outcome_sentence(const std::string& measure, double reached_percent, double target_percent,
                                   const std::string& detail, const std::string& stop_reason, std::size_t rounds,
                                   std::uint64_t photons);

/// "256 shadow rays per bin, the rounds' limit", or for a project's own count above
/// MaxDirectSamplesPerBin "400 shadow rays per bin, the project's own count (above the rounds'
/// limit of 256)": the words of a "direct rays limit" log line.
std::string direct_rays_limit_words(int samples_per_bin);

/// "%.3g" and the like, for the log lines.
std::string round_number(double x, const char* format = "%.3g");

}  // namespace dayphoton::study
