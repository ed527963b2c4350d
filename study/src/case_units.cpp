// Whole cases as units over the ranks: see case_units.h.
#include "dayphoton/study/case_units.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <vector>

#include <tbb/parallel_for.h>

#include "dayphoton/dist/job_assignment.h"

#include "string_list_wire.h"

namespace dayphoton::study {
namespace {

/// Tag of the messages that bring a rank's artefacts to rank 0 (a caller's tag, communicator.h).
constexpr int UnitArtefactsTag = 7;

/// One process's executor for its own cases: the local executor's pattern (lookup, else
/// compute), TBB over a batch; rank 0 stores what it computes, the others keep it.
class UnitExecutor final : public StepExecutor {
 public:
  UnitExecutor(const ArtifactStore& store, bool force, bool stores)
      : StepExecutor(store, force), m_stores(stores) {}

  std::vector<char> run_batch(const std::vector<Step>& steps, const StepDone& done) override {
    std::vector<char> computed(steps.size(), 0);
    auto run_one = [&](std::size_t i) {
      computed[i] = run_unit(steps[i]) ? 1 : 0;
      if (done) done(i, computed[i] != 0);
    };
    if (steps.size() == 1) {
      run_one(0);  // in the caller, so the step's own parallel loops stay at top level
    } else {
      tbb::parallel_for(std::size_t(0), steps.size(), run_one);
    }
    return computed;
  }

  /// Its results are rank 0's to write, later, from the cache; and it makes no annual
  /// multiply (not cached: rank 0's run makes it).
  bool writes_results() const override { return false; }

  /// The artefacts kept (kind, key, bytes, in the order computed).
  std::vector<std::string> take_kept() {
    std::lock_guard<std::mutex> lock(m_mutex);
    return std::move(m_kept);
  }

 private:
  bool run_unit(const Step& step) {
    if (lookup(step)) return false;
    std::vector<std::string> bytes = step.compute();
    if (m_stores) {
      store(step, bytes);
      return true;
    }
    if (bytes.size() != step.outputs.size())
      throw std::logic_error(std::string(step_kind_name(step.kind)) + " step returned " +
                             std::to_string(bytes.size()) + " artefacts for " + std::to_string(step.outputs.size()) +
                             " outputs");
    std::lock_guard<std::mutex> lock(m_mutex);
    for (std::size_t i = 0; i < bytes.size(); ++i) {
      m_kept.push_back(step.outputs[i].kind);
      m_kept.push_back(step.outputs[i].key);
      m_kept.push_back(std::move(bytes[i]));
    }
    return true;
  }

  const bool m_stores;
  std::mutex m_mutex;
  std::vector<std::string> m_kept;
};

class RankCaseUnits final : public CaseUnits {
 public:
  RankCaseUnits(dist::Communicator& comm, const std::vector<const ArtifactStore*>& stores, bool force,
                std::vector<CaseUnit> units, bool several_projects)
      : m_comm(comm), m_stores(stores), m_units(std::move(units)), m_several_projects(several_projects) {
    deal_out_on_root();
    for (const ArtifactStore* store : m_stores)
      m_executors.push_back(std::make_unique<UnitExecutor>(*store, force, comm.rank() == dist::RootRank));
  }

  bool mine(std::size_t unit) const override { return m_owner.at(unit) == m_comm.rank(); }
  StepExecutor& executor(std::size_t project) override { return *m_executors.at(project); }

  std::string join() override {
    // Each rank other than 0 sends its artefacts (project, kind, key, bytes) as messages of at
    // most about 64 MiB of artefacts each (an artefact alone may be larger; send() cuts it),
    // then one of none.
    constexpr std::size_t MessageBytes = std::size_t{64} << 20;
    if (m_comm.rank() != dist::RootRank) {
      std::vector<std::string> kept;
      for (std::size_t p = 0; p < m_executors.size(); ++p) {
        std::vector<std::string> triples = m_executors[p]->take_kept();  // kind, key, bytes
        for (std::size_t i = 0; i + 2 < triples.size(); i += 3) {
          kept.push_back(std::to_string(p));
          for (std::size_t k = i; k < i + 3; ++k) kept.push_back(std::move(triples[k]));
        }
      }
      std::size_t i = 0;
      while (i < kept.size()) {
        dist::ByteBuffer message;
        std::size_t bytes = 0;
        std::vector<std::string> part;
        for (; i < kept.size() && (part.empty() || bytes + kept[i + 3].size() <= MessageBytes); i += 4) {
          part.insert(part.end(), {kept[i], kept[i + 1], kept[i + 2], kept[i + 3]});
          bytes += kept[i + 3].size();
        }
        put_strings(message, part);
        m_comm.send(dist::RootRank, UnitArtefactsTag, message);
      }
      dist::ByteBuffer none;
      put_strings(none, {});
      m_comm.send(dist::RootRank, UnitArtefactsTag, none);
    } else {
      for (int r = 1; r < m_comm.size(); ++r)
        for (;;) {
          const dist::ByteBuffer message = m_comm.receive(r, UnitArtefactsTag);
          std::size_t at = 0;
          const std::vector<std::string> part = get_strings(message, at);
          if (part.empty()) break;
          if (part.size() % 4 != 0) throw std::runtime_error("case units: a malformed message from rank " + std::to_string(r));
          for (std::size_t i = 0; i < part.size(); i += 4) {
            const std::size_t p = std::stoul(part[i]);
            if (p >= m_stores.size() || part[i] != std::to_string(p))
              throw std::runtime_error("case units: rank " + std::to_string(r) + " sent an artefact of project '" +
                                       part[i] + "'");
            m_stores[p]->write(part[i + 1], part[i + 2], part[i + 3]);
          }
        }
    }
    return line();
  }

