// The attempt ranges of a photon step: see photon_range_step.h.
#include "dayphoton/study/photon_range_step.h"

#include <mutex>

#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/artifact_codec.h"

namespace dayphoton::study {
namespace {

/// A sun bin's one-disc source set, options and emitter, owned by its ranges. The emitter is
/// built on first use (from any thread): a local run never asks for it.
struct OwnedEmitter {
  const engine::Scene* scene = nullptr;
  engine::SourceSet sources;
  engine::TracingOptions options;

  const engine::PortEmitter& emitter() {
    std::call_once(m_built, [this] { m_emitter = std::make_unique<engine::PortEmitter>(*scene, sources); });
    return *m_emitter;
  }

 private:
  std::once_flag m_built;
  std::unique_ptr<engine::PortEmitter> m_emitter;
};

}  // namespace

std::shared_ptr<const PhotonRanges> sky_source_ranges(const engine::Scene& scene,
                                                      const std::vector<engine::Material>& materials,
                                                      const engine::PortEmitter& emitter,
                                                      const std::vector<engine::ReceiverPlane>& planes,
                                                      const engine::TracingOptions& options, std::size_t source) {
  auto r = std::make_shared<PhotonRanges>();
  r->cost = source < options.source_photon_factor.size() ? options.source_photon_factor[source] : 1.0;
  r->passes = [&scene, &materials, &emitter, &planes, &options, source] {
    return engine::SourcePasses(scene, materials, emitter, planes, options, source);
  };
  r->trace = [&scene, &materials, &emitter, &planes, &options, source](std::uint64_t first, std::uint64_t last,
                                                                        const engine::StorageProbabilities& storage) {
    return engine::trace_attempt_range(scene, materials, emitter, planes, options, source, first, last, storage);
  };
  r->encode = [](const engine::TracedPhotons& photons) { return encode_photons(photons); };
  return r;
}

std::shared_ptr<const PhotonRanges> sun_bin_ranges(const engine::Scene& scene,
                                                   const std::vector<engine::Material>& materials,
                                                   const engine::SunBins& bins, std::size_t bin,
                                                   const std::vector<engine::ReceiverPlane>& planes,
                                                   const engine::TracingOptions& options) {
  auto owned = std::make_shared<OwnedEmitter>();
  owned->sources = sun_bin_source(bins, bin);
  owned->options = sun_bin_tracing(options, bins, bin);
  owned->scene = &scene;
  auto r = std::make_shared<PhotonRanges>();
  r->cost = 1.0;  // every sun bin has the same target
  r->passes = [&scene, &materials, &planes, owned] {
    return engine::SourcePasses(scene, materials, owned->emitter(), planes, owned->options, 0);
  };
  r->trace = [&scene, &materials, &planes, owned](std::uint64_t first, std::uint64_t last,
                                                  const engine::StorageProbabilities& storage) {
    return engine::trace_attempt_range(scene, materials, owned->emitter(), planes, owned->options, 0, first, last,
                                       storage);
  };
  r->encode = [](const engine::TracedPhotons& photons) { return encode_photons(photons); };
  return r;
}

}  // namespace dayphoton::study
