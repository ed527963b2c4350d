// Test support for the uncertainty honesty tests: the observed spread of a value over runs
// with other seeds against the standard error the runs report beside it.
//
// Per sensor s: S_s, the sample standard deviation of the value over the n runs, against
// sigma_s, the mean reported standard error. For normal errors (n - 1) S^2 / sigma^2 ~
// chi^2(n - 1), so E[S] = c4(n) sigma (c4 = sqrt(2 / (n - 1)) Gamma(n / 2) / Gamma((n - 1) / 2),
// 0.987 at n = 20) and the ratio R_s = S_s / (c4 sigma_s) has mean 1. The statistic is the
// mean of R_s over the sensors. The sensors are NOT independent (neighbouring sensors share
// photons, and every sensor shares the direct component's sources), so its standard deviation
// is not sd(R) / sqrt(sensors): by the delta method, Cov(S_s / sigma_s, S_t / sigma_t) =
// rho_st^2 / (2 (n - 1)) for normal errors of correlation rho_st, so
//
//   sd(mean R) = sqrt(mean over s, t of rho_st^2 / (2 (n - 1))),
//
// with rho_st^2 estimated by the runs' own sample correlations (biased upward by about
// 1 / (n - 1) for uncorrelated pairs, so the bound is conservative).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace dayphoton::test {

inline double c4(int n) {
  return std::sqrt(2.0 / (n - 1)) * std::exp(std::lgamma(n / 2.0) - std::lgamma((n - 1) / 2.0));
}

struct SeedSpread {
  double mean_ratio = 0, sd_of_mean = 0;
  double max_ratio = 0;  ///< the largest sensor's ratio
  std::size_t sensors = 0;
};

/// `value[r][s]`, `stderr_value[r][s]`: run r's value and reported standard error at sensor s;
/// `keep(s)`: whether sensor s counts. Sensors without light or without a reported error (a
/// sensor in the dark has neither spread nor error) are left out. Prints the result as `name`.
template <class Keep>
SeedSpread seed_spread(const std::vector<std::vector<double>>& value,
                       const std::vector<std::vector<double>>& stderr_value, const std::string& name, Keep keep) {
  SeedSpread h;
  const int n = static_cast<int>(value.size());
  if (n < 2) return h;
  const std::size_t m_all = value[0].size();
  std::vector<std::size_t> used;
  std::vector<double> mean(m_all, 0.0), sd(m_all, 0.0), sigma(m_all, 0.0);
  for (std::size_t s = 0; s < m_all; ++s) {
    for (int r = 0; r < n; ++r) {
      mean[s] += value[r][s] / n;
      sigma[s] += stderr_value[r][s] / n;
    }
    for (int r = 0; r < n; ++r) sd[s] += (value[r][s] - mean[s]) * (value[r][s] - mean[s]);
    sd[s] = std::sqrt(sd[s] / (n - 1));
    if (mean[s] > 0 && sigma[s] > 0 && sd[s] > 0 && keep(s)) used.push_back(s);
  }
  h.sensors = used.size();
  if (used.empty()) return h;
  double worst_low = 1e30, worst_high = 0;
  for (const std::size_t s : used) {
    const double r = sd[s] / (c4(n) * sigma[s]);
    h.mean_ratio += r / double(used.size());
    worst_low = std::min(worst_low, r);
    worst_high = std::max(worst_high, r);
  }
  double rho2 = 0;
  for (const std::size_t s : used)
    for (const std::size_t t : used) {
      double cov = 0;
      for (int r = 0; r < n; ++r) cov += (value[r][s] - mean[s]) * (value[r][t] - mean[t]);
      const double rho = cov / ((n - 1) * sd[s] * sd[t]);
      rho2 += rho * rho;
    }
  rho2 /= double(used.size()) * double(used.size());
  h.sd_of_mean = std::sqrt(rho2 / (2.0 * (n - 1)));
  h.max_ratio = worst_high;
  std::printf("%s: %zu sensors, mean observed / reported standard error %.4f (sd of the mean %.4f, "
              "mean rho^2 %.3f; per sensor %.3f .. %.3f)\n",
              name.c_str(), h.sensors, h.mean_ratio, h.sd_of_mean, rho2, worst_low, worst_high);
  return h;
}

}  // namespace dayphoton::test
