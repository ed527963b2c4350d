// The accuracy target for the sun bins (`simulation.accuracy` with `sun: bins`,
// docs/photon-tracing.md "Accuracy target"): the sun bins' photons traced in rounds, as the sky
// bins' are (accuracy_rounds.h), until each grid's sun-bin results reach the target.
//
// The measure. The annual results add to the sky the indirect sun of every sun hour h,
// E_h(s) = 179 L_h sum_k w_hk C_k(s) (annual_sun.h: the bins k of the hour's stencil with
// weights w_hk, L_h the disc radiance, C_k(s) the luminance of bin k's coefficient at sensor s).
// Summed over the year, a sensor's annual sun-bin illuminance is 179 sum_k A_k C_k(s) with
// A_k = sum_h w_hk L_h, and since the bins are traced independently its variance is
// 179^2 sum_k A_k^2 var C_k(s): the sun's counterpart of the DF, a sum over every bin weighted
// by the light the year brings through it (the DF weights the sky bins by the overcast sky).
// The target applies to its relative standard error at the 95th percentile of the sensors (as
// the DF's). It is reported beside the hourly measure the target does not cover: the RMS over
// the sun hours of E_h's standard error relative to the RMS of E_h,
// sqrt(sum_k B_k var C_k(s) / sum_h E_h(s)^2) with B_k = sum_h w_hk^2 L_h^2 (179 cancels), which
// is what one hour's value carries (a few bins, not the whole year's).
//
// The rounds are the sky's loop (the pilot, the allocation, the stops and the log lines are
// one piece of code, study/src/accuracy_round_loop.h) with this measure. Round 1 traces every
// lit bin (sun_bins_to_trace) to a quarter of the reference count (sun photons_per_bin) by the
// pilot's doublings (engine::next_pilot_attempts) on the bin traced alone (its own disc and
// seed, as trace_sun_bin); later rounds extend each bin's attempt prefix by Neyman's
// allocation (next_round_scale) of the annual measure, the kernel kept at the reference size
// (GridPhotons::set_source_scale). Stops: target met, photon budget (stored photons of the sun
// bins, the goal's max_photons again, apart from the sky's), round limit, no light. No time
// budget (the run's goal for the sun has none: max_seconds bounds the sky's rounds). Grids
// estimated by final gather are not chased by the photon rounds (accuracy_policy.h): when the
// rounds would stop, such a grid above the target gets the sky's gather rounds
// (gather_accuracy_rounds.h: more gather rays, then more photons of the bins for the gather's
// photon part through a further round, within the same photon budget and round limit) with
// the annual measure as their "DF" (each bin weighted by A_k, in the gather's rays' variance
// too: sun_annual_estimating); the sun bins' coefficients have
// no direct part (the direct sun is exact, annual_sun.h), so no shadow rays are raised.
// Deterministic: every round is a pure function
// of the project and the seed, the same bytes for any number of threads and of MPI ranks
// (under MPI the bins' attempt ranges and each round's sensor blocks are shared over the
// ranks, round_work.h; docs/cluster.md "Accuracy rounds").
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/receiver_plane.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/engine/sun_bins.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/study/accuracy_rounds.h"
#include "dayphoton/study/round_work.h"

