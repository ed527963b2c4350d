// The run-log notes on a photon pass (sky sources or sun bins): sources capped by the
// low-yield rule, sources that stored nothing, and the warning when the capped sources
// bring so much of the light that the stated error does not cover their kernel bias.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "dayphoton/engine/photon_tracer.h"

namespace dayphoton::study {

/// The run-log note on sources whose main pass hit the low-yield cap
/// (engine::TracingOptions::max_mainpass_attempts_per_target), or "" if none did. `what`
/// names the sources ("sources", "sun bins"); the stored share is of the global target.
std::string capped_note(const engine::TracedPhotons& photons, const engine::TracingOptions& tracing,
                        const std::string& what);

/// Share of the stored photon flux (luminance, per unit radiance of each source; surface and
/// plane photons) that the capped sources which stored fewer than `below_photons` global
/// photons carry (infinity: every capped source); 0 when none or nothing is stored.
double capped_flux_share(const engine::TracedPhotons& photons, double below_photons);

/// A capped source that stored fewer global photons than this many bandwidths is starved: a
/// disc of `bandwidth` photons then covers a quarter or more of the area its photons reach,
/// and the kernel bias grows with the disc's area (photon-map.md, "Curvature away from
/// walls"); where such sources are the median source the sparse-source rule no longer keeps
/// their discs narrow (photon-map.md, "Sparse sources"). On projects/overhang at its own
/// settings the capped sources store more and the result stays within its noise.
inline constexpr int StarvedBandwidths = 4;

/// At this share of the stored photon flux from starved capped sources or more, the sources
/// are traced again with the cap in raw attempts where outdoor scatterers scaled it
/// (lifted_cap_sources), and the run warns if it is still reached (capped_warning): their
/// kernel bias, which the reported standard error does not include, becomes a bias of the
/// result (docs/photon-tracing.md, "Low-yield cap": a light pipe under an outdoor roof read
/// 6.6 % low on average over 24 seeds with the scaled cap alone).
inline constexpr double CappedFluxWarningShare = 0.2;

/// The sources to trace again with the cap counting raw attempts
/// (engine::TracingOptions::raw_attempt_cap), in increasing order, and the share of the stored
/// photon flux they carried.
struct LiftedCap {
  std::vector<std::size_t> sources;
  double flux_share = 0;
};

/// Every source of `per_source` (one traced source each, as trace_source_photons gives them)
/// that was capped and stored fewer than StarvedBandwidths x `bandwidth` global photons, when
/// these carry CappedFluxWarningShare or more of the stored photon flux; else none. With
/// outdoor scatterers the cap is scaled by a source's useful share, so its port gets about
/// M x target x share^2 attempts: a large scatterer around a small port (a roof around a light
/// pipe's collector) starves every source whatever its port brings, against the cap's premise
/// that capped sources bring little light. `scatterers`: the scene has outdoor scatterers
/// (without them the raw cap is the cap, and none is returned).
LiftedCap lifted_cap_sources(const std::vector<engine::TracedPhotons>& per_source, std::size_t bandwidth,
                             bool scatterers);

/// The run-log note on a LiftedCap ("" if it has no source): how many, the share of the flux
/// they carried, and the cap they were traced again with.
std::string lifted_cap_note(const LiftedCap& lifted, const engine::TracingOptions& tracing, std::size_t bandwidth,
                            const std::string& what);

/// The run-log warning (without location) when starved capped sources carry
/// CappedFluxWarningShare or more of the stored photon flux, else "". `bandwidth` is the
/// estimate's photons per disc (engine::DensityOptions::bandwidth); `what` as for capped_note.
std::string capped_warning(const engine::TracedPhotons& photons, const engine::TracingOptions& tracing,
                           std::size_t bandwidth, const std::string& what);

/// Sources whose photon pass stored nothing (engine::trace_source_photons): none traced when
/// nothing in the scene can store a photon, or stopped after the pre-pass's entries showed
/// that none is stored. "" when every source stored photons or was not lit.
std::string nothing_stored_note(const engine::TracedPhotons& photons, const std::string& what);

}  // namespace dayphoton::study
