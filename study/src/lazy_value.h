// LazyValue: a value built on first use, once, by the first thread that asks; the others
// wait for it. For what the sensor blocks of one grid step share on a rank (the grid's photon
// maps, plan_step.h SensorBlocks): built only on a rank that computes some block, and once
// there however many blocks it computes.
//
// The build runs isolated (tbb::this_task_arena::isolate): a thread building it runs only the
// build's own parallel tasks, never another block that would wait for the value it is
// building (the deadlock of nested parallelism inside a lock, oneTBB Developer Guide, "Work
// Isolation").
#pragma once

#include <mutex>
#include <optional>

#include <tbb/task_arena.h>

namespace dayphoton::study {

template <class T>
class LazyValue {
 public:
  /// The value, built by `build()` on the first call (a build that throws is tried again by
  /// the next call).
  template <class Build>
  const T& get(Build build) {
    std::call_once(m_once, [&] { tbb::this_task_arena::isolate([&] { m_value.emplace(build()); }); });
    return *m_value;
  }

 private:
  std::once_flag m_once;
  std::optional<T> m_value;
};

}  // namespace dayphoton::study
