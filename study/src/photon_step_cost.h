// The cost estimate of a sky source's photon step (Step::cost), for sharing a batch of them
// out over the ranks of an MPI run (docs/cluster.md "Cost-weighted assignment").
//
// What a source costs varies ten-fold between the sources of one sky (measured on the office
// at 10,000 photons per bin: 0.10 to 0.12 s for the ground, with 16 times the photons, and for
// a patch near the zenith, against 0.012 s on average), mostly through its yield, the attempts
// a stored photon takes, which only tracing tells. So the estimate is the rays cast by a pilot
// pass of the same source with a PilotPhotonDivisor-th of its photon targets (same tracing,
// same seed). Measured on the office (bench/mpi_strong_scaling): the pilots cost 0.09 s of
// CPU against 1.6 s for the sources, and the balance of the photon batches (the ranks' CPU
// over the largest rank's) rises from 1.95 to 1.98 of 2 ranks and from 2.56 to 2.93 of 3.
// The photon targets alone (the ground 16, a sky bin 1) balance worse than equal costs.
#pragma once

#include <cstddef>
#include <vector>

#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/port_emission.h"

namespace dayphoton::study {

constexpr std::size_t PilotPhotonDivisor = 20;

/// Rays cast by the pilot pass of source `source` (trace_source_photons with the targets of
/// `tracing` divided by PilotPhotonDivisor, at least 1).
double photon_step_cost(const engine::Scene& scene, const std::vector<engine::Material>& materials,
                        const engine::PortEmitter& emitter, const std::vector<engine::ReceiverPlane>& planes,
                        const engine::TracingOptions& tracing, std::size_t source);

}  // namespace dayphoton::study
