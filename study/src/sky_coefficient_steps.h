// The sky side of a case as plan steps: one StepKind::SourcePhotons step per sky source
// (handed to the executor as one batch: a killed run loses at most the sources in flight) and
// one StepKind::SkyCoefficients step per grid. The photons are traced only when some grid's
// coefficients are not cached. With an accuracy target the rounds replace both (one step).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/distant_source.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/accuracy_rounds.h"
#include "run_context.h"

namespace dayphoton::study {

/// The cache key of every sky source's photons (cache_keys.h photon_source_key).
std::vector<std::string> sky_photon_keys(const CaseScene& cs, const sky::PatchBasis& basis, std::size_t sources,
                                         const engine::TracingOptions& tracing);

/// The daylight coefficients of every grid of the case into `coefficients`: each from the
/// cache, or estimated from the sources' photons (from the cache or traced). `prefix` starts
/// the log lines of a variant.
void sky_coefficients(const CaseScene& cs, const engine::SourceSet& sources, const engine::TracingOptions& tracing,
                      const std::vector<std::string>& photon_keys, const std::string& prefix, RunContext& ctx,
                      std::vector<std::optional<engine::DaylightCoefficients>>& coefficients);

/// The same by the accuracy rounds (accuracy_rounds.h), one step: rounds of photons until the
/// daylight factors reach the project's accuracy target. Returns the rounds' outcome.
AccuracyOutcome accuracy_sky_coefficients(const project::Project& project, const CaseScene& cs,
                                          const engine::SourceSet& sources, const engine::TracingOptions& tracing,
                                          const std::vector<std::string>& photon_keys, const std::string& prefix,
                                          RunContext& ctx,
                                          std::vector<std::optional<engine::DaylightCoefficients>>& coefficients);

}  // namespace dayphoton::study
