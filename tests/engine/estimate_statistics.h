// Test support for the density-estimate tests: the sample statistics of independent trials
// (mean, sigma, and the 4-sigma tolerance of the mean these tests assert with) and the
// photon filter that passes every path class.
#pragma once

#include <algorithm>
#include <cmath>

#include "dayphoton/engine/photon_map.h"

namespace dayphoton::engine::test {

/// Running sums of independent trial values.
struct Stats {
  double sum = 0, sum2 = 0;
  int n = 0;
  void add(double x) { sum += x; sum2 += x * x; ++n; }
  double mean() const { return sum / n; }
  double sigma() const { return std::sqrt(std::max(0.0, (sum2 - sum * sum / n) / (n - 1))); }
  /// 4 standard errors of the mean.
  double tolerance() const { return 4.0 * sigma() / std::sqrt(static_cast<double>(n)); }
};

inline PhotonFilter all_photons() {
  PhotonFilter f;
  f.path_classes = 0x7;
  return f;
}

}  // namespace dayphoton::engine::test
