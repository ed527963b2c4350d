// The annual multiply of a grid by sensor blocks over the ranks of an MPI run (docs/cluster.md
// "Sensor blocks"): each rank computes the hourly illuminance, the per-sensor metrics and the
// ASE hours of its blocks; rank 0 receives them, joins them in sensor order and adds what
// needs the whole grid (the grid's summary and sDA, EN 17037), then writes the files alone.
// Every per-sensor value is a function of that sensor's coefficients alone, so the study is
// the one compute_annual_study or compute_annual_study_with_sun makes, byte for byte.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/engine/sun_bins.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/study/annual_study.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/step_executor.h"

namespace dayphoton::study {

/// Collective over the executor's ranks (StepExecutor::shares_sensor_blocks must hold): the
/// annual study of a grid of sky coefficients `coefficients`, with the sun of `sun` (the
/// sun-bins mode, as compute_annual_study_with_sun) or without (as compute_annual_study).
/// Rank 0 (StepExecutor::writes_results) returns the whole study, the other ranks nothing.
/// `name` names the grid in errors. `shares`: the coefficients' sub-patch shares, every
/// rank's (compute_annual_study).
std::optional<AnnualStudy> annual_study_in_blocks(StepExecutor& executor, const std::string& name,
                                                  const RadianceMatrix& coefficients, const AnnualSky& sky,
                                                  const AnnualStudySettings& settings,
                                                  const GridSunCoefficients* sun = nullptr,
                                                  const SubPatchShares* shares = nullptr);

}  // namespace dayphoton::study
