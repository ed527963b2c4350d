// Test support for the accuracy rounds' tests on in-process ranks: a RoundWork
// (study/round_work.h) that counts what passes through it and hands everything on to another
// (the executor's), so that a test can see how the rounds' work was shared out.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "dayphoton/study/round_work.h"

namespace dayphoton::test {

class CountingWork final : public study::RoundWork {
 public:
  explicit CountingWork(study::RoundWork& inner) : m_inner(inner) {}
  std::vector<engine::AttemptRange> trace(const std::vector<AttemptRequest>& requests, const RangeTracer& t) override {
    ++calls;
    requests_total += requests.size();
    return m_inner.trace(requests, [&](std::size_t p, std::uint64_t first, std::uint64_t last) {
      ++ranges;
      return t(p, first, last);
    });
  }
  std::vector<std::string> estimate(std::size_t sensors, const RowEstimator& rows, const std::string& name) override {
    std::vector<std::string> b = m_inner.estimate(sensors, rows, name);
    blocks += b.size();
    return b;
  }
  double agreed(double value) override { return m_inner.agreed(value); }

  int calls = 0;                  ///< trace calls (one a round's tracing)
  std::size_t requests_total = 0; ///< requests over all trace calls
  std::atomic<int> ranges{0};     ///< ranges this process traced
  std::size_t blocks = 0;         ///< sensor blocks over all estimate calls

 private:
  study::RoundWork& m_inner;
};

}  // namespace dayphoton::test
