// PhotonRanges: what a photon step (a sky source's, a sun bin's) offers an executor that
// traces one source in attempt ranges over several processes (docs/cluster.md, "Big sources
// in attempt ranges"): the source's pass control (engine/source_passes.h), the tracing of one
// range of its attempts, and the encoding of the assembled photons as the step's artefact.
//
// Driving the passes (next / trace the pass's ranges anywhere / record the summed counts /
// finish with the ranges appended in attempt order) gives exactly the photons the step's
// compute() traces in one process, so `encode` returns the same bytes compute() does.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dayphoton/engine/material.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/port_emission.h"
#include "dayphoton/engine/receiver_plane.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/engine/source_passes.h"
#include "dayphoton/engine/sun_bins.h"

namespace dayphoton::study {

struct PhotonRanges {
  /// The step's predicted cost relative to a sky bin at the project's photons per bin (its
  /// photon target's factor: the ground 16, GroundPhotonFactor in plan_policy.h).
  double cost = 1;
  /// A fresh pass control of the source, nothing traced.
  std::function<engine::SourcePasses()> passes;
  /// Attempts [first, last) of the source with the storage probabilities of their pass.
  std::function<engine::AttemptRange(std::uint64_t first, std::uint64_t last, const engine::StorageProbabilities&)>
      trace;
  /// The step's artefact bytes for the source's finished photons (SourcePasses::finish).
  std::function<std::string(const engine::TracedPhotons&)> encode;
};

/// The ranges of sky source `source` of `emitter`, traced with `options` (as
/// engine::trace_source_photons). Keeps references: every argument must outlive the result.
std::shared_ptr<const PhotonRanges> sky_source_ranges(const engine::Scene& scene,
                                                      const std::vector<engine::Material>& materials,
                                                      const engine::PortEmitter& emitter,
                                                      const std::vector<engine::ReceiverPlane>& planes,
                                                      const engine::TracingOptions& options, std::size_t source);

/// The ranges of sun bin `bin` traced alone (as study::trace_sun_bin: its own disc, seed and
/// options, photons labelled source 0); owns its source set and emitter, keeps references to
/// the other arguments.
std::shared_ptr<const PhotonRanges> sun_bin_ranges(const engine::Scene& scene,
                                                   const std::vector<engine::Material>& materials,
                                                   const engine::SunBins& bins, std::size_t bin,
                                                   const std::vector<engine::ReceiverPlane>& planes,
                                                   const engine::TracingOptions& options);

}  // namespace dayphoton::study
