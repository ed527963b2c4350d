// Photon-pass notes: see photon_pass_notes.h.
#include "photon_pass_notes.h"

#include <algorithm>
#include <cmath>

namespace dayphoton::study {

std::string capped_note(const engine::TracedPhotons& photons, const engine::TracingOptions& tracing,
                        const std::string& what) {
  std::size_t capped = 0;
  double least = 1, most = 0;
  for (std::size_t p = 0; p < photons.tallies.size(); ++p) {
    const engine::SourceTally& t = photons.tallies[p];
    if (!t.capped) continue;
    ++capped;
    const double factor = p < tracing.source_photon_factor.size() ? tracing.source_photon_factor[p] : 1.0;
    const double share = double(t.stored_global) / (double(tracing.photons_per_source) * factor);
    least = std::min(least, share);
    most = std::max(most, share);
  }
  if (capped == 0) return "";
  auto percent = [](double x) { return std::to_string(static_cast<long long>(std::lround(100 * x))); };
  return std::to_string(capped) + " of " + std::to_string(photons.tallies.size()) + " " + what +
         " capped at " + std::to_string(tracing.max_mainpass_attempts_per_target) +
         " main-pass attempts per target photon (low yield): they stored " + percent(least) + "-" +
         percent(most) + " % of their target; their flux stays unbiased, with more relative noise";
}

std::string nothing_stored_note(const engine::TracedPhotons& photons, const std::string& what) {
  std::size_t skipped = 0, stopped = 0;
  for (const engine::SourceTally& t : photons.tallies) {
    if (t.nothing_stores) ++skipped;
    else if (t.entered > 0 && t.stored_global + t.stored_caustic + t.stored_direct == 0) ++stopped;
  }
  if (skipped > 0)
    return "not traced: nothing in the scene can store a photon (no surface has a diffuse component, and no sensor "
           "plane can receive scattered light); the photon part of every " + what.substr(0, what.size() - 1) +
           " is zero and the results are its direct component alone";
  if (stopped > 0)
    return std::to_string(stopped) + " of " + std::to_string(photons.tallies.size()) + " " + what +
           " stored no photon: their light is absorbed before it reaches anything that stores photons (the pass "
           "stopped after 65536 entering photons)";
  return "";
}

}  // namespace dayphoton::study
