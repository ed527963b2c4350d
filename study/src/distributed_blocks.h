// A grid step's sensor blocks (plan_step.h SensorBlocks) shared out over the ranks of an MPI
// run: the distributed executor's (distributed_executor.cpp) path for one step that estimates
// a grid (docs/cluster.md "Sensor blocks").
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "dayphoton/dist/communicator.h"
#include "dayphoton/study/plan_step.h"

namespace dayphoton::study {

/// Whether `step` goes by sensor blocks over `comm`: it has blocks, there are several ranks
/// and at least two blocks of `block_size` sensors. (Otherwise one rank computes it whole.)
bool uses_sensor_blocks(const dist::Communicator& comm, const Step& step, std::size_t block_size);

/// Collective: the blocks of `blocks` (sensor_blocks.h, `block_size` sensors each) as the
/// jobs of one dist::distribute_jobs (longest first by sensor count, TBB within a rank), their
/// outputs sent to rank 0. Rank 0 returns them in sensor order, the other ranks an empty
/// vector. A block that throws fails every rank with dist::DistributedJobError naming it
/// ("`name`, sensors 16 to 31").
std::vector<std::vector<std::string>> compute_blocks_to_root(dist::Communicator& comm, const SensorBlocks& blocks,
                                                             const std::string& name, std::size_t block_size);

/// Collective: the blocks of `step` (sensor_blocks.h) as the jobs of one
/// dist::distribute_jobs (longest first by sensor count, TBB within a rank), their results
/// sent to rank 0, which joins them in sensor order (SensorBlocks::join) and broadcasts the
/// outputs' bytes: every rank returns what step.compute() would. A block that throws fails
/// every rank with dist::DistributedJobError naming the grid and its sensors.
std::vector<std::string> compute_sensor_blocks(dist::Communicator& comm, const Step& step, std::size_t block_size);

}  // namespace dayphoton::study
