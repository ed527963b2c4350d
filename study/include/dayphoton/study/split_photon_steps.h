// Photon steps traced in attempt ranges over the ranks of a distributed run (docs/cluster.md,
// "Big sources in attempt ranges"): the part of the distributed executor
// (distributed_executor.h) that shares ONE source over several ranks.
//
// Every rank runs the same rounds. In a round, each split source still tracing offers its
// next pass (engine/source_passes.h); the pass is cut into ranges of at least
// MinSplitRangeAttempts attempts (plan_policy.h), at most one per rank, and the ranges of every source are
// the jobs of one dist::distribute_jobs call (every rank receives every range, in job order,
// i.e. in source and then attempt order). Each rank appends a source's ranges to its photons
// and sums their counts; the summed counts of the whole pass decide the next pass, on every
// rank alike. A source whose passes are done is finished (its photons scaled), encoded as the
// step's artefact and handed to `deliver`, on every rank: the bytes of compute() in one process.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "dayphoton/dist/communicator.h"
#include "dayphoton/study/plan_step.h"

namespace dayphoton::study {

/// The steps among `misses` (indices into `steps`) to trace in attempt ranges over `ranks`
/// ranks: those with ranges whose cost exceeds 1/SplitSourceFactor of a rank's share of the
/// misses' total cost (plan_policy.h). None with one rank.
std::vector<std::size_t> photon_steps_to_split(const std::vector<Step>& steps, const std::vector<std::size_t>& misses,
                                               int ranks);

/// How one split source was traced: in how many attempt ranges, over how many passes.
struct SplitSourceRanges {
  std::size_t step = 0;    ///< index into the batch
  std::size_t ranges = 0;  ///< attempt ranges over all its passes
  std::size_t passes = 0;  ///< passes traced (rounds it took part in)
  std::uint64_t attempts = 0;  ///< attempts over all its passes
};

/// Traces steps[k] for every k of `split` (each with ranges) over comm's ranks and calls
/// deliver(k, artefacts) on every rank as each finishes (one artefact: the photons). A pass is
/// cut into ranges of at least `min_range_attempts` (the executor: MinSplitRangeAttempts,
/// plan_policy.h), at most one per rank. Collective. A range that throws ends every rank with
/// the same dist::DistributedJobError. Returns, in the order of `split`, each source's ranges
/// and passes (the same on every rank).
std::vector<SplitSourceRanges> run_split_photon_steps(dist::Communicator& comm, const std::vector<Step>& steps,
                            const std::vector<std::size_t>& split,
                            const std::function<void(std::size_t step, const std::vector<std::string>& artefacts)>&
                                deliver,
                            std::uint64_t min_range_attempts);

/// The run log's line about a batch's split sources (`split` as run_split_photon_steps returned
/// it): e.g. "photons: 1 source split into attempt ranges over 3 ranks: source photons 0
/// (7 ranges in 3 passes, 39984 attempts)"; at most 8 sources are named.
std::string split_sources_line(const std::vector<Step>& steps, const std::vector<SplitSourceRanges>& split, int ranks);

}  // namespace dayphoton::study
