// The distributed step executor: see distributed_executor.h.
#include "dayphoton/study/distributed_executor.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "dayphoton/dist/distribute_jobs.h"
#include "dayphoton/study/case_units.h"
#include "dayphoton/study/plan_policy.h"
#include "dayphoton/study/split_photon_steps.h"
#include "distributed_blocks.h"
#include "distributed_round_work.h"
#include "string_list_wire.h"

namespace dayphoton::study {
namespace {

using dist::ByteBuffer;

class DistributedExecutor final : public StepExecutor {
 public:
  DistributedExecutor(dist::Communicator& comm, const ArtifactStore& store, bool force, std::size_t block_size)
      : StepExecutor(store, force), m_comm(comm), m_block_size(block_size) {}

  /// Rank 0 reads the cache; every rank takes the same bytes (or none).
  bool lookup(const Step& step) const override {
    std::vector<std::vector<std::string>> found = cached_on_root({step});
    return take_everywhere(step, found[0]);
  }

  std::vector<char> run_batch(const std::vector<Step>& steps, const StepDone& done) override {
    std::vector<char> computed(steps.size(), 0);
    const std::vector<std::vector<std::string>> found = cached_on_root(steps);
    std::vector<std::size_t> misses;
    for (std::size_t i = 0; i < steps.size(); ++i) {
      if (take_everywhere(steps[i], found[i])) {
        if (done) done(i, false);
      } else {
        misses.push_back(i);
      }
    }
    misses = run_collective(steps, misses, computed, done);
    if (misses.empty()) return computed;
    if (misses.size() == 1 && uses_sensor_blocks(m_comm, steps[misses[0]], m_block_size)) {
      run_in_sensor_blocks(steps[misses[0]]);
      computed[misses[0]] = 1;
      if (done) done(misses[0], true);
      return computed;
    }
    misses = run_split_sources(steps, misses, computed, done);
    if (misses.empty()) return computed;
    dist::JobSet jobs;
    jobs.count = misses.size();
    const std::vector<double> costs = estimated_costs(steps, misses);
    jobs.cost_of = [&costs](std::size_t j) { return costs[j]; };
    jobs.compute = [&](std::size_t j) {
      ByteBuffer out;
      put_strings(out, steps[misses[j]].compute());
      return out;
    };
    jobs.deliver = [&](std::size_t j, ByteBuffer bytes) {
      const Step& step = steps[misses[j]];
      std::size_t at = 0;
      const std::vector<std::string> artefacts = get_strings(bytes, at);
      if (!step.take(artefacts))
        throw std::runtime_error(std::string("distributed executor: a ") + step_kind_name(step.kind) +
                                 " step's result does not fit it");
      if (m_comm.rank() == dist::RootRank) store(step, artefacts);
      computed[misses[j]] = 1;
      if (done) done(misses[j], true);
    };
    jobs.name_of = [&](std::size_t j) {
      return std::string(step_kind_name(steps[misses[j]].kind)) + " " + std::to_string(steps[misses[j]].index);
    };
    jobs.delivery = dist::Delivery::every_rank;
    dist::distribute_jobs(m_comm, jobs);
    return computed;
  }

  std::unique_ptr<CaseUnits> case_units(std::size_t cases, const CaseCosts& case_costs) override {
    return make_case_units(m_comm, m_store, m_force, cases, case_costs);
  }

  bool shares_sensor_blocks() const override { return m_comm.size() > 1; }
  bool writes_results() const override { return m_comm.rank() == dist::RootRank; }

  std::vector<std::vector<std::string>> blocks_to_root(const SensorBlocks& blocks, const std::string& name) override {
    return compute_blocks_to_root(m_comm, blocks, name, m_block_size);
  }

  RoundWork& round_work() override { return *m_round_work; }

 private:
  /// The collective steps among `misses` (Step::collective), computed by every rank alike
  /// (each talks to the others through round_work()); rank 0 stores them. Returns the others.
  std::vector<std::size_t> run_collective(const std::vector<Step>& steps, const std::vector<std::size_t>& misses,
                                          std::vector<char>& computed, const StepDone& done) {
    std::vector<std::size_t> rest;
    for (std::size_t i : misses) {
      if (!steps[i].collective) {
        rest.push_back(i);
        continue;
      }
      const std::vector<std::string> artefacts = steps[i].compute();
      if (m_comm.rank() == dist::RootRank) store(steps[i], artefacts);
      computed[i] = 1;
      if (done) done(i, true);
    }
    return rest;
  }

