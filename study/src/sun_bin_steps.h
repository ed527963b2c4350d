// The sun side of a case in the sun-bins mode as plan steps (annual_sun.h): one
// StepKind::SunBinPhotons step per lit sun bin (one batch), and per grid a
// StepKind::SunCoefficients step and StepKind::DirectSun steps (the year's suns; with the
// export, also the further daytime positions of direct_sun.bin.gz). The bins' photons are
// traced only when some grid's sun coefficients are not cached.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/engine/sun_bins.h"
#include "dayphoton/study/sun_accuracy_rounds.h"
#include "run_context.h"

namespace dayphoton::study {

/// The sun side of one grid in the sun-bins mode.
struct GridSun {
  RadianceMatrix bin_coefficients;  ///< sensors x sun bins x RGB, caustic + global
  std::vector<float> bin_variance;  ///< sensors x sun bins, of each entry's luminance (as cached: float)
  RadianceMatrix direct;            ///< sensors x suns x RGB, exact direct sun (unless SunBinsDirect::ByTheCaller)
  /// For direct_sun.bin.gz (outputs.coefficients): the direct sun of the other daytime sun
  /// positions (direct_sun_file.h), sensors x other_suns x RGB.
  RadianceMatrix direct_other;
  std::vector<sky::SunRecord> other_suns;
};

/// Who traces the exact direct sun of the suns of run_sun_bins.
enum class SunBinsDirect {
  Traced,             ///< run_sun_bins, per grid (GridSun::direct)
  TracedAndExported,  ///< as Traced, and at the further daytime positions of direct_sun.bin.gz
  ByTheCaller,        ///< not traced: the caller has it (the point-in-time cases, each sun alone)
};

/// Sun bins of one case for the suns of `ss`: trace (one cached artefact per bin), estimate
/// per grid, and as `direct` says trace the exact direct sun per grid. Every step cached. With
/// simulation.accuracy the bins are traced in rounds (sun_accuracy_step.h) and
/// `accuracy_outcome`, if given, receives what they did (else it is reset). `cases`: with the
/// target, the point-in-time cases the rounds measure (SunRoundCase; null: the annual sun-bin
/// value).
std::vector<GridSun> run_sun_bins(const project::Project& project, const std::string& prefix, const CaseScene& cs,
                                  const SkyAndSuns& ss, const engine::SunBins& bins, RunContext& ctx,
                                  SunBinsDirect direct,
                                  std::optional<SunAccuracyOutcome>* accuracy_outcome = nullptr,
                                  const std::vector<SunRoundCase>* cases = nullptr);

}  // namespace dayphoton::study
