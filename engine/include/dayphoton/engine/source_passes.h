// The photon-count control of one source (the two-pass scheme of photon_tracer.h: pre-pass,
// main pass, top-up), as a sequence of passes decided from counts.
//
// A source's attempts are traced in passes, each a range [first, last) of its attempt
// sequence with the storage probabilities of that pass: the pre-pass as a run of doublings
// [0, n), [n, 2n), [2n, 4n), ..., then at most one main pass and one top-up. Which pass comes
// next depends only on the counts of the passes before it (AttemptCounts: entered attempts,
// stored photons per class, rays, scatterer attempts that entered a room), and each count is
// a sum over attempts. So a pass may be traced in any number of ranges, anywhere (threads,
// MPI ranks): the sum of the ranges' counts is the pass's count, and the decisions, the
// tally and (after finish) the photons are those of the source traced at once.
//
//   SourcePasses passes(scene, materials, emitter, planes, options, source);
//   AttemptRange photons;
//   while (std::optional<AttemptPass> pass = passes.next()) {
//     AttemptRange r = trace_attempt_range(..., pass->first, pass->last, pass->storage);
//     passes.record(r.counts);      // the counts of the WHOLE pass (summed over its ranges)
//     append_attempt_range(photons, std::move(r));
//   }
//   TracedPhotons traced = passes.finish(std::move(photons));   // = trace_source_photons
//
// Passes are contiguous: each starts where the one before ended, so the photons of all
// ranges appended in attempt order are the photons of [0, attempts) in the order one process
// stores them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "dayphoton/engine/material.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/port_emission.h"
#include "dayphoton/engine/receiver_plane.h"
#include "dayphoton/engine/scene.h"

namespace dayphoton::engine {

/// One pass: attempts [first, last) stored with `storage`.
struct AttemptPass {
  std::uint64_t first = 0, last = 0;
  StorageProbabilities storage;
};

class SourcePasses {
 public:
  /// The control of `source` of `emitter` (its bound flux, whether anything can store a
  /// photon, its share of port light), nothing traced yet. Keeps no reference to its arguments.
  SourcePasses(const Scene& scene, const std::vector<Material>& materials, const PortEmitter& emitter,
               const std::vector<ReceiverPlane>& planes, const TracingOptions& options, std::size_t source);

  /// The next pass to trace, or nothing when the source is done (at once for a source that is
  /// not traced: nothing stores, zero bound flux or zero target).
  std::optional<AttemptPass> next() const;

  /// The counts of the whole pass next() returned; decides the pass after it.
  void record(const AttemptCounts& pass_counts);

  /// The counts so far and the decisions taken (attempts, storage probabilities, capped).
  const SourceTally& tally() const { return m_tally; }

  /// The source's photons once next() is empty: `traced` holds the ranges of every pass
  /// appended in attempt order; each photon's flux is scaled per class
  /// (SourceTally::stored_photon_flux). Equals trace_source_photons for this source.
  TracedPhotons finish(AttemptRange&& traced) const;

 private:
  enum class Stage { PrePass, MainPass, TopUp, Done };

  void start_main_pass();
  double useful_share(std::uint64_t attempts) const;
  std::uint64_t scaled_limit(std::size_t per_target, std::uint64_t attempts) const;

  // Fixed at construction.
  double m_prepass_fraction;
  std::size_t m_max_prepass_per_target, m_max_mainpass_per_target;
  std::size_t m_planes;
  std::size_t m_target_g = 0, m_target_c = 0, m_target_d = 0, m_largest = 0;
  std::uint64_t m_initial = 1;
  double m_port_share = 1;
  bool m_raw_cap = false;  ///< TracingOptions::raw_attempt_cap for this source
  bool m_normalised = false;  ///< traced at all: the flux per attempt is set by finish

  // The passes so far.
  Stage m_stage = Stage::Done;
  AttemptPass m_pass;          ///< the pass next() returns
  std::uint64_t m_prepass = 0;  ///< the pre-pass's attempts so far (its end)
  std::uint64_t m_main = 0, m_cap = 0;
  std::uint64_t m_g0 = 0, m_c0 = 0, m_d0 = 0;  ///< stored counts before the main pass
  std::uint64_t m_scattered_indoors = 0;
  SourceTally m_tally;
};

}  // namespace dayphoton::engine
