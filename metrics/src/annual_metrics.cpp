// Annual daylight metrics. Sources: Reinhart & Walkenhorst 2001 (DA), Rogers 2006 (cDA,
// DAmax), Nabil & Mardaljevic 2005 and Mardaljevic's revision (UDI), IES LM-83-12 (sDA, ASE),
// EN 17037:2018 (daylight provision); conventions in docs/metrics.md, distilled in
// ../shared/facts/sky-and-metrics.md section 5.
#include "dayphoton/metrics/annual_metrics.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace dayphoton::metrics {

namespace {

/// Sensors per task of the per-sensor counts. Every sensor's sums run over the steps in step
/// order whatever the split, so the values do not depend on it nor on the thread count; a
/// task reads its sensors' part of each step's row, so the table is read in order.
constexpr std::size_t SensorsPerTask = 256;

/// fn(begin, end) over the sensors [0, n) in blocks of SensorsPerTask, in parallel.
template <class Fn>
void for_sensor_blocks(std::size_t n, const Fn& fn) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, SensorsPerTask),
                    [&](const tbb::blocked_range<std::size_t>& r) { fn(r.begin(), r.end()); });
}

void check_shapes(const IlluminanceTable& table, const OccupancySchedule& occupancy) {
  if (table.step_count() != occupancy.step_count())
    throw std::invalid_argument("occupancy schedule has " + std::to_string(occupancy.step_count()) +
                                " steps, the illuminance table " + std::to_string(table.step_count()));
}

double weighted_mean(const std::vector<double>& values, const std::vector<double>& weights) {
  double sum = 0, weight_sum = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    sum += w * values[i];
    weight_sum += w;
  }
  return weight_sum > 0 ? sum / weight_sum : 0;
}

/// The share (percent) of the area whose sensors pass (`passes`: 100 or 0 per sensor), each
/// sensor weighted by `weights` (equal when empty): 100 x the passing weight over the total,
/// so that every sensor passing gives exactly 100 whatever the weights (a weighted mean of
/// the 100s need not), and equal weights give 100 k / n as a count does.
double share_percent(const std::vector<double>& passes, const std::vector<double>& weights) {
  double passing = 0, total = 0;
  for (std::size_t i = 0; i < passes.size(); ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    if (passes[i] > 0) passing += w;
    total += w;
  }
  return total > 0 ? 100.0 * passing / total : 0;
}

}  // namespace

std::vector<SensorMetrics> compute_sensor_metrics(const IlluminanceTable& table,
                                                  const OccupancySchedule& occupancy,
                                                  const MetricSettings& settings) {
  check_shapes(table, occupancy);
  const std::size_t n_sensors = table.sensor_count();
  const double n_occupied = static_cast<double>(occupancy.occupied_count());
  std::vector<SensorMetrics> result(n_sensors);
  if (n_occupied == 0) return result;

  const double x = settings.da_threshold_lux;
  const double low = settings.udi_lower_lux;
  const double up1 = settings.udi_upper_original_lux;
  const double up2 = settings.udi_upper_revised_lux;
  // Each sensor's sums over the occupied steps in step order (for_sensor_blocks).
  for_sensor_blocks(n_sensors, [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = 0; t < table.step_count(); ++t) {
      if (!occupancy.occupied(t)) continue;
      for (std::size_t s = begin; s < end; ++s) {
        const double e = table.lux(t, s);
        SensorMetrics& m = result[s];
        m.da_percent += e >= x;
        m.cda_percent += std::min(1.0, e / x);
        m.da_max_percent += e > 10 * x;
        m.udi_below_percent += e < low;
        m.udi_original_percent += e >= low && e <= up1;
        m.udi_above_original_percent += e > up1;
        m.udi_supplementary_percent += e >= low && e < x;
        m.udi_autonomous_percent += e >= x && e <= up2;
        m.udi_above_revised_percent += e > up2;
        m.mean_occupied_lux += e;
      }
    }
    for (std::size_t s = begin; s < end; ++s) {
      SensorMetrics& m = result[s];
      // 100 * count / n (not count * (100 / n)): correctly rounded, so exactly half the hours
      // gives exactly 50 % and the sDA ">= 50 %" test cannot fail on rounding.
      for (double* v : {&m.da_percent, &m.cda_percent, &m.da_max_percent, &m.udi_below_percent,
                        &m.udi_original_percent, &m.udi_above_original_percent,
                        &m.udi_supplementary_percent, &m.udi_autonomous_percent,
                        &m.udi_above_revised_percent})
        *v = 100.0 * *v / n_occupied;
      m.mean_occupied_lux /= n_occupied;
    }
  });
  return result;
}

std::vector<int> ase_hours_per_sensor(const IlluminanceTable& direct_sun,
                                      const OccupancySchedule& occupancy,
                                      const MetricSettings& settings) {
  check_shapes(direct_sun, occupancy);
  std::vector<int> hours(direct_sun.sensor_count(), 0);
  for_sensor_blocks(hours.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = 0; t < direct_sun.step_count(); ++t) {
      if (!occupancy.occupied(t)) continue;
      for (std::size_t s = begin; s < end; ++s) hours[s] += direct_sun.lux(t, s) >= settings.ase_threshold_lux;
    }
  });
  return hours;
}

