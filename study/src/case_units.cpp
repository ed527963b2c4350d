// Whole cases as units over the ranks: see case_units.h.
#include "dayphoton/study/case_units.h"

#include <cstdint>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <vector>

#include <tbb/parallel_for.h>

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
  RankCaseUnits(dist::Communicator& comm, const ArtifactStore& store, bool force, std::size_t cases)
      : m_comm(comm), m_store(store), m_cases(cases),
        m_executor(store, force, comm.rank() == dist::RootRank) {}

  bool mine(std::size_t c) const override { return owner(c) == m_comm.rank(); }
  StepExecutor& executor() override { return m_executor; }

  std::string join() override {
    // Each rank other than 0 sends its artefacts as messages of at most about 64 MiB of
    // artefacts each (an artefact alone may be larger; send() cuts it), then one of none.
    constexpr std::size_t MessageBytes = std::size_t{64} << 20;
    if (m_comm.rank() != dist::RootRank) {
      const std::vector<std::string> kept = m_executor.take_kept();
      std::size_t i = 0;
      while (i < kept.size()) {
        dist::ByteBuffer message;
        std::size_t bytes = 0;
        std::vector<std::string> part;
        for (; i < kept.size() && (part.empty() || bytes + kept[i + 2].size() <= MessageBytes); i += 3) {
          part.insert(part.end(), {kept[i], kept[i + 1], kept[i + 2]});
          bytes += kept[i + 2].size();
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
          if (part.size() % 3 != 0) throw std::runtime_error("case units: a malformed message from rank " + std::to_string(r));
          for (std::size_t i = 0; i < part.size(); i += 3) m_store.write(part[i], part[i + 1], part[i + 2]);
        }
    }
    // The line for the run log, the same on every rank.
    std::string line = "cases as units over " + std::to_string(m_comm.size()) + " ranks:";
    for (int r = 0; r < m_comm.size(); ++r) {
      line += (r == 0 ? " rank " : "; rank ") + std::to_string(r);
      std::string owned;
      for (std::size_t c = 0; c < m_cases; ++c)
        if (owner(c) == r) owned += (owned.empty() ? " case " : ", ") + std::to_string(c);
      line += owned;
    }
    return line + " (case 0: the base project, then the variants in order)";
  }

 private:
  int owner(std::size_t c) const {
    const auto ranks = static_cast<std::size_t>(m_comm.size());
    return static_cast<int>(ranks - 1 - c % ranks);
  }

  dist::Communicator& m_comm;
  const ArtifactStore& m_store;
  const std::size_t m_cases;
  UnitExecutor m_executor;
};

}  // namespace

std::unique_ptr<CaseUnits> make_case_units(dist::Communicator& comm, const ArtifactStore& store, bool force,
                                           std::size_t cases) {
  // With --force every step is computed again, so the case runs after the units would not
  // take the units' artefacts from the cache: every step is shared out as without units.
  if (force || comm.size() < 2 || cases < static_cast<std::size_t>(comm.size())) return nullptr;
  return std::make_unique<RankCaseUnits>(comm, store, force, cases);
}

}  // namespace dayphoton::study
