// StepExecutor and the local executor (TBB): see step_executor.h.
#include "dayphoton/study/step_executor.h"

#include "dayphoton/study/case_units.h"

#include <stdexcept>

#include <tbb/parallel_for.h>

namespace dayphoton::study {

const char* step_kind_name(StepKind kind) {
  switch (kind) {
    case StepKind::SkyMatrix: return "sky matrix";
    case StepKind::SourcePhotons: return "source photons";
    case StepKind::SunBinPhotons: return "sun-bin photons";
    case StepKind::SkyCoefficients: return "sky coefficients";
    case StepKind::SunCoefficients: return "sun coefficients";
    case StepKind::DirectSun: return "direct sun";
  }
  return "step";
}

bool StepExecutor::run(const Step& step) { return run_batch({step})[0] != 0; }

std::unique_ptr<CaseUnits> StepExecutor::case_units(std::size_t, const CaseCosts&) { return nullptr; }

std::vector<std::vector<std::string>> StepExecutor::blocks_to_root(const SensorBlocks&, const std::string& name) {
  throw std::logic_error("blocks_to_root (" + name + ") on an executor of one process");
}

RoundWork& StepExecutor::round_work() {
  // One process's work keeps no state, so every local executor shares one.
  static const std::unique_ptr<RoundWork> local = make_local_round_work();
  return *local;
}

bool StepExecutor::lookup(const Step& step) const {
  if (m_force) return false;
  std::vector<std::string> bytes;
  for (const ArtifactId& a : step.outputs) {
    auto b = m_store.read(a.kind, a.key);
    if (!b) return false;
    bytes.push_back(std::move(*b));
  }
  try {
    return step.take(bytes);
  } catch (const std::exception&) {
    return false;  // damaged or an older layout: computed again
  }
}

void StepExecutor::store(const Step& step, const std::vector<std::string>& bytes) const {
  if (bytes.size() != step.outputs.size())
    throw std::logic_error(std::string(step_kind_name(step.kind)) + " step returned " + std::to_string(bytes.size()) +
                           " artefacts for " + std::to_string(step.outputs.size()) + " outputs");
  for (std::size_t i = 0; i < bytes.size(); ++i) m_store.write(step.outputs[i].kind, step.outputs[i].key, bytes[i]);
}

bool StepExecutor::run_here(const Step& step) const {
  if (lookup(step)) return false;
  store(step, step.compute());
  return true;
}

namespace {

class LocalExecutor final : public StepExecutor {
 public:
  using StepExecutor::StepExecutor;

  std::vector<char> run_batch(const std::vector<Step>& steps, const StepDone& done) override {
    std::vector<char> computed(steps.size(), 0);
    if (steps.size() == 1) {
      // A step alone runs in the caller, so its own parallel loops stay at top level
      // (architecture.md, "Conventions": nested loops and exceptions).
      computed[0] = run_here(steps[0]) ? 1 : 0;
      if (done) done(0, computed[0] != 0);
      return computed;
    }
    tbb::parallel_for(std::size_t(0), steps.size(), [&](std::size_t i) {
      computed[i] = run_here(steps[i]) ? 1 : 0;
      if (done) done(i, computed[i] != 0);
    });
    return computed;
  }
};

}  // namespace

std::unique_ptr<StepExecutor> make_local_executor(const ArtifactStore& store, bool force) {
  return std::make_unique<LocalExecutor>(store, force);
}

}  // namespace dayphoton::study
