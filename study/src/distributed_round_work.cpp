// The accuracy rounds' work over the ranks of an MPI run: see distributed_round_work.h.
#include "distributed_round_work.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "dayphoton/dist/distribute_jobs.h"
#include "dayphoton/study/plan_policy.h"
#include "dayphoton/study/sensor_blocks.h"
#include "attempt_range_wire.h"
#include "string_list_wire.h"

namespace dayphoton::study {
namespace {

/// One job: attempts [first, last) of request `request`.
struct RangeJob {
  std::size_t request = 0;
  std::uint64_t first = 0, last = 0;
};

class DistributedRoundWork final : public RoundWork {
 public:
  DistributedRoundWork(dist::Communicator& comm, std::size_t block_size) : m_comm(comm), m_block_size(block_size) {}

  std::vector<engine::AttemptRange> trace(const std::vector<AttemptRequest>& requests,
                                          const RangeTracer& trace) override {
    const auto ranks = static_cast<std::uint64_t>(std::max(1, m_comm.size()));
    auto cost = [&](const AttemptRequest& r) { return double(r.last - r.first) * r.cost_per_attempt; };
    double total = 0;
    for (const AttemptRequest& r : requests) total += cost(r);
    std::vector<RangeJob> jobs;
    for (std::size_t i = 0; i < requests.size(); ++i) {
      const AttemptRequest& r = requests[i];
      const std::uint64_t length = r.last > r.first ? r.last - r.first : 0;
      std::uint64_t pieces = 1;
      if (ranks > 1 && cost(r) * double(ranks) * SplitSourceFactor > total)
        pieces = std::clamp<std::uint64_t>(length / MinSplitRangeAttempts, 1, ranks);
      for (std::uint64_t k = 0; k < pieces; ++k)
        jobs.push_back({i, r.first + length * k / pieces, r.first + length * (k + 1) / pieces});
    }
    std::vector<engine::AttemptRange> out(requests.size());
    dist::JobSet set;
    set.count = jobs.size();
    set.cost_of = [&](std::size_t j) {
      return double(jobs[j].last - jobs[j].first) * requests[jobs[j].request].cost_per_attempt;
    };
    set.compute = [&](std::size_t j) {
      return encode_attempt_range(trace(requests[jobs[j].request].source, jobs[j].first, jobs[j].last));
    };
    set.deliver = [&](std::size_t j, dist::ByteBuffer bytes) {
      engine::append_attempt_range(out[jobs[j].request], decode_attempt_range(bytes));
    };
    set.name_of = [&](std::size_t j) {
      return "accuracy rounds: source " + std::to_string(requests[jobs[j].request].source) + ", attempts " +
             std::to_string(jobs[j].first) + " to " + std::to_string(jobs[j].last);
    };
    set.delivery = dist::Delivery::every_rank;
    if (!jobs.empty()) dist::distribute_jobs(m_comm, set);
    return out;
  }

  std::vector<std::string> estimate(std::size_t sensors, const RowEstimator& rows, const std::string& name) override {
    const std::vector<engine::SensorRange> blocks = sensor_blocks(sensors, m_block_size);
    if (m_comm.size() == 1 || blocks.empty()) return {rows(0, sensors)};
    std::vector<std::string> out(blocks.size());
    dist::JobSet set;
    set.count = blocks.size();
    set.cost_of = [&](std::size_t b) { return double(blocks[b].size()); };
    set.compute = [&](std::size_t b) {
      dist::ByteBuffer bytes;
      put_strings(bytes, {rows(blocks[b].begin, blocks[b].end)});
      return bytes;
    };
    set.deliver = [&](std::size_t b, dist::ByteBuffer bytes) {
      std::size_t at = 0;
      std::vector<std::string> strings = get_strings(bytes, at);
      if (strings.size() != 1 || at != bytes.size()) throw std::runtime_error("accuracy rounds: malformed block message");
      out[b] = std::move(strings[0]);
    };
    set.name_of = [&](std::size_t b) {
      return name + ", sensors " + std::to_string(blocks[b].begin) + " to " + std::to_string(blocks[b].end - 1);
    };
    set.delivery = dist::Delivery::every_rank;
    dist::distribute_jobs(m_comm, set);
    return out;
  }

  double agreed(double value) override {
    dist::ByteBuffer bytes(sizeof value);
    std::memcpy(bytes.data(), &value, sizeof value);
    m_comm.broadcast_from_root(bytes);
    if (bytes.size() != sizeof value) throw std::runtime_error("accuracy rounds: malformed clock message");
    std::memcpy(&value, bytes.data(), sizeof value);
    return value;
  }

 private:
  dist::Communicator& m_comm;
  const std::size_t m_block_size;
};

}  // namespace

std::unique_ptr<RoundWork> make_distributed_round_work(dist::Communicator& comm, std::size_t block_size) {
  return std::make_unique<DistributedRoundWork>(comm, block_size);
}

}  // namespace dayphoton::study
