// Photons traced in rounds: see photon_rounds.h.
#include "dayphoton/engine/photon_rounds.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <tbb/parallel_for.h>

namespace dayphoton::engine {
namespace {

/// Entries (or attempts with nothing entering) after which a dark source's pilot stops: its
/// stored (or entering) fraction is then below 3 / 65536 at 95 % confidence, as the
/// pre-pass's give-up (photon_tracer.cpp).
constexpr std::uint64_t DarkSourceAttempts = 65536;

}  // namespace

std::uint64_t SourcePhotonRecord::stored() const {
  if (raw.tallies.empty()) return 0;
  const SourceTally& t = raw.tallies[0];
  return t.stored_global + t.stored_caustic + t.stored_direct;
}

SourcePhotonRecord empty_source_record(const Scene& scene, const std::vector<Material>& materials,
                                       const PortEmitter& emitter, const std::vector<ReceiverPlane>& planes,
                                       std::size_t source) {
  SourcePhotonRecord record;
  record.raw.planes.resize(planes.size());
  record.raw.tallies.resize(1);
  record.raw.tallies[0].bound_flux = emitter.bound_flux(static_cast<std::uint32_t>(source));
  record.raw.tallies[0].nothing_stores = !can_store_photons(scene, materials, planes);
  return record;
}

std::optional<std::uint64_t> next_pilot_attempts(const SourcePhotonRecord& record, std::size_t target,
                                                 std::size_t max_prepass_attempts_per_target) {
  const SourceTally& t = record.raw.tallies.at(0);
  if (target == 0 || !(t.bound_flux > 0) || t.nothing_stores) return std::nullopt;
  if (record.attempts == 0) return std::max<std::uint64_t>(1, (target + 3) / 4);
  const std::uint64_t limit =
      std::max<std::uint64_t>(1, std::uint64_t(max_prepass_attempts_per_target) * std::uint64_t(target));
  const std::uint64_t attempts = record.attempts;
  if (t.stored_global + t.stored_caustic >= target) return std::nullopt;
  if (attempts >= limit) return std::nullopt;
  if (t.entered == 0 && attempts >= DarkSourceAttempts) return std::nullopt;
  if (t.entered >= DarkSourceAttempts && t.stored_global + t.stored_caustic + t.stored_direct == 0) return std::nullopt;
  return std::min(limit, attempts * 2);
}

AttemptRange round_attempt_range(const Scene& scene, const std::vector<Material>& materials,
                                 const PortEmitter& emitter, const std::vector<ReceiverPlane>& planes,
                                 const TracingOptions& options, std::size_t source, std::uint64_t first,
                                 std::uint64_t last) {
  if (last > first && emitter.bound_flux(static_cast<std::uint32_t>(source)) > 0 &&
      can_store_photons(scene, materials, planes))
    return trace_attempt_range(scene, materials, emitter, planes, options, source, first, last, StorageProbabilities{});
  AttemptRange none;
  none.planes.resize(planes.size());
  return none;
}

void append_round_range(SourcePhotonRecord& record, std::uint64_t last, AttemptRange&& range) {
  TracedPhotons& to = record.raw;
  SourceTally& t = to.tallies.at(0);
  if (last <= record.attempts) return;
  to.surface.insert(to.surface.end(), range.surface.begin(), range.surface.end());
  to.planes.resize(std::max(to.planes.size(), range.planes.size()));
  for (std::size_t g = 0; g < range.planes.size(); ++g)
    to.planes[g].insert(to.planes[g].end(), range.planes[g].begin(), range.planes[g].end());
  if (t.bound_flux > 0 && !t.nothing_stores) t.prepass_attempts += last - record.attempts;
  t.entered += range.counts.entered;
  t.stored_global += range.counts.stored_global;
  t.stored_caustic += range.counts.stored_caustic;
  t.stored_direct += range.counts.stored_direct;
  t.rays += range.counts.rays;
  record.attempts = last;
  range = AttemptRange{};
}

void extend_source_photons(const Scene& scene, const std::vector<Material>& materials, const PortEmitter& emitter,
                           const std::vector<ReceiverPlane>& planes, const TracingOptions& options,
                           std::size_t source, std::uint64_t attempts, SourcePhotonRecord& record) {
  if (record.raw.tallies.empty()) record = empty_source_record(scene, materials, emitter, planes, source);
  if (attempts <= record.attempts) return;
  append_round_range(record, attempts,
                     round_attempt_range(scene, materials, emitter, planes, options, source, record.attempts, attempts));
}

SourcePhotonRecord pilot_source_photons(const Scene& scene, const std::vector<Material>& materials,
                                        const PortEmitter& emitter, const std::vector<ReceiverPlane>& planes,
                                        const TracingOptions& options, std::size_t source, std::size_t target) {
  SourcePhotonRecord record = empty_source_record(scene, materials, emitter, planes, source);
  while (const std::optional<std::uint64_t> next =
             next_pilot_attempts(record, target, options.max_prepass_attempts_per_target))
    extend_source_photons(scene, materials, emitter, planes, options, source, *next, record);
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

TracedPhotons scaled_merged_photons(const std::vector<SourcePhotonRecord>& records, bool label_by_record) {
  const std::size_t n = records.size();
  if (label_by_record && n > MaxPhotonSources)
    throw std::invalid_argument("photon rounds: " + std::to_string(n) + " records, but a photon record names at most " +
                                std::to_string(MaxPhotonSources) + " sources");
  TracedPhotons out;
  std::size_t plane_count = 0;
  for (const SourcePhotonRecord& r : records) plane_count = std::max(plane_count, r.raw.planes.size());
  // Each record's offsets in the merged vectors (merge_traced_photons' order: record by record).
  std::vector<std::size_t> surface_at(n + 1, 0);
  std::vector<std::vector<std::size_t>> plane_at(plane_count, std::vector<std::size_t>(n + 1, 0));
  for (std::size_t p = 0; p < n; ++p) {
    const TracedPhotons& raw = records[p].raw;
    surface_at[p + 1] = surface_at[p] + raw.surface.size();
    for (std::size_t g = 0; g < plane_count; ++g)
      plane_at[g][p + 1] = plane_at[g][p] + (g < raw.planes.size() ? raw.planes[g].size() : 0);
  }
  out.surface.resize(surface_at[n]);
  out.planes.resize(plane_count);
  for (std::size_t g = 0; g < plane_count; ++g) out.planes[g].resize(plane_at[g][n]);
  // The tallies as scaled_source_photons sets them (one per record; a record without one gets one).
  for (const SourcePhotonRecord& r : records) {
    const std::size_t first = out.tallies.size();
    if (r.raw.tallies.empty())
      out.tallies.emplace_back();
    else
      out.tallies.insert(out.tallies.end(), r.raw.tallies.begin(), r.raw.tallies.end());
    SourceTally& t = out.tallies[first];
    t.prepass_attempts = r.attempts;
    t.mainpass_attempts = 0;
    t.storage_probability_global = t.storage_probability_caustic = t.storage_probability_direct = 1;
    t.flux_per_attempt = r.attempts > 0 ? t.bound_flux / double(r.attempts) : 0.0;
  }
  std::vector<float> scale(n);
  {
    std::size_t first = 0;
    for (std::size_t p = 0; p < n; ++p) {
      scale[p] = static_cast<float>(out.tallies[first].flux_per_attempt);
      first += std::max<std::size_t>(1, records[p].raw.tallies.size());
    }
  }
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t p) {
    auto copy = [&](const std::vector<Photon>& from, Photon* to) {
      for (const Photon& ph : from) {
        Photon q = ph;
        for (float& f : q.flux) f *= scale[p];
        if (label_by_record) q.source = static_cast<std::uint32_t>(p);
        *to++ = q;
      }
    };
    const TracedPhotons& raw = records[p].raw;
    copy(raw.surface, out.surface.data() + surface_at[p]);
    for (std::size_t g = 0; g < raw.planes.size(); ++g) copy(raw.planes[g], out.planes[g].data() + plane_at[g][p]);
  });
  return out;
}

}  // namespace dayphoton::engine
