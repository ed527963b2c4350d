// StepExecutor: the one seam through which a run's steps (plan_step.h) meet the cache
// (artifact_store.h): a step's artefacts are looked up, and only when one is missing,
// damaged or does not fit is the step computed and its artefacts stored. This is the only
// place of the pipeline that writes the try-load / decode / recompute / store pattern.
//
// Independent steps of a phase (the photons of a case's sources, of its sun bins) are handed
// over as one BATCH. The local executor runs a batch over its steps with TBB, as the run did
// before there was a seam; results do not depend on the thread count (each step is a pure
// function of its inputs, and results are kept per step, in step order).
//
// Where a distributed executor plugs in (docs/architecture.md, "Plan and executor"): a
// subclass overriding run_batch. Rank 0 looks every step up; the misses are shared out over
// the ranks, each rank runs compute() of its share and sends the returned bytes to rank 0,
// which take()s them in step order and stores them; the other ranks write nothing.
// lookup() and store() below are what such an executor reuses. A collective step
// (Step::collective, the accuracy rounds) is computed by every process alike, through
// round_work(); rank 0 stores it.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dayphoton/study/artifact_store.h"
#include "dayphoton/study/plan_step.h"
#include "dayphoton/study/round_work.h"

namespace dayphoton::study {

class CaseUnits;

class StepExecutor {
 public:
  /// `force`: ignore the cache (every step is computed; its artefacts are still stored).
  StepExecutor(const ArtifactStore& store, bool force) : m_store(store), m_force(force) {}
  virtual ~StepExecutor() = default;
  StepExecutor(const StepExecutor&) = delete;
  StepExecutor& operator=(const StepExecutor&) = delete;

  /// Called once per step of a batch as it finishes, from any thread: its index in the batch
  /// and whether it was computed (false: it came from the cache).
  using StepDone = std::function<void(std::size_t index, bool computed)>;

  /// Runs a batch of independent steps: each one's artefacts from the cache when every one
  /// is intact and the step takes them, else computed and stored. Returns per step whether it
  /// was computed (1) or cached (0). Throws what a step's compute throws.
  virtual std::vector<char> run_batch(const std::vector<Step>& steps, const StepDone& done = {}) = 0;

  /// One step (a batch of one); true if it was computed.
  bool run(const Step& step);

  /// The step's artefacts from the cache, taken by the step: true if every one was intact
  /// and the step took them. Never computes; always false with `force`.
  virtual bool lookup(const Step& step) const;

  /// Where the executor's own notes go, a line each (the distributed executor's: which sources
  /// it split into attempt ranges); run_study sends them to the run log. Empty: dropped.
  using NoteSink = std::function<void(const std::string& line)>;
  void set_note_sink(NoteSink sink) { m_note = std::move(sink); }

  /// Whole cases (the base project and each variant) as units over the processes, when this
  /// executor assigns them (the distributed executor with at least as many cases as ranks,
  /// case_units.h), dealt out by `case_costs` (each case's estimate, case_cost.h; called
  /// only when there are units); null: every case's steps go through this executor.
  /// Collective.
  using CaseCosts = std::function<std::vector<double>()>;
  virtual std::unique_ptr<CaseUnits> case_units(std::size_t cases, const CaseCosts& case_costs);

  /// Whether this executor shares sensor blocks out over several processes (the distributed
  /// executor with more than one rank): what is computed per grid but not cached (the annual
  /// multiply, annual_blocks.h) then goes by blocks too, through blocks_to_root.
  virtual bool shares_sensor_blocks() const { return false; }
  /// Whether this process writes the run's results: false on the ranks other than 0. It is
  /// run_study's writer flag (study_runner.h): a process that does not write takes no output
  /// lock, keeps no manifest or run.log and writes no file, and still runs every step.
  virtual bool writes_results() const { return true; }
  /// Only where shares_sensor_blocks(); collective: the blocks of `blocks` (sensor_blocks.h)
  /// computed over the processes, nothing cached. Rank 0 returns every block's outputs in
  /// sensor order, the other ranks an empty vector (`name` names a failing block). Throws
  /// std::logic_error on an executor of one process.
  virtual std::vector<std::vector<std::string>> blocks_to_root(const SensorBlocks& blocks, const std::string& name);
  /// The work of a collective step (Step::collective), e.g. the accuracy rounds' tracing and
  /// estimates (round_work.h): this process's alone here, the ranks' in the distributed executor.
  virtual RoundWork& round_work();

 protected:
  /// Stores the bytes of a step's outputs (one per output, in order).
  void store(const Step& step, const std::vector<std::string>& bytes) const;
  /// lookup, else compute and store: the whole pattern for a step run in this process.
  bool run_here(const Step& step) const;

  /// A note for the run log (set_note_sink).
  void note(const std::string& line) const {
    if (m_note) m_note(line);
  }

  const ArtifactStore& m_store;
  const bool m_force;
  NoteSink m_note;
};

/// The executor of one process: a batch's steps in parallel over this machine's cores (TBB).
std::unique_ptr<StepExecutor> make_local_executor(const ArtifactStore& store, bool force);

}  // namespace dayphoton::study
