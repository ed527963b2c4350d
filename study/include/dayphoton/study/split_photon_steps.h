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

/// Traces steps[k] for every k of `split` (each with ranges) over comm's ranks and calls
/// deliver(k, artefacts) on every rank as each finishes (one artefact: the photons). A pass is
/// cut into ranges of at least `min_range_attempts` (the executor: MinSplitRangeAttempts,
/// plan_policy.h), at most one per rank. Collective. A range that throws ends every rank with
/// the same dist::DistributedJobError.
void run_split_photon_steps(dist::Communicator& comm, const std::vector<Step>& steps,
                            const std::vector<std::size_t>& split,
                            const std::function<void(std::size_t step, const std::vector<std::string>& artefacts)>&
                                deliver,
                            std::uint64_t min_range_attempts);

}  // namespace dayphoton::study
