// The cost estimate of a sky source's photon step: see photon_step_cost.h.
#include "photon_step_cost.h"

#include <algorithm>

namespace dayphoton::study {

double photon_step_cost(const engine::Scene& scene, const std::vector<engine::Material>& materials,
                        const engine::PortEmitter& emitter, const std::vector<engine::ReceiverPlane>& planes,
                        const engine::TracingOptions& tracing, std::size_t source) {
  engine::TracingOptions pilot = tracing;
  pilot.photons_per_source = std::max<std::size_t>(1, tracing.photons_per_source / PilotPhotonDivisor);
  if (tracing.caustic_photons_per_source > 0)
    pilot.caustic_photons_per_source = std::max<std::size_t>(1, tracing.caustic_photons_per_source / PilotPhotonDivisor);
  return double(engine::trace_source_photons(scene, materials, emitter, planes, pilot, source).tallies.at(0).rays);
}

}  // namespace dayphoton::study
