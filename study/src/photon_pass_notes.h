// The run-log notes on a photon pass (sky sources or sun bins): sources capped by the
// low-yield rule, sources that stored nothing.
#pragma once

#include <string>

#include "dayphoton/engine/photon_tracer.h"

namespace dayphoton::study {

/// The run-log note on sources whose main pass hit the low-yield cap
/// (engine::TracingOptions::max_mainpass_attempts_per_target), or "" if none did. `what`
/// names the sources ("sources", "sun bins"); the stored share is of the global target.
std::string capped_note(const engine::TracedPhotons& photons, const engine::TracingOptions& tracing,
                        const std::string& what);

/// Sources whose photon pass stored nothing (engine::trace_source_photons): none traced when
/// nothing in the scene can store a photon, or stopped after the pre-pass's entries showed
/// that none is stored. "" when every source stored photons or was not lit.
std::string nothing_stored_note(const engine::TracedPhotons& photons, const std::string& what);

}  // namespace dayphoton::study