  /// The big photon sources among `misses`, traced in attempt ranges over the ranks
  /// (split_photon_steps.h), each taken by every rank and stored by rank 0. Returns the
  /// misses left to compute whole.
  std::vector<std::size_t> run_split_sources(const std::vector<Step>& steps, const std::vector<std::size_t>& misses,
                                             std::vector<char>& computed, const StepDone& done) {
    const std::vector<std::size_t> split = photon_steps_to_split(steps, misses, m_comm.size());
    if (split.empty()) return misses;
    auto deliver = [&](std::size_t k, const std::vector<std::string>& artefacts) {
      if (!steps[k].take(artefacts))
        throw std::runtime_error(std::string("distributed executor: a ") + step_kind_name(steps[k].kind) +
                                 " step's result does not fit it");
      if (m_comm.rank() == dist::RootRank) store(steps[k], artefacts);
      computed[k] = 1;
      if (done) done(k, true);
    };
    note(split_sources_line(steps, run_split_photon_steps(m_comm, steps, split, deliver, MinSplitRangeAttempts),
                            m_comm.size()));
    std::vector<std::size_t> rest;
    std::set_difference(misses.begin(), misses.end(), split.begin(), split.end(), std::back_inserter(rest));
    return rest;
  }

  /// Rank 0: the misses' costs for the assignment (the other ranks: ones, unused). Equal
  /// costs unless every miss has a Step::cost estimate; the estimates (a pilot pass for a
  /// sky source) are themselves shared out over the ranks with equal costs and reach rank 0
  /// in step order. An estimate that fails counts 0: the step's own compute then reports the
  /// error. Costs decide where a step runs, never its result.
  std::vector<double> estimated_costs(const std::vector<Step>& steps, const std::vector<std::size_t>& misses) {
    std::vector<double> costs(misses.size(), 1.0);
    if (m_comm.size() == 1 || misses.size() < 2) return costs;
    for (std::size_t i : misses)
      if (!steps[i].cost) return costs;
    dist::JobSet estimates;
    estimates.count = misses.size();
    estimates.cost_of = [](std::size_t) { return 1.0; };
    estimates.compute = [&](std::size_t j) {
      double cost = 0.0;
      try {
        cost = steps[misses[j]].cost();
      } catch (const std::exception&) {
        cost = 0.0;
      }
      if (!(cost >= 0.0 && cost <= 1e300)) cost = 0.0;  // NaN or infinite: no estimate
      ByteBuffer out(sizeof cost);
      std::memcpy(out.data(), &cost, sizeof cost);
      return out;
    };
    estimates.deliver = [&](std::size_t j, ByteBuffer bytes) {
      if (bytes.size() != sizeof(double)) throw std::runtime_error("distributed executor: malformed cost estimate");
      std::memcpy(&costs[j], bytes.data(), sizeof(double));
    };
    estimates.name_of = [&](std::size_t j) {
      return std::string("cost of ") + step_kind_name(steps[misses[j]].kind) + " " +
             std::to_string(steps[misses[j]].index);
    };
    estimates.delivery = dist::Delivery::root_only;
    dist::distribute_jobs(m_comm, estimates);
    return costs;
  }

  /// A grid step by sensor blocks over the ranks (distributed_blocks.h); every rank takes the
  /// joined artefacts, rank 0 stores them.
  void run_in_sensor_blocks(const Step& step) {
    const std::vector<std::string> artefacts = compute_sensor_blocks(m_comm, step, m_block_size);
    if (!step.take(artefacts))
      throw std::runtime_error(std::string("distributed executor: the joined sensor blocks of a ") +
                               step_kind_name(step.kind) + " step do not fit it");
    if (m_comm.rank() == dist::RootRank) store(step, artefacts);
  }

  /// Rank 0: each step's cached artefacts (all of them, or none), broadcast to every rank.
  std::vector<std::vector<std::string>> cached_on_root(const std::vector<Step>& steps) const {
    ByteBuffer message;
    if (m_comm.rank() == dist::RootRank) {
      for (const Step& step : steps) {
        std::vector<std::string> bytes;
        if (!m_force)
          for (const ArtifactId& a : step.outputs) {
            auto b = m_store.read(a.kind, a.key);
            if (!b) {
              bytes.clear();
              break;
            }
            bytes.push_back(std::move(*b));
          }
        put_strings(message, bytes);
      }
    }
    m_comm.broadcast_from_root(message);
    std::vector<std::vector<std::string>> found(steps.size());
    std::size_t at = 0;
    for (std::vector<std::string>& f : found) f = get_strings(message, at);
    return found;
  }

  /// Every rank takes the same bytes: the same verdict everywhere (a step that refuses them,
  /// or a decoder that throws, is computed again, as in the local executor).
  static bool take_everywhere(const Step& step, const std::vector<std::string>& bytes) {
    if (bytes.empty() || bytes.size() != step.outputs.size()) return false;
    try {
      return step.take(bytes);
    } catch (const std::exception&) {
      return false;
    }
  }

  dist::Communicator& m_comm;
  const std::size_t m_block_size;
  const std::unique_ptr<RoundWork> m_round_work = make_distributed_round_work(m_comm, m_block_size);
};

}  // namespace

std::unique_ptr<StepExecutor> make_distributed_executor(dist::Communicator& comm, const ArtifactStore& store,
                                                        bool force, std::size_t block_size) {
  return std::make_unique<DistributedExecutor>(comm, store, force, block_size);
}

}  // namespace dayphoton::study
