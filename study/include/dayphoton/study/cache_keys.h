// Cache keys of the pipeline's artefacts (docs/cache.md): what each step depends on, hashed.
//
//   photons of source p : the scene (materials, surfaces, ports), the receiver planes (height,
//                         facing, outline), the sky basis, source p, the tracing options
//   coefficients of a grid : the photon-pass key of every source, the grid's sensors,
//                         the estimate and direct-sampling options
//   sky matrix          : the weather file's bytes (the site comes from its header), the
//                         basis, the ground reflectance, the sky mode
// A changed sensor spacing therefore re-estimates without re-tracing (the plane is the same);
// a changed weather file re-multiplies only; a changed material re-traces everything.
#pragma once

#include <string>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/receiver_plane.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/study/content_hash.h"

namespace dayphoton::study {

/// Bumped whenever the engine's output for the same inputs changes (invalidates old caches).
constexpr int EngineCacheVersion = 1;

ContentHash scene_key(const SceneDescription& scene);
ContentHash planes_key(const std::vector<SensorGrid>& grids);
std::string photon_source_key(const ContentHash& scene, const ContentHash& planes,
                              const sky::PatchBasis& basis, std::size_t source,
                              const engine::TracingOptions& options);
std::string coefficients_key(const std::vector<std::string>& photon_keys, const SensorGrid& grid,
                             const engine::CoefficientOptions& options);

}  // namespace dayphoton::study
