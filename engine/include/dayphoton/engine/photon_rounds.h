// Photons traced in rounds (the accuracy target, docs/photon-tracing.md "Accuracy target"):
// each source keeps the attempts [0, A) it has traced, unscaled, and a later round extends
// them to [0, A') with A' >= A. Attempt i of source p is a pure function of (seed, p, i)
// (photon_tracer.h), so a round only adds photons: those of earlier rounds are reused as they
// are, and the photons after any sequence of rounds are those of one pass of A' attempts.
// Every class is stored with probability 1 and every photon carries bound_flux / A (each
// attempt is an independent draw carrying that flux, port_emission.h), so the flux is
// unbiased for any A fixed before the round is traced.
//
// The pilot round sizes each source as the pre-pass of the two-pass scheme does (seeds/000
// Alg. 4.1): attempts doubled until the source stores its pilot target or is found dark; the
// only data-dependent stopping, as in the pre-pass.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/port_emission.h"

namespace dayphoton::engine {

/// One source's attempts [0, attempts), photons unscaled (flux relative to an attempt's).
struct SourcePhotonRecord {
  TracedPhotons raw;            ///< one tally: counts and rays of all attempts so far
  std::uint64_t attempts = 0;
  std::uint64_t stored() const;  ///< stored photons of every class (kept or only counted)
};

/// A source's record before its first attempt: its bound flux, whether anything stores.
SourcePhotonRecord empty_source_record(const Scene& scene, const std::vector<Material>& materials,
                                       const PortEmitter& emitter, const std::vector<ReceiverPlane>& planes,
                                       std::size_t source);

/// The pilot's next step for a source whose record holds its pilot so far (pilot_source_photons):
/// the attempts to extend the record to, or nothing when the pilot is done. Depends only on
/// the record's counts, which are sums over attempts: the attempts may be traced in ranges,
/// anywhere, and the decision is the same.
std::optional<std::uint64_t> next_pilot_attempts(const SourcePhotonRecord& record, std::size_t target,
                                                 std::size_t max_prepass_attempts_per_target);

/// Attempts [first, last) of a source as the rounds trace them (every class stored, each
/// photon's flux relative to its attempt's); an empty range for a source that is not traced
/// (zero bound flux, nothing stores). Any split of [a, b) appended in order gives [a, b).
AttemptRange round_attempt_range(const Scene& scene, const std::vector<Material>& materials,
                                 const PortEmitter& emitter, const std::vector<ReceiverPlane>& planes,
                                 const TracingOptions& options, std::size_t source, std::uint64_t first,
                                 std::uint64_t last);

/// Appends `range`, attempts [record.attempts, last) traced by round_attempt_range (in one
/// piece or several appended in order), to the record.
void append_round_range(SourcePhotonRecord& record, std::uint64_t last, AttemptRange&& range);

/// The pilot of one source: attempts doubled from ceil(target / 4) until `target` photons
/// (global and caustic) are stored, or options.max_prepass_attempts_per_target x target
/// attempts are made, or 65536 attempts saw nothing enter or 65536 entries stored nothing.
SourcePhotonRecord pilot_source_photons(const Scene& scene, const std::vector<Material>& materials,
                                        const PortEmitter& emitter, const std::vector<ReceiverPlane>& planes,
                                        const TracingOptions& options, std::size_t source, std::size_t target);

/// Trace attempts [record.attempts, attempts) and append them (nothing if attempts <= record.attempts).
void extend_source_photons(const Scene& scene, const std::vector<Material>& materials, const PortEmitter& emitter,
                           const std::vector<ReceiverPlane>& planes, const TracingOptions& options,
                           std::size_t source, std::uint64_t attempts, SourcePhotonRecord& record);

/// The record's photons with their flux, bound_flux / attempts each; the tally as
/// trace_source_photons reports it (all attempts in prepass_attempts, storage probabilities 1).
TracedPhotons scaled_source_photons(const SourcePhotonRecord& record);

/// The photons of every record with their flux, merged in record order: exactly what
/// merge_traced_photons of each record's scaled_source_photons gives, but made in one copy
/// (each record's photons scaled straight into the merged vectors at their offsets), so a round
/// holds the records and one merged copy, never the per-source copies beside them. With
/// `label_by_record`, record p's photons carry source p (a source traced alone as source 0).
TracedPhotons scaled_merged_photons(const std::vector<SourcePhotonRecord>& records, bool label_by_record);

}  // namespace dayphoton::engine
