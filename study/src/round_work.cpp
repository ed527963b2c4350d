// The local RoundWork (one process): see round_work.h.
#include "dayphoton/study/round_work.h"

#include <tbb/parallel_for.h>

namespace dayphoton::study {
namespace {

class LocalRoundWork final : public RoundWork {
 public:
  std::vector<engine::AttemptRange> trace(const std::vector<AttemptRequest>& requests,
                                          const RangeTracer& trace) override {
    std::vector<engine::AttemptRange> out(requests.size());
    tbb::parallel_for(std::size_t(0), requests.size(), [&](std::size_t i) {
      out[i] = trace(requests[i].source, requests[i].first, requests[i].last);
    });
    return out;
  }

  std::vector<std::string> estimate(std::size_t sensors, const RowEstimator& rows, const std::string&) override {
    return {rows(0, sensors)};
  }

  double agreed(double value) override { return value; }
};

}  // namespace

std::unique_ptr<RoundWork> make_local_round_work() { return std::make_unique<LocalRoundWork>(); }

}  // namespace dayphoton::study
