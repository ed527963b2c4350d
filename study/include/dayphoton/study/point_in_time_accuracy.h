// A point-in-time case against the accuracy target (docs/photon-tracing.md "Accuracy target",
// "Point-in-time cases"): the statistic the daylight factor's target uses, the 95th percentile
// (nearest rank) of the sensors' relative standard error over the sensors with light
// (percentile_relative_stderr_percent, accuracy_rounds.h), of one case's illuminance at one
// grid, and which part of its variance (point_in_time_uncertainty.h) keeps it above the target:
// the sky and the ground, the indirect sun (the sun bins through the case's stencil) or the
// exact direct sun's shadow rays over the disc (its penumbra).
//
// The part is the one with the largest share of the relative variance summed over the sensors
// the target is decided by: those at or below the percentile whose relative error exceeds the
// target (sensors_at_or_below_percentile); over every sensor with light when none does. The
// shares are reported beside it in the run log and summary.json, so a user sees where the
// error of a case comes from even when it meets the target.
#pragma once

#include <string>
#include <vector>

#include "dayphoton/study/point_in_time_uncertainty.h"

namespace dayphoton::study {

/// One case at one grid against the target.
struct PointInTimeAccuracy {
  double target_percent = 0;   ///< the run's target (simulation.accuracy); 0: none (photon counts)
  double reached_percent = 0;  ///< the 95th percentile of the relative standard error, %
  /// "met", "above target", or "" without a target.
  std::string status;
  /// Why the case stopped where it is: "target met", or for a case above its target the stop
  /// of the part that keeps it there ("photon budget", "round limit", "direct rays limit", ...:
  /// point_in_time_stop_reason).
  std::string stop_reason;
  /// "sky", "indirect sun" or "direct sun": the part with the largest share (header comment).
  std::string limiting_part;
  /// Shares of the relative variance over the sensors of the header comment, summing to 1
  /// (all 0 when no sensor has light).
  double sky_share = 0, indirect_sun_share = 0, direct_sun_share = 0;
  /// Shadow rays per sun disc of the case's exact direct sun (0: the case has no sun).
  int direct_sun_samples = 0;
};

/// `value_lux`: the case's illuminance per sensor; `parts`: its variance by part. `target_percent`
/// 0 gives the statistic and the shares without a status.
PointInTimeAccuracy assess_point_in_time(const std::vector<double>& value_lux, const PointInTimeVarianceParts& parts,
                                         double target_percent);

/// The stop of a case above its target, from the stop of the rounds that serve its limiting
/// part: the sky's rounds (the daylight factor's), the point-in-time sun bins' rounds, or the
/// direct sun's shadow-ray raises. A part's rounds that met their own measure while the case is
/// still above it say so: "sky part: the sky rounds met the target on each part alone" (the
/// sky rounds hold the DF and each case's sky part to the target, each against itself: the
/// sky part of a case measured together with its sun can still be above it),
/// "indirect sun: the sun rounds met their own measure".
std::string point_in_time_stop_reason(const PointInTimeAccuracy& a, const std::string& sky_stop,
                                      const std::string& indirect_sun_stop, const std::string& direct_sun_stop);

/// The shadow rays over the sun's disc of a case's exact direct sun after one raise decision
/// (the sky's next_direct_round, accuracy_rounds.h, for one sun): with `samples` rays now
/// (rounded up to k x k strata as the direct sun traces them), per sensor the case's value
/// (lux), the variance of its other parts and of its direct sun (lux^2), a raise is made when a
/// sensor with light at or below the percentile, above the aim (AccuracyRoundAim x target), owes
/// at least half its budget (aim x value)^2 to the direct sun: to 2k x 2k, or 4k x 4k when the
/// predicted variance V_d (k / k')^(2 DirectVarianceExponent) is not yet under half the budget, at
/// most MaxDirectSamplesPerBin (plan_policy.h). Returns `samples` when no raise is made (none
/// needed, or already at the limit: a project's own count above it is kept).
int next_direct_sun_samples(const std::vector<double>& value_lux, const std::vector<double>& other_variance,
                            const std::vector<double>& direct_variance, int samples, double target_percent);

/// The run log's and the report's sentence: "relative standard error (95th percentile) 0.9 %
/// <= target 1 %: target met (variance: sky 20 %, indirect sun 70 %, direct sun 10 %; 64
/// shadow rays over the sun's disc)"; above the target "... 3.1 % > target 1 %: direct rays limit
/// (direct sun 80 % of the variance ...)".
std::string point_in_time_accuracy_sentence(const PointInTimeAccuracy& a);

}  // namespace dayphoton::study
