// A grid step's sensor blocks over the ranks: see distributed_blocks.h.
#include "distributed_blocks.h"

#include <stdexcept>

#include "dayphoton/dist/distribute_jobs.h"
#include "dayphoton/study/sensor_blocks.h"
#include "string_list_wire.h"

namespace dayphoton::study {

bool uses_sensor_blocks(const dist::Communicator& comm, const Step& step, std::size_t block_size) {
  return step.blocks && comm.size() > 1 && block_size > 0 && step.blocks->sensors > block_size;
}

std::vector<std::vector<std::string>> compute_blocks_to_root(dist::Communicator& comm, const SensorBlocks& sb,
                                                             const std::string& name, std::size_t block_size) {
  const std::vector<engine::SensorRange> blocks = sensor_blocks(sb.sensors, block_size);
  std::vector<std::vector<std::string>> results(blocks.size());  // rank 0's
  dist::JobSet jobs;
  jobs.count = blocks.size();
  jobs.cost_of = [&](std::size_t b) { return double(blocks[b].size()); };
  jobs.compute = [&](std::size_t b) {
    dist::ByteBuffer out;
    put_strings(out, sb.compute_rows(blocks[b].begin, blocks[b].end));
    return out;
  };
  jobs.deliver = [&](std::size_t b, dist::ByteBuffer bytes) {
    std::size_t at = 0;
    results[b] = get_strings(bytes, at);
  };
  jobs.name_of = [&](std::size_t b) {
    return name + ", sensors " + std::to_string(blocks[b].begin) + " to " + std::to_string(blocks[b].end - 1);
  };
  jobs.delivery = dist::Delivery::root_only;
  dist::distribute_jobs(comm, jobs);
  if (comm.rank() != dist::RootRank) results.clear();
  return results;
}

std::vector<std::string> compute_sensor_blocks(dist::Communicator& comm, const Step& step, std::size_t block_size) {
  if (!step.blocks) throw std::logic_error("compute_sensor_blocks: the step has no sensor blocks");
  const SensorBlocks& sb = *step.blocks;
  std::vector<std::vector<std::string>> results = compute_blocks_to_root(
      comm, sb, std::string(step_kind_name(step.kind)) + " " + std::to_string(step.index), block_size);

  // Rank 0 joins the blocks; every rank takes the joined bytes (a join that fails on rank 0
  // is broadcast as such, so every rank throws alike).
  dist::ByteBuffer message;
  if (comm.rank() == dist::RootRank) {
    std::vector<std::string> joined;
    std::string problem;
    try {
      joined = sb.join(results);
      results.clear();
    } catch (const std::exception& e) {
      problem = e.what();
    }
    put_strings(message, {problem});
    put_strings(message, joined);
  }
  comm.broadcast_from_root(message);
  std::size_t at = 0;
  const std::vector<std::string> problem = get_strings(message, at);
  if (problem.size() != 1) throw std::runtime_error("distributed executor: malformed message");
  if (!problem[0].empty())
    throw std::runtime_error(std::string("joining the sensor blocks of ") + step_kind_name(step.kind) + " " +
                             std::to_string(step.index) + ": " + problem[0]);
  return get_strings(message, at);
}

}  // namespace dayphoton::study
