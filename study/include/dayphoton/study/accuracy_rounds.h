// The accuracy target (`simulation.accuracy`, docs/photon-tracing.md "Accuracy target"):
// instead of a photon count, the run traces the sky sources in rounds until the daylight
// factors reach a relative Monte Carlo standard error.
//
// Round 1 (the pilot) traces every source to a quarter of the reference count (photons_per_bin,
// the ground 16 times as many) as engine::pilot_source_photons does, each doubling decided by
// engine::next_pilot_attempts. After each round the grids'
// coefficients are estimated with their variances (engine/estimate_variance.h), and each
// grid's measure is the 95th percentile (nearest rank) of its sensors' relative standard error
// of DF (sensors with DF > 0): the value that 95 % of the sensors reach. A percentile rather
// than the RMS, because the dark back of a room (low DF, large relative error) is what a
// user misses when it is averaged with the bright front; rather than the maximum, because
// one sensor in a corner would otherwise set the photon count of the whole run.
//
// The next round's photons per source follow from the variances (next_round_scale): a
// source's photon variance at a sensor falls as 1/N_p (its bandwidth grows with its count
// over a disc of fixed size: engine::GridPhotons::set_source_scale), so for one sensor the
// cheapest counts meeting its variance budget are Neyman's allocation, N_p proportional to
// sqrt(variance share / cost per photon) (Cochran, "Sampling Techniques", 3rd ed., 1977,
// section 5.5); each source takes the largest count any sensor below the percentile asks
// for. A source that brings no light to a failing sensor gets no photons after the pilot.
// The direct component's variance (shadow rays) does not fall with photons: a sensor whose
// direct variance alone exceeds its budget cannot be helped by photons and is left out of the
// photon plan. The direct part has its own round decision (next_direct_round): a grid whose
// failing sensors owe at least half their budget to the shadow rays gets more shadow rays per
// bin (its direct component traced again at the new count, by sensor blocks through the
// work) when that is needed or costs fewer rays than the photons, up to
// MaxDirectSamplesPerBin (plan_policy.h; the stop "direct rays limit").
//
// Beside each chased grid's DF the rounds measure the sky part of each point-in-time case whose
// sky is not of the DF's shape (AccuracyCase::case_skies: a CIE general sky or a weather hour
// weights the patches otherwise), each against itself, as one more GridVariance of that grid
// in the allocation; the rounds meet the target only when every measure does.
//
// Grids estimated by final gather are measured but not chased by this measure: their error is
// mostly the gather rays' (accuracy_policy.h); after the photon rounds their rays are raised
// in gather rounds (gather_accuracy_rounds.h), and the part of their error that rays do not
// lower asks for further photon rounds (next_gather_photons there).
//
// The loop (pilot, allocation, stops, log lines) is the one the sun bins' rounds share
// (study/src/accuracy_round_loop.h); this file holds the DF measure and the allocation.
// Rounds stop when every grid meets the target, or at the photon budget (stored photons of
// all sky sources), the time budget (checked before each round from the time per attempt so
// far: the one stop that depends on the machine, so not deterministic), the round limit, or
// when no source can help. Everything else is a pure function of the project and the seed:
// the same bytes for any number of threads and of MPI ranks. Under MPI every rank runs the
// rounds (round_work.h): the attempt ranges of the pilot and of each round are traced over
// the ranks and summed on every rank, each round's estimates go by sensor blocks over the
// ranks and are gathered on every rank, and the time budget reads rank 0's clock, so every
// rank takes the same decisions (docs/cluster.md "Accuracy rounds").
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/receiver_plane.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/study/gather_accuracy.h"
#include "dayphoton/study/round_work.h"