GridMetrics summarize_grid(const std::vector<SensorMetrics>& sensors, const MetricSettings& settings,
                           const std::vector<double>& area_weights, const std::vector<int>* ase_hours) {
  if (!area_weights.empty() && area_weights.size() != sensors.size())
    throw std::invalid_argument("area weights and sensors differ in number");
  GridMetrics grid;
  auto mean_of = [&](double SensorMetrics::*field) {
    std::vector<double> v(sensors.size());
    for (std::size_t i = 0; i < sensors.size(); ++i) v[i] = sensors[i].*field;
    return weighted_mean(v, area_weights);
  };
  for (double SensorMetrics::*field :
       {&SensorMetrics::da_percent, &SensorMetrics::cda_percent, &SensorMetrics::da_max_percent,
        &SensorMetrics::udi_below_percent, &SensorMetrics::udi_original_percent,
        &SensorMetrics::udi_above_original_percent, &SensorMetrics::udi_supplementary_percent,
        &SensorMetrics::udi_autonomous_percent, &SensorMetrics::udi_above_revised_percent,
        &SensorMetrics::mean_occupied_lux})
    grid.mean.*field = mean_of(field);

  std::vector<double> passes(sensors.size());
  for (std::size_t i = 0; i < sensors.size(); ++i)
    passes[i] = sensors[i].da_percent >= 100.0 * settings.sda_time_fraction ? 100.0 : 0.0;
  grid.sda_percent = share_percent(passes, area_weights);

  if (ase_hours) {
    std::vector<double> fails(ase_hours->size());
    for (std::size_t i = 0; i < fails.size(); ++i) fails[i] = (*ase_hours)[i] > settings.ase_hours ? 100.0 : 0.0;
    grid.ase_percent = share_percent(fails, area_weights);
  }
  return grid;
}

double en17037_target_area_required_percent(const MetricSettings& settings) {
  return settings.en17037_openings == MetricSettings::Openings::Horizontal ? En17037TargetAreaPercentHorizontal
                                                                           : En17037TargetAreaPercentVertical;
}

const char* en17037_openings_name(MetricSettings::Openings openings) {
  switch (openings) {
    case MetricSettings::Openings::Horizontal: return "horizontal";
    case MetricSettings::Openings::Both: return "vertical or inclined, and horizontal";
    case MetricSettings::Openings::VerticalOrInclined: break;
  }
  return "vertical or inclined";
}

std::optional<MetricSettings::Openings> parse_en17037_openings(const std::string& name) {
  for (MetricSettings::Openings o : {MetricSettings::Openings::VerticalOrInclined, MetricSettings::Openings::Horizontal,
                                     MetricSettings::Openings::Both})
    if (name == en17037_openings_name(o)) return o;
  return std::nullopt;
}

std::vector<En17037Result> en17037_daylight_provision(const IlluminanceTable& table,
                                                      const OccupancySchedule& daylight_hours,
                                                      const std::vector<double>& area_weights,
                                                      const MetricSettings& settings) {
  check_shapes(table, daylight_hours);
  const double n_hours = static_cast<double>(daylight_hours.occupied_count());
  const std::size_t n_sensors = table.sensor_count();
  // Hours reached per level and sensor, counted step by step within a block of sensors (the
  // table is stored step by step, so a block reads its part of each row in order), then
  // whether each point meets each target; the area fractions are summed below in sensor
  // order, so no value depends on the blocks or the thread count.
  constexpr std::size_t Levels = std::size(En17037Levels);
  std::vector<std::vector<double>> target(Levels, std::vector<double>(n_sensors)), minimum = target;
  for_sensor_blocks(n_sensors, [&](std::size_t begin, std::size_t end) {
    const std::size_t n = end - begin;
    std::vector<std::size_t> hours_target(Levels * n, 0), hours_minimum(Levels * n, 0);
    for (std::size_t t = 0; t < table.step_count(); ++t) {
      if (!daylight_hours.occupied(t)) continue;
      for (std::size_t l = 0; l < Levels; ++l) {
        const double target_lux = En17037Levels[l].target_lux, minimum_lux = En17037Levels[l].minimum_target_lux;
        std::size_t* reached_target = hours_target.data() + l * n;
        std::size_t* reached_minimum = hours_minimum.data() + l * n;
        for (std::size_t s = begin; s < end; ++s) {
          const double e = table.lux(t, s);
          reached_target[s - begin] += e >= target_lux;
          reached_minimum[s - begin] += e >= minimum_lux;
        }
      }
    }
    // A point meets a target when it is reached for at least half of the daylight hours.
    for (std::size_t l = 0; l < Levels; ++l)
      for (std::size_t s = begin; s < end; ++s) {
        target[l][s] = n_hours > 0 && double(hours_target[l * n + s - begin]) >= 0.5 * n_hours ? 100.0 : 0.0;
        minimum[l][s] = n_hours > 0 && double(hours_minimum[l * n + s - begin]) >= 0.5 * n_hours ? 100.0 : 0.0;
      }
  });
  std::vector<En17037Result> results;
  for (std::size_t l = 0; l < Levels; ++l) {
    const En17037Level& level = En17037Levels[l];
    En17037Result r;
    r.level = level.name;
    r.target_area_percent = share_percent(target[l], area_weights);
    r.minimum_target_area_percent = share_percent(minimum[l], area_weights);
    r.target_area_required_percent = en17037_target_area_required_percent(settings);
    r.passes = r.target_area_percent >= r.target_area_required_percent &&
               r.minimum_target_area_percent >= En17037MinimumTargetAreaPercent;
    results.push_back(r);
  }
  return results;
}

}  // namespace dayphoton::metrics
