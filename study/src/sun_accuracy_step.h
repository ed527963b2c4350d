// The sun bins' coefficients of a case by the accuracy target's sun rounds
// (sun_accuracy_rounds.h), as one step of the plan (step_executor.h): the coefficients and
// variances of every grid and the rounds' outcome, cached together. It replaces, with
// `simulation.accuracy`, the count-controlled sun photons (one step per bin) and sun
// coefficients (one step per grid) of sun_bin_steps.cpp; the direct sun is unchanged. The step
// is collective (Step::collective): under MPI every rank runs the rounds, their tracing and
// estimates shared through the executor's RoundWork (round_work.h).
#pragma once

#include <string>
#include <vector>

#include "dayphoton/engine/sun_bins.h"
#include "dayphoton/study/sun_accuracy_rounds.h"
#include "run_context.h"
#include "sun_bin_steps.h"

namespace dayphoton::study {

/// Fills bin_coefficients and bin_variance of every grid in `result` (sized to the grids),
/// estimated with `estimating` (the sun's, with the year's gather weights:
/// sun_annual_estimating); logs each round and a sentence per grid; returns the outcome.
/// `cases`: the point-in-time cases the rounds measure (SunRoundCase; null: the annual value),
/// their parts in the step's key.
SunAccuracyOutcome accuracy_sun_coefficients(const project::Project& project, const std::string& prefix,
                                             const CaseScene& cs, const std::vector<sky::SunRecord>& suns,
                                             const engine::SunBins& bins,
                                             const engine::CoefficientOptions& estimating, RunContext& ctx,
                                             std::vector<GridSun>& result,
                                             const std::vector<SunRoundCase>* cases = nullptr);

}  // namespace dayphoton::study