namespace dayphoton::study {

/// The percentile of the sensors' relative standard error that must reach the target.
constexpr double AccuracyPercentile = 95.0;
/// Rounds at most, the pilot included.
constexpr std::size_t MaxAccuracyRounds = 8;
/// The pilot's photons per source, as a fraction of the reference count.
constexpr double AccuracyPilotFraction = 0.25;
/// Each round aims below the target by this factor, so that the next measurement (itself an
/// estimate) passes without a round for the last few per cent.
constexpr double AccuracyRoundAim = 0.9;
/// No source's photons grow more than this factor in one round (the variances are measured
/// again before the next). The pilot's photons are a quarter of the reference count, and a
/// pilot 4 times above the target (the curvature correction's variance near walls) asks for a
/// 20-fold fall of the variance: 16 made such runs trace a third round
/// (docs/photon-tracing.md, "Allocation").
constexpr double AccuracyMaxGrowth = 32.0;

/// Presets of simulation.accuracy.preset: name and target (relative standard error of DF, %).
struct AccuracyPreset {
  const char* name;
  double target_percent;
};
constexpr AccuracyPreset AccuracyPresets[] = {{"draft", 5.0}, {"standard", 2.0}, {"final", 1.0}};

struct AccuracyGoal {
  double target_percent = 1.0;    ///< relative standard error of DF at the percentile, %
  std::uint64_t max_photons = 0;  ///< stored photons of all sky sources; 0 = no budget
  double max_seconds = 0;         ///< tracing and estimating; 0 = no budget
  /// No source's photons grow more than this factor in one round (tests set other caps to
  /// build rounds of their own).
  double max_growth = AccuracyMaxGrowth;
};

/// Nearest-rank percentile of 100 x stderr / DF over the sensors with DF > 0 (0 if none).
double percentile_relative_stderr_percent(const std::vector<double>& df_percent,
                                          const std::vector<double>& stderr_percent, double percentile);

/// Indices of the sensors with DF > 0 at or below that percentile (nearest rank), by relative
/// error `relative`: the sensors a round's allocation must bring under its budget.
std::vector<std::size_t> sensors_at_or_below_percentile(const std::vector<double>& relative,
                                                        const std::vector<double>& df, double percentile);

/// One grid's variances after a round, in (DF percent)^2.
struct GridVariance {
  std::vector<double> df_percent;       ///< per sensor
  std::vector<double> direct_variance;  ///< per sensor, all sources
  std::vector<double> photon_variance;  ///< [sensor x sources + source], at the current counts
  /// Per sensor (empty: none): left to the parts of its error these photons do not reduce, and
  /// not chased (a point-in-time case's sensor whose sky and direct sun keep it above:
  /// sun_accuracy_rounds.h, SunRoundCase).
  std::vector<char> left_out;
};

struct RoundPlan {
  std::vector<double> scale;        ///< photons per source relative to now (>= 1)
  std::size_t sensors_constrained = 0;
  std::size_t sensors_direct_limited = 0;  ///< above their budget by the direct variance alone
  std::size_t sensors_left_out = 0;        ///< at or below the percentile, GridVariance::left_out
};

/// One sensor's share of an allocation (header comment): with `variance[p]` its photon variance
/// from source p at the current counts ((DF percent)^2, `cost.size()` of them) and `budget` what
/// their sum may be, raises scale[p] to Neyman's factor sqrt(a_p / c_p) sum_q sqrt(a_q c_q) /
/// budget for every source with variance and cost (never lowers it). `budget` > 0.
void raise_to_neyman_scale(const double* variance, const std::vector<double>& cost, double budget,
                           std::vector<double>& scale);

/// The next round's photon count of each source as a factor of its current count, for every
/// grid's sensors at or below the percentile whose relative standard error exceeds `aim_percent`
/// (header comment), each at most `max_growth`. `cost` is the cost of a source's photons so
/// far (rays cast).
RoundPlan next_round_scale(const std::vector<GridVariance>& grids, const std::vector<double>& cost,
                           double aim_percent, double percentile,
                           double max_growth = AccuracyMaxGrowth);

/// The direct component's variance at a sensor falls with its shadow rays per bin n as
/// n^(-DirectVarianceExponent) when planning a raise: the stratified estimator's law at a
/// shadow edge (engine/direct_component.h: error n^(-3/4); n^(-1) or faster where T cos is
/// smooth), the slower of the two, so a raise never plans too few rays for the edges; the
/// next round measures the variance again.
constexpr double DirectVarianceExponent = 1.5;

/// Shadow rays per sensor of the direct component at `samples_per_bin` (rounded up to a square
/// k x k, as engine::direct_coefficients does): k^2 per source, plus (PortStrataFactor k)^2 on
/// each of the two sides of the ports with port sampling (direct_component.h, an upper
/// bound: a side without ports traces none).
double direct_rays_per_sensor(int samples_per_bin, std::size_t sources, bool port_sampling);

/// The next round's direct part (next_direct_round).
struct DirectRoundPlan {
  std::vector<int> samples_per_bin;  ///< per grid of `grids`: the next round's count (= now if not raised)
  RoundPlan photons;                 ///< the photon plan with the raised grids' predicted direct variance
  double rays = 0;                   ///< shadow rays the raise traces (direct_rays_per_sensor x sensors; 0: none)
  /// Sensors above their budget by the direct variance alone in grids already at
  /// MaxDirectSamplesPerBin (plan_policy.h): neither photons nor the rounds' rays help them.
  std::size_t sensors_at_limit = 0;
  /// The shadow rays per bin those sensors are at (the largest over their grids, rounded up to a
  /// square as the direct component traces them): MaxDirectSamplesPerBin, or a project's own
  /// count above it; 0 when sensors_at_limit is 0.
  int samples_at_limit = 0;
  bool raised() const { return rays > 0; }
};

/// Whether the next round raises the shadow rays of some grids, and the photon plan that goes
/// with it. `grids` and `samples_per_bin`, `sensors` (per grid), `cost` and `photons` (the
/// plan of next_round_scale for the variances as they are) as measured. A grid is raised when
/// one of its sensors at or below the percentile above the aim has a direct variance of at least
/// half its budget (the direct part is what keeps it above), to the smallest k' = 2k or 4k
/// (at most MaxDirectSamplesPerBin) that brings every such sensor's predicted direct variance
/// (DirectVarianceExponent) to half its budget, and only if it is needed (a sensor's direct
/// variance alone exceeds its budget: photons cannot help) or cheaper: its shadow rays plus the
/// photon plan with the predicted variance cost fewer rays than the plan without. Grids in
/// order, each decided against the plan with the raises before it: a pure function of its
/// arguments, so every process decides alike.
DirectRoundPlan next_direct_round(const std::vector<GridVariance>& grids, const std::vector<int>& samples_per_bin,
                                  const std::vector<std::size_t>& sensors, const std::vector<double>& cost,
                                  const RoundPlan& photons, double aim_percent, double percentile, std::size_t sources,
                                  bool port_sampling);

/// What the rounds did (summary.json `accuracy` of each grid, docs/outputs.md).
struct AccuracyOutcome {
  double target_percent = 0;
  std::vector<double> reached_percent;  ///< per grid: the percentile after the last round
  std::size_t rounds = 0;
  std::uint64_t photons = 0;            ///< stored photons of all sky sources
  std::uint64_t attempts = 0;
  /// "target met", "not reachable by photons" (every grid the photons serve met it, a gathered
  /// grid did not: accuracy_policy.h), "photon budget", "time budget", "round limit",
  /// "direct component", "direct rays limit" (the sensors still above the target are so by
  /// their direct variance at MaxDirectSamplesPerBin), "no light"
  std::string stop_reason;
  /// Per grid: the shadow rays per bin of its final direct component (the project's
  /// direct_samples_per_bin unless the rounds raised it).
  std::vector<int> direct_samples_per_bin;
  std::vector<std::string> grid_status;  ///< per grid: accuracy_grid_status (accuracy_policy.h)
  std::vector<GatherAccuracy> gather;    ///< per grid: its gather rounds (gather_accuracy_rounds.h)
  std::vector<NearCutReached> near_cut;  ///< per grid: its sensors next to a cut (accuracy_policy.h)
  /// Attempts per source after the pilot and at the end (of a run that traced; not cached).
  std::vector<std::uint64_t> pilot_attempts, final_attempts;
};

/// A point-in-time case's sky the rounds measure (AccuracyCase::case_skies).
struct CaseSky {
  std::string name;       ///< the case's name, for the log
  RadianceMatrix vector;  ///< its sky over the basis (bins x 1)
  /// The continuous sky of its direct part among the coefficients' (engine::DirectOptions::
  /// skies); nullopt: the basis's sum (a weather case).
  std::optional<std::size_t> direct_sky;
};

/// Everything one case's rounds need.
struct AccuracyCase {
  const engine::Scene* scene = nullptr;
  const std::vector<engine::Material>* materials = nullptr;
  const engine::SourceSet* sources = nullptr;
  const std::vector<engine::ReceiverPlane>* planes = nullptr;
  const std::vector<int>* plane_of_grid = nullptr;  ///< receiver plane of each grid, or -1
  /// Per plane, its sensors next to a cut, gathered (CaseLayout::near_cut_sensors); null: none.
  const std::vector<std::size_t>* near_cut_sensors = nullptr;
  const std::vector<SensorGrid>* grids = nullptr;
  bool gather = true;  ///< grids off a plane: final gather (else surface photons)
  engine::TracingOptions tracing;       ///< seed, region of interest, photons_per_source = the reference count
  engine::CoefficientOptions estimating;
  /// The measure's weights per source: DF = 100 sum_p w . C_p L_p / horizontal_illuminance_lux
  /// (the overcast sky; for the sun rounds' gathered grids, sun_accuracy_rounds.h, the year's
  /// weight A_k of each bin as a grey vector, so that the "DF" is the annual sun-bin value).
  const RadianceMatrix* overcast_vector = nullptr;
  double horizontal_illuminance_lux = 0;
  /// Point-in-time cases whose sky part the rounds hold to the target too, at every grid they
  /// chase (docs/photon-tracing.md "Point-in-time cases"): the 95th percentile of the sky
  /// part's relative standard error against the sky part itself (sky_illuminance_parts,
  /// daylight_factor.h). A case's parts each within the target keep their sum within it, so
  /// the sun rounds then hold its sun parts alike. Empty: the daylight factor alone.
  std::vector<CaseSky> case_skies;
  /// Each source was traced alone as source 0 (the sun bins): its photons are relabelled as
  /// source p when merged (round_photons, accuracy_round_loop.h).
  bool relabel_sources = false;
  /// The words of the gather rounds' log lines: "<round_name> gather round 2, grid ...;
  /// <measure_name> (95th percentile) ...".
  std::string round_name = "accuracy", measure_name = "DF relative standard error";
};

/// Rows [begin, end) of one grid's direct part into `out` (out.sensors = end - begin,
/// out.sources = `sources`): `whole` holds the whole grid's direct, direct_variance and
/// direct_on_skies (the rounds trace it once per shadow-ray count), or nothing (no direct
/// part, the sun bins' gathered grids: zeros).
void copy_direct_rows(const engine::DaylightCoefficients& whole, std::size_t begin, std::size_t end,
                      std::size_t sources, engine::DaylightCoefficients& out);
/// The same for the rows `which`, in that order (rows that need not be contiguous: a plane's
/// sensors next to a cut).
void copy_direct_rows(const engine::DaylightCoefficients& whole, const std::vector<std::size_t>& which,
                      std::size_t sources, engine::DaylightCoefficients& out);

/// A gathered grid's last estimate at more gather rays than the photon rounds' (its gather
/// rounds' result): kept while later photon rounds serve other grids, so that when it cannot be
/// gathered again its reported accuracy, rays and rounds still describe the estimate written
/// (gather_accuracy_rounds.h).
struct GatheredEstimate {
  engine::DaylightCoefficients coefficients;
  double reached_percent = 0;
  GatherAccuracy accuracy;  ///< accuracy.rays == 0: none yet
};

/// A plane's sensors next to a cut as the gather rounds estimated them (gather_accuracy_rounds.h):
/// their rows of the grid and the estimate of those rows alone.
struct NearCutEstimate {
  std::vector<std::size_t> rows;             ///< ascending; empty: none
  engine::DaylightCoefficients coefficients; ///< rows.size() sensors (its direct part the grid's rows)
};

struct AccuracyResult {
  std::vector<engine::DaylightCoefficients> coefficients;  ///< per grid
  AccuracyOutcome outcome;
  std::vector<GatheredEstimate> gathered;  ///< per grid, filled by the gather rounds (not cached)
  std::vector<NearCutEstimate> near_cut;   ///< per grid, filled by the gather rounds (not cached)
};

/// The rounds of one case; `log` receives one line per round and the stop. The tracing (the
/// pilot's doublings, each round's extension) and the estimates go through `work`
/// (round_work.h): collective when it spans several processes, every one of which then runs
/// these rounds alike and returns the same result.
AccuracyResult run_accuracy_rounds(const AccuracyCase& c, const AccuracyGoal& goal,
                                   const std::function<void(const std::string&)>& log, RoundWork& work);
/// The same in this process alone (make_local_round_work).
AccuracyResult run_accuracy_rounds(const AccuracyCase& c, const AccuracyGoal& goal,
                                   const std::function<void(const std::string&)>& log);

class StepExecutor;

/// The case's coefficients and outcome, one step of the plan (step_executor.h): from the
/// cache (kinds "coefficients" and "accuracy") when a run with the same inputs, goal and photon
/// keys made them and the executor does not force, else by run_accuracy_rounds, then cached. `photon_keys` are the count-controlled run's keys
/// of the sources; the goal and the rounds' policy constants are added to them.
struct CaseAccuracy {
  std::vector<engine::DaylightCoefficients> coefficients;
  AccuracyOutcome outcome;
  bool cached = false;
};
CaseAccuracy accuracy_coefficients(const AccuracyCase& c, const AccuracyGoal& goal, StepExecutor& executor,
                                   const std::vector<std::string>& photon_keys,
                                   const std::function<void(const std::string&)>& log);

/// The sentence of the report and the run log: "DF relative standard error (95th percentile)
/// 0.93 % <= target 1 %: target met after 3 rounds, 4.1 M photons".
std::string accuracy_sentence(const AccuracyOutcome& outcome, std::size_t grid);

}  // namespace dayphoton::study
