// The annual multiply by sensor blocks: see annual_blocks.h.
#include "dayphoton/study/annual_blocks.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <type_traits>

#include "dayphoton/metrics/annual_metrics.h"
#include "dayphoton/study/annual_illuminance.h"
#include "dayphoton/study/annual_sun.h"

namespace dayphoton::study {
namespace {

/// Rows [begin, end) of a matrix (with its header lines).
RadianceMatrix matrix_rows(const RadianceMatrix& m, std::size_t begin, std::size_t end) {
  RadianceMatrix rows(end - begin, m.columns(), m.components());
  rows.header_lines() = m.header_lines();
  const std::size_t per_row = m.columns() * static_cast<std::size_t>(m.components());
  std::copy(m.data().begin() + static_cast<std::ptrdiff_t>(begin * per_row),
            m.data().begin() + static_cast<std::ptrdiff_t>(end * per_row), rows.data().begin());
  return rows;
}

// Values as this build lays them out in memory: every rank runs the same build.
template <class T>
std::string bytes_of(const std::vector<T>& values) {
  static_assert(std::is_trivially_copyable_v<T>);
  std::string bytes(values.size() * sizeof(T), '\0');
  if (!values.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
  return bytes;
}

template <class T>
std::vector<T> values_of(const std::string& bytes, std::size_t expected) {
  static_assert(std::is_trivially_copyable_v<T>);
  if (bytes.size() != expected * sizeof(T)) throw std::runtime_error("annual blocks: a block of the wrong size");
  std::vector<T> values(expected);
  if (expected > 0) std::memcpy(values.data(), bytes.data(), bytes.size());
  return values;
}

}  // namespace

std::optional<AnnualStudy> annual_study_in_blocks(StepExecutor& executor, const std::string& name,
                                                  const RadianceMatrix& coefficients, const AnnualSky& sky,
                                                  const AnnualStudySettings& settings, const GridSunCoefficients* sun,
                                                  const SubPatchShares* shares) {
  const std::size_t n_sensors = coefficients.rows(), n_steps = sky.steps.size();
  const metrics::OccupancySchedule occupancy = occupancy_schedule(settings, sky.steps);
  // A block: its illuminance (steps x its sensors), per-sensor metrics and (with the sun) ASE
  // hours, as compute_annual_study_with_sun computes them for the whole grid.
  SensorBlocks blocks;
  blocks.sensors = n_sensors;
  blocks.compute_rows = [&](std::size_t begin, std::size_t end) {
    const SubPatchShares block_shares = shares ? shares->rows(begin, end) : SubPatchShares{};
    metrics::IlluminanceTable table = annual_illuminance(matrix_rows(coefficients, begin, end), sky.matrix, sky.steps,
                                                         begin, &block_shares, &sky.quadrant_deltas);
    std::vector<int> ase;
    if (sun) {
      const metrics::IlluminanceTable direct =
          direct_sun_table(matrix_rows(*sun->direct, begin, end), *sun->suns, sky.steps);
      const metrics::IlluminanceTable indirect =
          indirect_sun_table(matrix_rows(*sun->bin_coefficients, begin, end), *sun->bins, *sun->suns, sky.steps);
      ase = metrics::ase_hours_per_sensor(direct, occupancy, settings.metrics);
      for (std::size_t t = 0; t < n_steps; ++t)
        for (std::size_t s = 0; s < end - begin; ++s)
          table.lux(t, s) = static_cast<float>(double(table.lux(t, s)) + double(direct.lux(t, s)) +
                                               double(indirect.lux(t, s)));
    }
    const std::vector<metrics::SensorMetrics> metrics = metrics::compute_sensor_metrics(table, occupancy, settings.metrics);
    std::vector<float> lux(n_steps * (end - begin));
    for (std::size_t t = 0; t < n_steps; ++t)
      for (std::size_t s = 0; s < end - begin; ++s) lux[t * (end - begin) + s] = table.lux(t, s);
    return std::vector<std::string>{bytes_of(lux), bytes_of(metrics), bytes_of(ase)};
  };
  const std::vector<std::vector<std::string>> parts = executor.blocks_to_root(blocks, "annual " + name);
  if (!executor.writes_results()) return std::nullopt;  // not rank 0, which joins and writes them

  AnnualStudy study;
  study.illuminance = metrics::IlluminanceTable(sky.steps, n_sensors);
  study.sky_description = sky.description;
  study.occupied_hours = occupancy.occupied_count();
  std::size_t first = 0;
  for (const std::vector<std::string>& part : parts) {
    if (part.size() != 3) throw std::runtime_error("annual blocks: a block of the wrong shape");
    const std::vector<metrics::SensorMetrics> metrics =
        values_of<metrics::SensorMetrics>(part[1], part[1].size() / sizeof(metrics::SensorMetrics));
    const std::size_t n = metrics.size();
    if (first + n > n_sensors) throw std::runtime_error("annual blocks: more sensors than the grid's");
    const std::vector<float> lux = values_of<float>(part[0], n_steps * n);
    for (std::size_t t = 0; t < n_steps; ++t)
      for (std::size_t s = 0; s < n; ++s) study.illuminance.lux(t, first + s) = lux[t * n + s];
    study.sensors.insert(study.sensors.end(), metrics.begin(), metrics.end());
    if (sun) {
      const std::vector<int> ase = values_of<int>(part[2], n);
      study.ase_hours.insert(study.ase_hours.end(), ase.begin(), ase.end());
    }
    first += n;
  }
  if (first != n_sensors) throw std::runtime_error("annual blocks: fewer sensors than the grid's");
  summarize_annual_study(study, settings, sun != nullptr, sky.daylight_hours_quantity, sky.daylight_hours_source);
  return study;
}

}  // namespace dayphoton::study
