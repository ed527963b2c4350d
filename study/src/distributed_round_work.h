// The accuracy rounds' work (round_work.h) over the ranks of an MPI run: the distributed
// executor's round_work (distributed_executor.h; docs/cluster.md "Accuracy rounds").
//
// trace: the requests' attempts are the jobs of one dist::distribute_jobs, delivered to every
// rank in request and attempt order. A request is cut into ranges as a big source's pass is
// (split_photon_steps.h): when its cost (attempts x cost per attempt) exceeds 1/SplitSourceFactor
// of a rank's share of the call's total, into at most one range per rank of at least
// MinSplitRangeAttempts attempts (plan_policy.h); the others go whole.
// estimate: a grid's sensor blocks of `block_size` sensors are the jobs of one distribute_jobs,
// every block's bytes delivered to every rank in sensor order; with one rank, the whole grid
// at once (as the local work).
// agreed: rank 0's value broadcast.
// A job that throws ends every rank with the same dist::DistributedJobError; a rank that dies
// ends the MPI job (distribute_jobs.h).
#pragma once

#include <cstddef>
#include <memory>

#include "dayphoton/dist/communicator.h"
#include "dayphoton/study/round_work.h"

namespace dayphoton::study {

/// Work over `comm`'s ranks (`comm` must outlive it); `block_size` sensors per block.
std::unique_ptr<RoundWork> make_distributed_round_work(dist::Communicator& comm, std::size_t block_size);

}  // namespace dayphoton::study
