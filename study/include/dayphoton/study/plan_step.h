// Step: one unit of a run's plan (simulation_plan.h): the artefacts it produces, their cache
// keys, how to compute them and how to take them back from bytes. Steps are what a
// StepExecutor (step_executor.h) looks up in the cache, runs when missing and stores.
//
// A step's result travels as BYTES, encoded with the artefact codec (artifact_codec.h): the
// same bytes the cache stores. That is what lets another process compute a step (an MPI rank,
// docs/architecture.md "Plan and executor") and hand the result back: a step's compute must
// be a pure function of the step's inputs (the plan's options and seed, the scene, the
// source, bin or grid it is for), never of the thread or process that runs it.
//
// Typed results: compute() both keeps its typed value where the caller wants it (the slot a
// make_step closure captures) and returns the encoded bytes for the cache; take() decodes
// bytes from the cache (or from another process) into the same slot. So a local run never
// decodes what it has just computed, and a cached one decodes each artefact once.
//
// Sensor blocks: a step that estimates a grid (sky or sun coefficients, the direct sun) may
// also say how to compute its outputs for a range of the grid's sensors and how to join such
// blocks (SensorBlocks). An executor over several processes then shares the blocks out
// (distributed_executor.h); the joined bytes are those compute() returns, so the artefact and
// its key are the same whichever way it was made. The local executor ignores the blocks.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace dayphoton::study {

struct PhotonRanges;  // photon_range_step.h

/// What a step computes; its artefacts' cache kinds are in docs/cache.md.
enum class StepKind {
  SkyMatrix,        ///< the annual sky matrix ("sky"; with sun bins also "suns")
  SourcePhotons,    ///< the photons of one sky source ("photons")
  SunBinPhotons,    ///< the photons of one sun bin ("sun-photons")
  SkyCoefficients,  ///< the daylight coefficients of one grid ("coefficients")
  SunCoefficients,  ///< a grid's sun-bin coefficients and their variance ("sun-coefficients", "-variance")
  DirectSun,        ///< a grid's exact direct sun for a list of suns ("sun-direct")
};

/// The step kind's name, for logs and tests ("source photons", ...).
const char* step_kind_name(StepKind kind);

/// One artefact of the cache: its kind and key (ArtifactStore::path_for).
struct ArtifactId {
  std::string kind;
  std::string key;
};

/// A grid step split by sensors (header comment).
struct SensorBlocks {
  std::size_t sensors = 0;  ///< rows of every output: the grid's sensors
  /// The outputs' bytes for sensors [begin, end), each encoded as its codec encodes a grid of
  /// those sensors alone. Pure, as compute is; may run on several threads at once.
  std::function<std::vector<std::string>(std::size_t begin, std::size_t end)> compute_rows;
  /// Blocks' outputs in sensor order (each compute_rows' result) joined into the outputs'
  /// bytes, byte for byte those compute() returns.
  std::function<std::vector<std::string>(const std::vector<std::vector<std::string>>& blocks)> join;
};

struct Step {
  StepKind kind = StepKind::SourcePhotons;
  std::size_t index = 0;            ///< the source, sun bin or grid it is for, within its batch
  std::vector<ArtifactId> outputs;  ///< what it produces (usually one artefact), stored together
  /// Computes the step: the encoded bytes of every output, in the order of `outputs`. Keeps
  /// its typed result itself (see the header comment). Pure: see the header comment.
  std::function<std::vector<std::string>()> compute;
  /// Takes the outputs' bytes computed elsewhere (the cache, another process): decodes them
  /// into the typed result and checks that they fit the step (dimensions). Returns false or
  /// throws when they do not: a cached artefact is then computed again.
  std::function<bool(const std::vector<std::string>&)> take;
  /// A photon step's source traced in attempt ranges (photon_range_step.h), which an executor
  /// may use instead of compute() to share one source over several processes; null for
  /// every other step. Gives the bytes compute() gives.
  std::shared_ptr<const PhotonRanges> ranges;
  /// Optional: an estimate of compute()'s cost, for sharing a batch out over the ranks of an
  /// MPI run (distributed_executor.h): any unit, the same for the steps of a batch; finite and
  /// >= 0; a small fraction of compute's own cost (the estimates of a batch are shared out
  /// with equal costs before the batch). Used only when every missing step of the batch has
  /// one; empty: equal costs. Pure like compute; it decides where a step runs, never what it
  /// yields.
  std::function<double()> cost;
  /// Optional: the step by sensor blocks (header comment).
  std::optional<SensorBlocks> blocks;
  /// compute() takes every process of the run (it calls the executor's RoundWork,
  /// round_work.h: the accuracy rounds): an executor over several processes runs it on every
  /// process alike, rather than on one; every process then holds its typed result.
  bool collective = false;
};

/// A step of one artefact of type T: `compute` returns the value, which is kept in `slot`
/// and encoded with `encode` for the cache; `decode` is the codec's decoder and `fits` checks a
/// decoded value against the step (e.g. its rows are the grid's sensors).
template <class T, class Compute, class Encode, class Decode, class Fits>
Step make_step(StepKind kind, std::size_t index, ArtifactId output, T& slot, Compute compute, Encode encode,
               Decode decode, Fits fits) {
  Step s;
  s.kind = kind;
  s.index = index;
  s.outputs.push_back(std::move(output));
  s.compute = [&slot, compute, encode]() -> std::vector<std::string> {
    slot = compute();
    return {encode(slot)};
  };
  s.take = [&slot, decode, fits](const std::vector<std::string>& bytes) {
    if (bytes.size() != 1) return false;
    T value = decode(bytes[0]);
    if (!fits(value)) return false;
    slot = std::move(value);
    return true;
  };
  return s;
}

}  // namespace dayphoton::study
