// A point-in-time case against the accuracy target: see point_in_time_accuracy.h.
#include "dayphoton/study/point_in_time_accuracy.h"

#include <algorithm>
#include <cmath>

#include "dayphoton/study/accuracy_rounds.h"
#include "dayphoton/study/plan_policy.h"
#include "accuracy_round_loop.h"

namespace dayphoton::study {
PointInTimeAccuracy assess_point_in_time(const std::vector<double>& value_lux, const PointInTimeVarianceParts& parts,
                                         double target_percent) {
  PointInTimeAccuracy a;
  a.target_percent = target_percent;
  const std::vector<double> stderr_lux = parts.stderr_lux();
  a.reached_percent = percentile_relative_stderr_percent(value_lux, stderr_lux, AccuracyPercentile);
  std::vector<double> relative(value_lux.size(), 0.0);
  for (std::size_t s = 0; s < relative.size(); ++s)
    relative[s] = value_lux[s] > 0 ? 100.0 * stderr_lux[s] / value_lux[s] : 0.0;
  std::vector<std::size_t> deciding;
  if (target_percent > 0)
    for (std::size_t s : sensors_at_or_below_percentile(relative, value_lux, AccuracyPercentile))
      if (relative[s] > target_percent) deciding.push_back(s);
  if (deciding.empty())
    for (std::size_t s = 0; s < value_lux.size(); ++s)
      if (value_lux[s] > 0) deciding.push_back(s);
  double sky = 0, indirect = 0, direct = 0;
  for (std::size_t s : deciding) {
    const double v2 = value_lux[s] * value_lux[s];
    sky += parts.sky[s] / v2;
    indirect += parts.indirect_sun[s] / v2;
    direct += parts.direct_sun[s] / v2;
  }
  const double total = sky + indirect + direct;
  if (total > 0) {
    a.sky_share = sky / total;
    a.indirect_sun_share = indirect / total;
    a.direct_sun_share = direct / total;
  }
  a.limiting_part = direct > std::max(sky, indirect) ? "direct sun" : indirect > sky ? "indirect sun" : "sky";
  if (target_percent > 0) {
    a.status = a.reached_percent <= target_percent ? "met" : "above target";
    if (a.status == "met") a.stop_reason = "target met";
  }
  return a;
}

std::string point_in_time_stop_reason(const PointInTimeAccuracy& a, const std::string& sky_stop,
                                      const std::string& indirect_sun_stop, const std::string& direct_sun_stop) {
  if (a.status != "above target") return a.stop_reason;
  const std::string& stop = a.limiting_part == "sky"            ? sky_stop
                            : a.limiting_part == "indirect sun" ? indirect_sun_stop
                                                                : direct_sun_stop;
  if (stop == "target met" || stop.empty()) {
    if (a.limiting_part == "sky") return "sky part: the sky rounds met the target on each part alone";
    if (a.limiting_part == "indirect sun") return "indirect sun: the sun rounds met their own measure";
    return "direct sun: shadow rays not raised";
  }
  return stop;
}

int next_direct_sun_samples(const std::vector<double>& value_lux, const std::vector<double>& other_variance,
                            const std::vector<double>& direct_variance, int samples, double target_percent) {
  const int k = static_cast<int>(std::ceil(std::sqrt(double(std::max(samples, 1)))));
  const int k_limit = static_cast<int>(std::lround(std::sqrt(double(MaxDirectSamplesPerBin))));
  if (target_percent <= 0 || k >= k_limit) return samples;
  const double aim = AccuracyRoundAim * target_percent;
  std::vector<double> relative(value_lux.size(), 0.0);
  for (std::size_t s = 0; s < relative.size(); ++s)
    relative[s] = value_lux[s] > 0 ? 100.0 * std::sqrt(other_variance.at(s) + direct_variance.at(s)) / value_lux[s] : 0.0;
  // The largest fall of the direct variance any deciding sensor asks for: to half its budget.
  double fall = 1.0;
  for (std::size_t s : sensors_at_or_below_percentile(relative, value_lux, AccuracyPercentile)) {
    if (!(relative[s] > aim)) continue;
    const double half_budget = 0.5 * std::pow(aim / 100.0 * value_lux[s], 2);
    if (direct_variance[s] >= half_budget) fall = std::max(fall, direct_variance[s] / half_budget);
  }
  if (fall <= 1.0) return samples;
  int next = std::min(2 * k, k_limit);
  if (std::pow(double(k) / next, 2.0 * DirectVarianceExponent) * fall > 1.0) next = std::min(4 * k, k_limit);
  return next * next;
}

std::string point_in_time_accuracy_sentence(const PointInTimeAccuracy& a) {
  std::string s = "relative standard error (95th percentile) " + round_number(a.reached_percent) + " %";
  if (a.target_percent > 0)
    s += std::string(a.reached_percent <= a.target_percent ? " <= " : " > ") + "target " + round_number(a.target_percent) +
         " %: " + a.stop_reason;
  s += " (variance: sky " + round_number(100 * a.sky_share) + " %, indirect sun " + round_number(100 * a.indirect_sun_share) +
       " %, direct sun " + round_number(100 * a.direct_sun_share) + " %";
  if (a.direct_sun_samples > 0) s += "; " + std::to_string(a.direct_sun_samples) + " shadow rays over the sun's disc";
  return s + ")";
}

}  // namespace dayphoton::study
