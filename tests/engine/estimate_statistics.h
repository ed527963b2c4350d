// Test support for the density-estimate tests: the sample statistics of independent trials
// (mean, sigma, and the 4-sigma tolerance of the mean these tests assert with) and the
// photon filter that passes every path class.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

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

/// An estimator's values over independent trials against the variance it reported in each:
/// the mean and its standard error, the observed variance, the mean reported one, and the
/// standard error of their difference (the sample variance's, from the fourth central
/// moment, and the reported mean's).
struct ReportedVariance {
  double mean = 0, mean_se = 0, observed = 0, reported = 0, difference_se = 0;
};

inline ReportedVariance reported_variance(const std::vector<double>& estimates, const std::vector<double>& reported) {
  const double n = static_cast<double>(estimates.size());
  ReportedVariance r;
  double fourth = 0, rvar = 0;
  for (double e : estimates) r.mean += e / n;
  for (double e : estimates) {
    r.observed += (e - r.mean) * (e - r.mean) / (n - 1);
    fourth += std::pow(e - r.mean, 4) / n;
  }
  for (double v : reported) r.reported += v / n;
  for (double v : reported) rvar += (v - r.reported) * (v - r.reported) / (n - 1);
  r.mean_se = std::sqrt(r.observed / n);
  r.difference_se = std::sqrt((fourth - r.observed * r.observed) / n + rvar / n);
  return r;
}

inline PhotonFilter all_photons() {
  PhotonFilter f;
  f.path_classes = 0x7;
  return f;
}

}  // namespace dayphoton::engine::test
