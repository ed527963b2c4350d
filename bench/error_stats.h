// Running mean, root mean square and worst value of a bench's errors (in whatever unit the
// bench adds them: % of a case's total for the photon-part benches).
#pragma once

#include <cmath>
#include <cstddef>

namespace dayphoton::bench {

struct ErrorStats {
  double sum = 0, sum2 = 0, worst = 0;
  std::size_t n = 0;
  void add(double e) {
    sum += e;
    sum2 += e * e;
    if (std::fabs(e) > std::fabs(worst)) worst = e;
    ++n;
  }
  double mean() const { return n ? sum / double(n) : 0.0; }
  double rms() const { return n ? std::sqrt(sum2 / double(n)) : 0.0; }
};

}  // namespace dayphoton::bench