namespace dayphoton::study {

/// Per sun bin: A_k = sum_h w_hk L_h and B_k = sum_h w_hk^2 L_h^2 over the year's suns.
struct SunYearWeights {
  std::vector<double> annual, squared;
};
SunYearWeights sun_year_weights(const engine::SunBins& bins, const std::vector<sky::SunRecord>& suns);

/// `estimating` with the gather's variance weights of the annual measure: each bin's A_k
/// (engine::GatherOptions::variance_weights), so that a gathered grid's per-bin variances,
/// summed with the weights A_k^2, give the variance of its annual value (final_gather.h,
/// "Variance"). The rounds estimate with it whatever `estimating` had.
engine::CoefficientOptions sun_annual_estimating(engine::CoefficientOptions estimating, const SunYearWeights& weights);

/// One grid's sun-bin measures from its coefficients (sensors x bins x RGB) and variances
/// (sensors x bins, of each entry's luminance): per sensor the annual sun-bin value
/// sum_k A_k C_k(s) (luminance units), and the GridVariance of next_round_scale in those units
/// (df_percent = the annual value, direct_variance 0, photon_variance A_k^2 var C_k(s)).
GridVariance sun_annual_variance(const RadianceMatrix& coefficients, const std::vector<double>& variance,
                                 const SunYearWeights& weights);

/// The hourly measure of the header (%, per sensor; 0 for a sensor without sun-bin light).
std::vector<double> sun_hourly_relative_stderr_percent(const RadianceMatrix& coefficients,
                                                       const std::vector<double>& variance,
                                                       const engine::SunBins& bins,
                                                       const std::vector<sky::SunRecord>& suns,
                                                       const SunYearWeights& weights);

/// A point-in-time case's sun in the sun rounds (point_in_time.h, point_in_time_accuracy.h): with
/// such cases the rounds measure each case's illuminance at every sensor, E(s) = other(s) + 179
/// L sum_k w_k C_k(s) (the case's stencil w_k, L its disc radiance), with the variance of its
/// other parts fixed and 179^2 L^2 w_k^2 var C_k(s) per bin, instead of the annual sun-bin value:
/// the target then applies to each case's relative standard error at the percentile, as the
/// daylight factor's, and the allocation goes to the bins of the stencils in proportion to the
/// light each case takes from them (next_round_scale over one GridVariance per grid and case).
/// The indirect sun's budget at a case's sensor is what the other parts leave of (aim x E)^2, but
/// at least SunCaseBudgetFloor of it; a sensor is left to its other parts (GridVariance::
/// left_out: the sun's photons do not reduce what keeps it above) when they alone exceed
/// (target x E)^2, or take more than the rest of the budget while its indirect sun is within the
/// floor. When only such sensors remain the rounds stop with "other parts".
/// The share of a point-in-time case's variance budget at the aim that its indirect sun is
/// always given (SunRoundCase): with the sky at the aim itself a quarter more keeps it within
/// the target (0.9 sqrt(1.25) = 1.006 x aim ~ target), at a bounded count of photons.
constexpr double SunCaseBudgetFloor = 0.25;

struct SunRoundCase {
  std::string name;     ///< the case's, for the log lines
  std::size_t sun = 0;  ///< index into the rounds' suns
  /// Per grid, per sensor: the case's illuminance without its indirect sun (lux) and the variance
  /// of those parts (lux^2): the sky, the ground and the exact direct sun.
  std::vector<std::vector<double>> other_lux, other_variance;
};

/// The measure of one case at one grid (SunRoundCase): its illuminance in lux as df_percent, the
/// other parts' variance as direct_variance, per bin the indirect sun's.
GridVariance sun_case_variance(const RadianceMatrix& coefficients, const std::vector<double>& variance,
                               const engine::SunBins& bins, const sky::SunRecord& sun,
                               const std::vector<double>& other_lux, const std::vector<double>& other_variance);

/// Everything one case's sun rounds need.
struct SunAccuracyCase {
  const engine::Scene* scene = nullptr;
  const std::vector<engine::Material>* materials = nullptr;
  const engine::SunBins* bins = nullptr;
  const std::vector<sky::SunRecord>* suns = nullptr;
  const std::vector<engine::ReceiverPlane>* planes = nullptr;
  const std::vector<int>* plane_of_grid = nullptr;  ///< receiver plane of each grid, or -1
  /// Per plane, its sensors next to a cut, gathered (CaseLayout::near_cut_sensors); null: none.
  const std::vector<std::size_t>* near_cut_sensors = nullptr;
  const std::vector<SensorGrid>* grids = nullptr;
  bool gather = true;                    ///< grids off a plane: final gather (else surface photons)
  engine::TracingOptions tracing;        ///< the sun's: seed, photons_per_source = the reference count
  engine::CoefficientOptions estimating; ///< the sun's (sun-bin bandwidth); its gather weights: sun_annual_estimating
  /// The point-in-time cases whose illuminance the rounds measure (SunRoundCase); null or empty:
  /// the annual sun-bin value.
  const std::vector<SunRoundCase>* cases = nullptr;
};

/// What the sun rounds did (summary.json `accuracy.sun` of each grid, docs/outputs.md).
struct SunAccuracyOutcome {
  double target_percent = 0;
  std::vector<double> reached_percent;  ///< per grid: annual measure at the percentile
  std::vector<double> hourly_percent;   ///< per grid: hourly measure at the percentile (not targeted)
  std::vector<std::string> grid_status; ///< per grid: "met", "above target"
  std::vector<GatherAccuracy> gather;    ///< per grid: its gather rounds (gather_accuracy_rounds.h)
  std::vector<NearCutReached> near_cut;  ///< per grid: its sensors next to a cut (accuracy_policy.h)
  /// With point-in-time cases (SunRoundCase): per grid, per case, the case's relative standard
  /// error at the percentile after the last round (reached_percent is then the grid's largest).
  std::vector<std::vector<double>> case_reached_percent;
  std::size_t rounds = 0;
  std::uint64_t photons = 0;            ///< stored photons of all sun bins
  std::uint64_t attempts = 0;
  /// "target met", "photon budget", "round limit", "no light", "other parts" (point-in-time cases only: SunRoundCase), or, when only gathered grids
  /// were left above the target, the first such grid's gather stop (settle_case_stop)
  std::string stop_reason;
  std::vector<std::uint64_t> pilot_attempts, final_attempts;  ///< per bin (of a run that traced)
};

struct SunAccuracyResult {
  std::vector<RadianceMatrix> coefficients;   ///< per grid: sensors x bins x RGB (sun_bin_coefficients)
  std::vector<std::vector<double>> variance;  ///< per grid: sensors x bins
  SunAccuracyOutcome outcome;
};

/// The sun rounds of one case; `log` receives one line per round and the stop. The tracing
/// (the pilot's doublings, each round's extension of the bins' attempt prefixes) and each
/// round's estimates (sensor blocks) go through `work` (round_work.h): collective when it
/// spans several processes, every one of which then runs these rounds alike and returns the
/// same result.
SunAccuracyResult run_sun_accuracy_rounds(const SunAccuracyCase& c, const AccuracyGoal& goal,
                                          const std::function<void(const std::string&)>& log, RoundWork& work);
/// The same in this process alone (make_local_round_work).
SunAccuracyResult run_sun_accuracy_rounds(const SunAccuracyCase& c, const AccuracyGoal& goal,
                                          const std::function<void(const std::string&)>& log);

/// "sun-bin annual illuminance relative standard error (95th percentile) 0.8 % <= target 1 %
/// (hourly 6.1 %): target met after 2 round(s), 3.1 M photons".
std::string sun_accuracy_sentence(const SunAccuracyOutcome& outcome, std::size_t grid);

}  // namespace dayphoton::study
