// verdict_uncertainty: see verdict_uncertainty.h.
#include "dayphoton/study/verdict_uncertainty.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dayphoton/core/units.h"
#include "dayphoton/metrics/occupancy.h"
#include "dayphoton/study/tile_product.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace dayphoton::study {

VerdictUncertainty verdict_uncertainty(const AnnualStudy& study, const AnnualSky& sky,
                                       const std::vector<double>& sky_variance, const SunBinVariance* sun,
                                       const AnnualStudySettings& settings, std::size_t block_values) {
  const std::size_t n_steps = study.illuminance.step_count(), n_sensors = study.illuminance.sensor_count();
  const std::size_t bins = sky.matrix.rows();
  if (sky_variance.size() != n_sensors * bins || sky.matrix.columns() != n_steps)
    throw std::invalid_argument("verdict uncertainty: " + std::to_string(sky_variance.size()) + " variances for " +
                                std::to_string(n_sensors) + " sensors x " + std::to_string(bins) + " bins, " +
                                std::to_string(sky.matrix.columns()) + " sky steps for " + std::to_string(n_steps));
  const double efficacy2 = RadianceWhiteEfficacy_lm_per_W * RadianceWhiteEfficacy_lm_per_W;
  const metrics::OccupancySchedule occupancy = occupancy_schedule(settings, sky.steps);
  std::vector<std::size_t> occupied_steps;
  for (std::size_t t = 0; t < n_steps; ++t)
    if (occupancy.occupied(t)) occupied_steps.push_back(t);
  const std::size_t n_occupied = occupied_steps.size();
  // The squared luminance of every bin in every occupied step (occupied steps x bins).
  std::vector<double> radiance2(n_occupied * bins);
  const int nc = sky.matrix.components();
  for (std::size_t j = 0; j < n_occupied; ++j) {
    const std::size_t t = occupied_steps[j];
    for (std::size_t p = 0; p < bins; ++p) {
      const double l = nc == 3 ? RgbLuminanceWeights.x * sky.matrix.at(p, t, 0) + RgbLuminanceWeights.y * sky.matrix.at(p, t, 1) +
                                     RgbLuminanceWeights.z * sky.matrix.at(p, t, 2)
                               : double(sky.matrix.at(p, t, 0));
      radiance2[j * bins + p] = l * l;
    }
  }
  // The same squares by tiles of TileSteps occupied steps, bin-major within a tile (zero past
  // the last step), for detail::tile_product: the sky part of each variance is its plain
  // sequential sum over the bins, computed for two sensors and a tile of steps at once.
  using detail::TileSteps;
  const std::size_t n_tiles = (n_occupied + TileSteps - 1) / TileSteps;
  std::vector<double> radiance2_tiles(n_tiles * bins * TileSteps, 0.0);
  for (std::size_t j = 0; j < n_occupied; ++j)
    for (std::size_t p = 0; p < bins; ++p)
      radiance2_tiles[(j / TileSteps * bins + p) * TileSteps + j % TileSteps] = radiance2[j * bins + p];
  radiance2 = {};
  // The suns of the occupied steps, in record order, with their stencils.
  std::vector<std::vector<std::size_t>> suns_at(n_occupied);
  std::vector<engine::SunStencil> stencils;
  std::size_t n_bins = 0;
  if (sun && sun->variance && sun->bins && sun->suns) {
    n_bins = sun->bins->size();
    if (sun->variance->size() != n_sensors * n_bins)
      throw std::invalid_argument("verdict uncertainty: the sun bins' variances do not match the sensors");
    std::vector<std::size_t> occupied_index(n_steps, n_occupied);
    for (std::size_t j = 0; j < n_occupied; ++j) occupied_index[occupied_steps[j]] = j;
    for (std::size_t i = 0; i < sun->suns->size(); ++i) {
      const sky::SunRecord& record = (*sun->suns)[i];
      stencils.push_back(sun->bins->weights(record.direction));
      if (record.step < n_steps && occupied_index[record.step] < n_occupied)
        suns_at[occupied_index[record.step]].push_back(i);
    }
  }
  VerdictUncertainty out;
  if (n_occupied == 0) return out;
  // Variance (lux^2) of every occupied step of a block of sensors and each sensor's verdict,
  // computed in parallel (each value's sums in the same order as one sensor alone, the
  // verdicts integer counts), then the sum of the variances taken in sensor order, step
  // order: no sensors x hours table is held.
  const std::size_t block = std::max<std::size_t>(1, block_values / n_occupied);
  std::vector<double> variance(std::min(block, n_sensors) * n_occupied);
  std::vector<char> uncertain(std::min(block, n_sensors));
  const double threshold = settings.metrics.da_threshold_lux;
  const double need = settings.metrics.sda_time_fraction * double(n_occupied);
  double sum_variance = 0;
  const std::vector<double>& area_m2 = settings.sensor_area_m2;
  if (!area_m2.empty() && area_m2.size() != n_sensors)
    throw std::invalid_argument("verdict uncertainty: " + std::to_string(area_m2.size()) + " sensor areas for " +
                                std::to_string(n_sensors) + " sensors");
  double uncertain_m2 = 0, total_m2 = 0;  // in sensor order
  for (std::size_t first = 0; first < n_sensors; first += block) {
    const std::size_t last = std::min(n_sensors, first + block);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last), [&](const tbb::blocked_range<std::size_t>& r) {
      // The sky's part: r2 . sv summed over the bins in order (tile_product.h), a tile of
      // steps at a time over the range's sensors (the tile stays in the first-level cache).
      double acc[2 * TileSteps];
      for (std::size_t tile = 0; tile < n_tiles; ++tile) {
        const std::size_t j0 = tile * TileSteps, m = std::min(TileSteps, n_occupied - j0);
        const double* columns = radiance2_tiles.data() + tile * bins * TileSteps;
        for (std::size_t s = r.begin(); s < r.end(); s += 2) {
          const std::size_t rows = std::min<std::size_t>(2, r.end() - s);
          detail::tile_product(sky_variance.data() + s * bins, rows, bins, columns, acc);
          for (std::size_t q = 0; q < rows; ++q) {
            double* row = variance.data() + (s + q - first) * n_occupied + j0;
            for (std::size_t j = 0; j < m; ++j) row[j] = efficacy2 * acc[q * TileSteps + j];
          }
        }
      }
      // Then each step's suns, added in record order.
      if (!stencils.empty())
        for (std::size_t s = r.begin(); s != r.end(); ++s) {
          double* row = variance.data() + (s - first) * n_occupied;
          for (std::size_t j = 0; j < n_occupied; ++j)
            for (const std::size_t i : suns_at[j]) {
              const sky::SunRecord& record = (*sun->suns)[i];
              const double vs = interpolated_sun_variance(stencils[i], sun->variance->data() + s * n_bins);
              row[j] += efficacy2 * record.disc_radiance * record.disc_radiance * vs;
            }
        }
      // The DA verdict with the illuminance lowered and raised by VerdictSigmas standard
      // errors, counted step by step (each step's row of the table read in order).
      const std::size_t n = r.end() - r.begin();
      std::vector<std::size_t> low(n, 0), high(n, 0);
      for (std::size_t j = 0; j < n_occupied; ++j)
        for (std::size_t s = r.begin(); s != r.end(); ++s) {
          const double e = study.illuminance.lux(occupied_steps[j], s), v = variance[(s - first) * n_occupied + j];
          const double band = VerdictSigmas * std::sqrt(v);
          low[s - r.begin()] += e - band >= threshold ? 1 : 0;
          high[s - r.begin()] += e + band >= threshold ? 1 : 0;
        }
      for (std::size_t s = r.begin(); s != r.end(); ++s)
        uncertain[s - first] = (double(low[s - r.begin()]) >= need) != (double(high[s - r.begin()]) >= need);
    });
    for (std::size_t s = first; s < last; ++s) {
      const double* row = variance.data() + (s - first) * n_occupied;
      for (std::size_t j = 0; j < n_occupied; ++j) sum_variance += row[j];
      if (uncertain[s - first]) ++out.da_verdicts_uncertain;
      if (!area_m2.empty()) {
        total_m2 += area_m2[s];
        if (uncertain[s - first]) uncertain_m2 += area_m2[s];
      }
    }
  }
  const std::size_t occupied = n_occupied;
  out.mean_occupied_stderr_lux = std::sqrt(sum_variance / (double(occupied) * double(n_sensors)));
  if (!area_m2.empty() && total_m2 > 0) out.da_verdicts_uncertain_area_percent = 100.0 * uncertain_m2 / total_m2;
  return out;
}

}  // namespace dayphoton::study
