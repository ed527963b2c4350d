// Photons traced in rounds: see photon_rounds.h.
#include "dayphoton/engine/photon_rounds.h"

#include <algorithm>
#include <cmath>

namespace dayphoton::engine {
namespace {

/// Entries (or attempts with nothing entering) after which a dark source's pilot stops: its
/// stored (or entering) fraction is then below 3 / 65536 at 95 % confidence, as the
/// pre-pass's give-up (photon_tracer.cpp).
constexpr std::uint64_t DarkSourceAttempts = 65536;

void append(TracedPhotons& to, TracedPhotons&& more) {
  to.surface.insert(to.surface.end(), more.surface.begin(), more.surface.end());
  to.planes.resize(std::max(to.planes.size(), more.planes.size()));
  for (std::size_t g = 0; g < more.planes.size(); ++g)
    to.planes[g].insert(to.planes[g].end(), more.planes[g].begin(), more.planes[g].end());
  SourceTally& t = to.tallies.at(0);
  const SourceTally& m = more.tallies.at(0);
  t.prepass_attempts += m.prepass_attempts;
  t.entered += m.entered;
  t.stored_global += m.stored_global;
  t.stored_caustic += m.stored_caustic;
  t.stored_direct += m.stored_direct;
  t.rays += m.rays;
  t.bound_flux = m.bound_flux;
  t.nothing_stores = m.nothing_stores;
}

}  // namespace

std::uint64_t SourcePhotonRecord::stored() const {
  if (raw.tallies.empty()) return 0;
  const SourceTally& t = raw.tallies[0];
  return t.stored_global + t.stored_caustic + t.stored_direct;
}

void extend_source_photons(const Scene& scene, const std::vector<Material>& materials, const PortEmitter& emitter,
                           const std::vector<ReceiverPlane>& planes, const TracingOptions& options,
                           std::size_t source, std::uint64_t attempts, SourcePhotonRecord& record) {
  if (record.raw.tallies.empty()) {
    record.raw.planes.resize(planes.size());
    record.raw.tallies.resize(1);
    record.raw.tallies[0].bound_flux = emitter.bound_flux(static_cast<std::uint32_t>(source));
  }
  if (attempts <= record.attempts) return;
  append(record.raw,
         trace_source_attempts(scene, materials, emitter, planes, options, source, record.attempts, attempts));
  record.attempts = attempts;
}

SourcePhotonRecord pilot_source_photons(const Scene& scene, const std::vector<Material>& materials,
                                        const PortEmitter& emitter, const std::vector<ReceiverPlane>& planes,
                                        const TracingOptions& options, std::size_t source, std::size_t target) {
  SourcePhotonRecord record;
  extend_source_photons(scene, materials, emitter, planes, options, source, 0, record);
  const SourceTally& t = record.raw.tallies[0];
  if (target == 0 || !(t.bound_flux > 0) || !can_store_photons(scene, materials, planes)) {
    record.raw.tallies[0].nothing_stores = !can_store_photons(scene, materials, planes);
    return record;
  }
  const std::uint64_t limit = std::max<std::uint64_t>(
      1, std::uint64_t(options.max_prepass_attempts_per_target) * std::uint64_t(target));
  std::uint64_t attempts = std::max<std::uint64_t>(1, (target + 3) / 4);
  for (;;) {
    extend_source_photons(scene, materials, emitter, planes, options, source, attempts, record);
    const SourceTally& now = record.raw.tallies[0];
    if (now.stored_global + now.stored_caustic >= target) break;
    if (attempts >= limit) break;
    if (now.entered == 0 && attempts >= DarkSourceAttempts) break;
    if (now.entered >= DarkSourceAttempts && now.stored_global + now.stored_caustic + now.stored_direct == 0) break;
    attempts = std::min(limit, attempts * 2);
  }
  return record;
}

TracedPhotons scaled_source_photons(const SourcePhotonRecord& record) {
  TracedPhotons out = record.raw;
  if (out.tallies.empty()) out.tallies.resize(1);
  SourceTally& t = out.tallies[0];
  t.prepass_attempts = record.attempts;
  t.mainpass_attempts = 0;
  t.storage_probability_global = t.storage_probability_caustic = t.storage_probability_direct = 1;
  t.flux_per_attempt = record.attempts > 0 ? t.bound_flux / double(record.attempts) : 0.0;
  const float scale = static_cast<float>(t.flux_per_attempt);
  auto rescale = [scale](std::vector<Photon>& photons) {
    for (Photon& p : photons)
      for (float& f : p.flux) f *= scale;
  };
  rescale(out.surface);
  for (auto& plane : out.planes) rescale(plane);
  return out;
}

}  // namespace dayphoton::engine
