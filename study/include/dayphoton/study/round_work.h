// RoundWork: what the accuracy rounds (accuracy_rounds.h) hand to the processes of a run, so
// that the rounds themselves (pilot, allocation, stops) stay one piece of code whether one
// process or the ranks of an MPI job run them (docs/cluster.md "Accuracy rounds").
//
// Every process runs the same rounds on the same data and calls these methods in the same
// order (they are collective); each returns the same values on every process, so every
// process takes the same decisions. Work is independent of where it runs: an attempt range is
// a pure function of (seed, source, attempts), a sensor block's rows are those of the whole
// grid (engine/sensor_range.h), so the results are byte for byte those of one process.
//
// Implemented by the local executor (one process: TBB over the requests, one block per grid)
// and by the distributed executor (distributed_round_work.h); StepExecutor::round_work gives
// the executor's. A step whose compute() calls them is marked Step::collective, so that the
// distributed executor runs it on every rank rather than on one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dayphoton/engine/photon_tracer.h"

namespace dayphoton::study {

class RoundWork {
 public:
  virtual ~RoundWork() = default;

  /// Attempts [first, last) of source `source`.
  struct AttemptRequest {
    std::size_t source = 0;
    std::uint64_t first = 0, last = 0;
    double cost_per_attempt = 1;  ///< any unit, the same for every request of a call; finite, > 0
  };
  /// Traces attempts [first, last) of a source (engine::round_attempt_range): pure, may run on
  /// several threads at once; any split of a request, appended in order, gives the request.
  using RangeTracer = std::function<engine::AttemptRange(std::size_t source, std::uint64_t first, std::uint64_t last)>;

  /// Collective: every request traced by `trace` (whole or in ranges over the processes), and
  /// each request's attempts returned on every process, in request order. A range that throws
  /// ends every process with the same error.
  virtual std::vector<engine::AttemptRange> trace(const std::vector<AttemptRequest>& requests,
                                                  const RangeTracer& trace) = 0;

  /// The bytes of sensors [begin, end) of a grid (an artefact codec's grid of those sensors).
  using RowEstimator = std::function<std::string(std::size_t begin, std::size_t end)>;

  /// Collective: the grid's `sensors` estimated by `rows` in consecutive blocks (sensor_blocks.h),
  /// each block's bytes returned on every process in sensor order (one block for the whole grid
  /// in one process). `name` names a failing block ("accuracy round 2, grid floor").
  virtual std::vector<std::string> estimate(std::size_t sensors, const RowEstimator& rows, const std::string& name) = 0;

  /// Collective: the first process's `value` on every process (the time budget's clock, the
  /// one measurement the rounds' decisions read).
  virtual double agreed(double value) = 0;
};

/// The work of one process: requests traced whole, in parallel (TBB); one block per grid.
std::unique_ptr<RoundWork> make_local_round_work();

}  // namespace dayphoton::study
