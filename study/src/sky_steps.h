// The annual sky of a run, one cached step (StepKind::SkyMatrix) built or loaded once per run
// and kept in the RunContext: the RADIANCE-compatible matrix with the sun spread into patches
// (`sun: spread`), or the matrix without the sun and the hourly suns (`sun: bins`).
#pragma once

#include "dayphoton/project/project.h"
#include "run_context.h"

namespace dayphoton::study {

/// The annual sky of the project's weather file, from the cache when the file is unchanged.
const AnnualSky& annual_sky(const project::Project& project, RunContext& ctx);

/// The sun-bins mode's sky (without the sun) and suns, from the cache when the weather file
/// is unchanged: the matrix under kind "sky" and the suns under kind "suns", same key.
const SkyAndSuns& sky_and_suns(const project::Project& project, RunContext& ctx);

}  // namespace dayphoton::study