 private:
  /// Collective: rank 0 deals the units out by its own cost estimates (assign_case_units) and
  /// sends every rank the owners and those estimates, which replace the rank's own. Each rank
  /// computes the estimates itself, in floating point: on another node (another processor,
  /// library or build) one could round differently, and ranks dealing out by their own could
  /// disagree on who computes a case (a case computed twice, or by none).
  void deal_out_on_root() {
    dist::ByteBuffer message;
    if (m_comm.rank() == dist::RootRank) {
      std::vector<double> costs;
      for (const CaseUnit& u : m_units) costs.push_back(u.cost_seconds);
      const std::vector<int> owner = assign_case_units(costs, m_comm.size());
      for (std::size_t u = 0; u < m_units.size(); ++u) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &costs[u], sizeof bits);
        put_u64(message, static_cast<std::uint64_t>(owner[u]));
        put_u64(message, bits);
      }
    }
    m_comm.broadcast_from_root(message);
    constexpr std::size_t UnitBytes = 2 * sizeof(std::uint64_t);  // owner, cost's bits
    if (message.size() != m_units.size() * UnitBytes)
      throw std::runtime_error("case units: rank 0 dealt out " + std::to_string(message.size() / UnitBytes) +
                               " units, not " + std::to_string(m_units.size()));
    std::size_t at = 0;
    m_owner.assign(m_units.size(), 0);
    for (std::size_t u = 0; u < m_units.size(); ++u) {
      const std::uint64_t owner = get_u64(message, at);
      const std::uint64_t bits = get_u64(message, at);
      if (owner >= static_cast<std::uint64_t>(m_comm.size()))
        throw std::runtime_error("case units: rank 0 gave unit " + std::to_string(u) + " to rank " +
                                 std::to_string(owner));
      m_owner[u] = static_cast<int>(owner);
      std::memcpy(&m_units[u].cost_seconds, &bits, sizeof bits);
    }
  }

  /// The line for the run log, the same on every rank: which rank computed which case, and
  /// each rank's estimated cost.
  std::string line() const {
    std::string text = std::string(m_several_projects ? "cases of " + std::to_string(m_stores.size()) + " projects"
                                                      : "cases") +
                       " as units over " + std::to_string(m_comm.size()) + " ranks:";
    std::vector<double> load(static_cast<std::size_t>(m_comm.size()), 0.0);
    for (int r = 0; r < m_comm.size(); ++r) {
      text += (r == 0 ? " rank " : "; rank ") + std::to_string(r);
      std::string owned;
      for (std::size_t u = 0; u < m_units.size(); ++u)
        if (m_owner[u] == r) {
          owned += (owned.empty() ? " " : ", ") +
                   (m_several_projects ? "project " + std::to_string(m_units[u].project) + " " : std::string()) +
                   (owned.empty() || m_several_projects ? "case " : "") + std::to_string(m_units[u].case_index);
          load[static_cast<std::size_t>(r)] += m_units[u].cost_seconds;
        }
      text += owned;
    }
    text += m_several_projects ? " (project 0: the first project given; case 0: a project's base, then its variants in order)"
                               : " (case 0: the base project, then the variants in order)";
    text += "; estimated CPU s by rank:";
    for (std::size_t r = 0; r < load.size(); ++r) {
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%s %.2f", r == 0 ? "" : ",", load[r]);
      text += seconds;
    }
    return text;
  }

  dist::Communicator& m_comm;
  const std::vector<const ArtifactStore*> m_stores;
  std::vector<CaseUnit> m_units;  ///< the costs rank 0's (deal_out_on_root)
  const bool m_several_projects;
  std::vector<int> m_owner;
  std::vector<std::unique_ptr<UnitExecutor>> m_executors;
};

}  // namespace

std::vector<int> assign_case_units(const std::vector<double>& costs, int ranks) {
  std::vector<int> owner = dist::assign_jobs(costs, ranks).owner_of_job;
  for (int& r : owner) r = ranks - 1 - r;
  return owner;
}

std::unique_ptr<CaseUnits> make_case_units(dist::Communicator& comm, const std::vector<const ArtifactStore*>& stores,
                                           bool force, const std::vector<CaseUnit>& units) {
  // With --force every step is computed again, so the case runs after the units would not
  // take the units' artefacts from the cache: every step is shared out as without units.
  if (force || comm.size() < 2 || units.size() < static_cast<std::size_t>(comm.size())) return nullptr;
  for (const CaseUnit& u : units)
    if (u.project >= stores.size()) throw std::logic_error("case units: a unit of project " + std::to_string(u.project));
  return std::make_unique<RankCaseUnits>(comm, stores, force, units, stores.size() > 1);
}

std::unique_ptr<CaseUnits> make_case_units(dist::Communicator& comm, const ArtifactStore& store, bool force,
                                           std::size_t cases, const std::function<std::vector<double>()>& costs_of) {
  if (force || comm.size() < 2 || cases < static_cast<std::size_t>(comm.size())) return nullptr;
  const std::vector<double> case_costs = costs_of();
  if (case_costs.size() != cases)
    throw std::logic_error("case units: " + std::to_string(case_costs.size()) + " costs for " + std::to_string(cases) +
                           " cases");
  std::vector<CaseUnit> units;
  for (std::size_t c = 0; c < case_costs.size(); ++c) units.push_back({0, c, case_costs[c]});
  return make_case_units(comm, {&store}, force, units);
}

}  // namespace dayphoton::study
