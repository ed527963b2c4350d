// Annual sun with sun bins: exact hourly direct sun, interpolated indirect sun, and the
// annual study that adds both to the sky-only product. See study/annual_sun.h.
#include "dayphoton/study/annual_sun.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "dayphoton/core/atomic_file.h"
#include "dayphoton/core/units.h"
#include "dayphoton/engine/direct_component.h"
#include "dayphoton/engine/distant_source.h"
#include "dayphoton/engine/estimate_variance.h"
#include "dayphoton/engine/port_view.h"
#include "dayphoton/engine/random.h"
#include "dayphoton/metrics/annual_metrics.h"
#include "dayphoton/metrics/occupancy.h"
#include "dayphoton/sky/solar_position.h"
#include "dayphoton/study/annual_illuminance.h"

namespace dayphoton::study {
namespace {

/// Largest double below 1 (a jittered stratum coordinate must stay inside the disc's map).
constexpr double OneMinusEpsilon = 0x1.fffffffffffffp-1;

/// Columns of suns_to_matrix.
constexpr std::size_t SunColumns = 6;

std::string fixed(double v, int decimals) {
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed, decimals);
  std::string s(buffer, r.ptr);
  if (s.find_first_not_of("-0.") == std::string::npos) s = decimals > 0 ? "0." + std::string(decimals, '0') : "0";
  return s;
}

/// 179 (0.265, 0.670, 0.065) per component of an RGB matrix (1 component: 179).
Vec3 photometric_weights(int components) {
  if (components == 1) return {RadianceWhiteEfficacy_lm_per_W, 0, 0};
  if (components == 3) return RgbLuminanceWeights * RadianceWhiteEfficacy_lm_per_W;
  throw std::invalid_argument("annual sun: coefficients must have 1 or 3 components, not " +
                              std::to_string(components));
}

void check_suns(const std::vector<sky::SunRecord>& suns, std::size_t steps) {
  for (const sky::SunRecord& s : suns)
    if (s.step >= steps)
      throw std::invalid_argument("annual sun: a sun at step " + std::to_string(s.step) + " of " +
                                  std::to_string(steps));
}

}  // namespace

std::size_t sun_bin_bandwidth(std::size_t bandwidth) {
  const auto scaled = static_cast<std::size_t>(std::llround(double(bandwidth) * SunBinBandwidthFraction));
  return std::max(SunBinMinimumBandwidth, scaled);
}

std::vector<char> sun_bins_to_trace(const engine::PortEmitter& emitter, std::size_t bins) {
  double largest = 0;
  for (std::size_t i = 0; i < bins; ++i) largest = std::max(largest, emitter.bound_flux(i));
  std::vector<char> trace(bins, 0);
  for (std::size_t i = 0; i < bins; ++i)
    trace[i] = emitter.bound_flux(i) > 0 && emitter.bound_flux(i) >= SunBinMinimumBoundFraction * largest;
  return trace;
}

engine::TracedPhotons trace_sun_bins(const engine::Scene& scene,
                                     const std::vector<engine::Material>& materials,
                                     const engine::SunBins& bins,
                                     const std::vector<engine::ReceiverPlane>& planes,
                                     const engine::TracingOptions& options) {
  const engine::SourceSet sources = bins.sources(sky::SunHalfAngle_rad);
  const std::vector<char> trace = sun_bins_to_trace(engine::PortEmitter(scene, sources), sources.size());
  std::vector<engine::TracedPhotons> results(sources.size());
  tbb::parallel_for(std::size_t(0), sources.size(), [&](std::size_t p) {
    if (trace[p]) {
      results[p] = trace_sun_bin(scene, materials, bins, p, planes, options);
      relabel_photons(results[p], static_cast<std::uint32_t>(p));
    } else {
      results[p].planes.resize(planes.size());
      results[p].tallies.resize(1);
    }
  });
  return engine::merge_traced_photons(std::move(results));
}

std::uint64_t sun_bin_seed(std::uint64_t seed, int mf, int patch) {
  const std::uint64_t id = (static_cast<std::uint64_t>(mf) << 32) | static_cast<std::uint32_t>(patch);
  return engine::Rng::mix(engine::Rng::mix(seed) ^ engine::Rng::mix(id + 0x9E3779B97F4A7C15ull));
}

engine::TracedPhotons trace_sun_bin(const engine::Scene& scene,
                                    const std::vector<engine::Material>& materials,
                                    const engine::SunBins& bins, std::size_t bin,
                                    const std::vector<engine::ReceiverPlane>& planes,
                                    const engine::TracingOptions& options) {
  const engine::SourceSet one = sun_bin_source(bins, bin);
  const engine::PortEmitter emitter(scene, one);
  return engine::trace_source_photons(scene, materials, emitter, planes, sun_bin_tracing(options, bins, bin), 0);
}

engine::SourceSet sun_bin_source(const engine::SunBins& bins, std::size_t bin) {
  engine::SourceSet one;
  one.add_sun_disc(bins.direction(bin), sky::SunHalfAngle_rad);
  return one;
}

engine::TracingOptions sun_bin_tracing(const engine::TracingOptions& options, const engine::SunBins& bins,
                                       std::size_t bin) {
  engine::TracingOptions o = options;
  o.seed = sun_bin_seed(options.seed, bins.multiplication_factor(), bins.patch(bin));
  o.source_photon_factor.clear();
  return o;
}

void relabel_photons(engine::TracedPhotons& photons, std::uint32_t source) {
  if (source >= engine::MaxPhotonSources)
    throw std::invalid_argument("sun photons: source " + std::to_string(source) + " beyond the photon record's " +
                                std::to_string(engine::MaxPhotonSources));
  for (engine::Photon& p : photons.surface) p.source = source;
  for (std::vector<engine::Photon>& plane : photons.planes)
    for (engine::Photon& p : plane) p.source = source;
}

sky::SkyMatrixOptions sun_excluded_sky_options(double ground_reflectance) {
  sky::SkyMatrixOptions o = radiance_compatible_sky_options(ground_reflectance);
  o.sun = sky::SunInMatrix::None;
  return o;
}

std::string sky_and_suns_description(const weather::HourlyWeather& weather, const sky::PatchBasis& basis) {
  return "Perez sky matrix without the sun (gendaymtx -s conventions, MF " + std::to_string(basis.multiplication_factor()) +
         ") from " + weather.source_name + "; sun from sun bins (indirect) and exact hourly shadow rays (direct)";
}

SkyAndSuns annual_sky_and_suns(const weather::HourlyWeather& weather, const sky::SolarSite& site,
                               const sky::PatchBasis& basis, sky::SkyMatrixOptions options) {
  options.sun = sky::SunInMatrix::None;
  options.quadrant_deltas = true;
  sky::SkyMatrix built = sky::build_sky_matrix(weather, site, basis, options);
  SkyAndSuns result;
  result.sky.matrix = std::move(built.matrix);
  result.sky.quadrant_deltas = std::move(built.quadrant_deltas);
  result.sky.steps = time_stamps(weather);
  result.sky.daylight_hours_quantity = daylight_hours_quantity(weather, result.sky.daylight_hours_source);
  result.sky.description = sky_and_suns_description(weather, basis);
  result.suns = suns_from_matrix(suns_to_matrix(built.suns));  // the cache's float rounding
  return result;
}

RadianceMatrix suns_to_matrix(const std::vector<sky::SunRecord>& suns) {
  RadianceMatrix m(suns.size(), SunColumns, 1);
  for (std::size_t i = 0; i < suns.size(); ++i) {
    const sky::SunRecord& s = suns[i];
    const double values[SunColumns] = {double(s.step), s.direction.x, s.direction.y, s.direction.z,
                                       s.direct_normal_illuminance_lux, s.disc_radiance};
    for (std::size_t c = 0; c < SunColumns; ++c) m.at(i, c, 0) = static_cast<float>(values[c]);
  }
  return m;
}

std::vector<sky::SunRecord> suns_from_matrix(const RadianceMatrix& m) {
  if (m.columns() != SunColumns || m.components() != 1)
    throw std::runtime_error("sun records: expected " + std::to_string(SunColumns) +
                             " columns of 1 component");
  std::vector<sky::SunRecord> suns(m.rows());
  for (std::size_t i = 0; i < m.rows(); ++i) {
    double v[SunColumns];
    for (std::size_t c = 0; c < SunColumns; ++c) {
      v[c] = m.at(i, c, 0);
      if (!std::isfinite(v[c])) throw std::runtime_error("sun records: a value is not finite");
    }
    if (v[0] < 0 || v[0] != std::floor(v[0]) || !(v[3] > 0))
      throw std::runtime_error("sun records: a bad step or a sun below the horizon");
    suns[i].step = static_cast<std::size_t>(v[0]);
    suns[i].direction = normalize(Vec3{v[1], v[2], v[3]});
    suns[i].direct_normal_illuminance_lux = v[4];
    suns[i].disc_radiance = v[5];
  }
  return suns;
}

RadianceMatrix direct_sun_coefficients(const engine::Scene& scene,
                                       const std::vector<engine::Material>& materials,
                                       const std::vector<SensorPoint>& sensors,
                                       const std::vector<sky::SunRecord>& suns, int samples,
                                       std::uint64_t seed, DirectSunValues values, engine::SensorRange rows,
                                       std::vector<double>* variance) {
  rows = rows.within(sensors.size());
  if (samples < 1) throw std::invalid_argument("direct sun: at least 1 sample per sun is needed");
  int k = static_cast<int>(std::sqrt(double(samples)));
  while (k * k < samples) ++k;
  // The discs, sampled by SourceSet's area-preserving cone map (distant_source.h).
  engine::SourceSet discs;
  for (const sky::SunRecord& s : suns) discs.add_sun_disc(s.direction, sky::SunHalfAngle_rad);
  const double weight = discs.size() ? discs[0].solid_angle_sr / (double(k) * k) : 0.0;

  const double pad_m = engine::port_view_pad_m(scene, materials);
  const bool rgb = values == DirectSunValues::Rgb;
  RadianceMatrix result(rows.size(), suns.size(), rgb ? 3 : 1);
  if (variance) variance->assign(rows.size() * suns.size(), 0.0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(rows.begin, rows.end),
                    [&](const tbb::blocked_range<std::size_t>& range) {
    for (std::size_t s = range.begin(); s != range.end(); ++s) {
      const double len = length(sensors[s].normal);
      if (!is_finite(sensors[s].normal) || !(len > 0.0) || !is_finite(sensors[s].position))
        throw std::invalid_argument("direct sun: a sensor needs a finite position and a non-zero normal");
      const Vec3 normal = sensors[s].normal / len;
      const Vec3 origin = sensors[s].position + normal * scene.ray_epsilon_m();
      const engine::PortView ports(scene, origin, pad_m, sky::SunHalfAngle_rad);
      for (std::size_t i = 0; i < suns.size(); ++i) {
        Vec3 sum;
        // A disc wholly behind the sensor's plane contributes nothing (its angular radius
        // is far below any cos margin that matters, checked per sample below anyway), nor
        // does one whose every ray misses every port (engine/port_view.h: each of its rays
        // would have zero sky transmittance, so skipping them changes no value).
        if (dot(suns[i].direction, normal) > -std::sin(sky::SunHalfAngle_rad) &&
            ports.may_cross_port(suns[i].direction, sky::SunHalfAngle_rad)) {
          engine::Rng rng(seed, suns[i].step, s, engine::RandomStream::Direct);
          // Each stratum's share of the value's luminance, row by row (rows of k strata).
          double* v = variance ? &(*variance)[(s - rows.begin) * suns.size() + i] : nullptr;
          engine::StratifiedVariance strata(k, v);
          for (int a = 0; a < k; ++a)
            for (int b = 0; b < k; ++b) {
              const double u1 = std::min((a + rng.uniform()) / k, OneMinusEpsilon);
              const double u2 = std::min((b + rng.uniform()) / k, OneMinusEpsilon);
              const Vec3 w = discs.sample_direction(i, u1, u2);
              const double c = dot(w, normal);
              Vec3 ray;
              if (c > 0.0) ray = engine::sky_transmittance(scene, materials, origin, w) * c;
              sum += ray;
              if (v) strata.add(0, dot(ray, RgbLuminanceWeights) * weight);
            }
        }
        if (rgb) {
          for (int c = 0; c < 3; ++c) result.at(s - rows.begin, i, c) = static_cast<float>(sum[c] * weight);
        } else {
          result.at(s - rows.begin, i, 0) = static_cast<float>(dot(sum, RgbLuminanceWeights) * weight);
        }
      }
    }
  });
  return result;
}

namespace {

/// sun_bin_coefficients with the variances stored as `Real` (double, or float as the cache
/// keeps them).
template <class Real>
RadianceMatrix sun_bin_coefficients_into(const engine::Scene& scene, const std::vector<engine::Material>& materials,
                                         const engine::SourceSet& sources, const engine::GridPhotons& photons,
                                         const std::vector<SensorPoint>& sensors,
                                         const engine::CoefficientOptions& options, std::vector<Real>* variance,
                                         engine::SensorRange rows, std::size_t block_values) {
  rows = rows.within(sensors.size());
  const std::size_t n_sources = photons.source_count();
  RadianceMatrix result(rows.size(), n_sources, 3);
  if (variance) variance->assign(rows.size() * n_sources, Real(0));
  // Estimates on a receiver plane without bias compensation are made a block of sensors at a
  // time, so the double-precision parts of only SunCoefficientBlockValues coefficients are
  // held, whatever the grid's size; the others in one block. A block's rows are those of the
  // whole grid (engine/sensor_range.h), so the blocks change no value.
  const bool blocks = !photons.gather() && !options.bias_compensation;
  const std::size_t block =
      blocks ? std::max<std::size_t>(1, block_values / std::max<std::size_t>(1, n_sources)) : rows.size();
  for (std::size_t first = rows.begin; first < rows.end; first += block) {
    const std::size_t last = std::min(rows.end, first + block);
    engine::DaylightCoefficients c;
    c.sensors = last - first;
    c.sources = n_sources;
    c.caustic.assign(c.sensors * c.sources, Vec3{});
    c.global.assign(c.sensors * c.sources, Vec3{});
    engine::photon_coefficients(scene, materials, sources, photons, sensors, options, c,
                                engine::SensorRange{first, last});
    const std::size_t row0 = first - rows.begin;
    for (std::size_t s = 0; s < c.sensors; ++s)
      for (std::size_t p = 0; p < n_sources; ++p) {
        const std::size_t i = s * n_sources + p;
        const Vec3 total = Vec3{} + c.caustic[i] + c.global[i];  // DaylightCoefficients::total, no direct part
        for (int k = 0; k < 3; ++k) result.at(row0 + s, p, k) = static_cast<float>(total[k]);
        if (variance) (*variance)[(row0 + s) * n_sources + p] = static_cast<Real>(c.photon_variance[i]);
      }
  }
  return result;
}

}  // namespace

RadianceMatrix sun_bin_coefficients(const engine::Scene& scene, const std::vector<engine::Material>& materials,
                                    const engine::SourceSet& sources, const engine::GridPhotons& photons,
                                    const std::vector<SensorPoint>& sensors, const engine::CoefficientOptions& options,
                                    std::vector<double>* variance, engine::SensorRange rows,
                                    std::size_t block_values) {
  return sun_bin_coefficients_into(scene, materials, sources, photons, sensors, options, variance, rows, block_values);
}

RadianceMatrix sun_bin_coefficients(const engine::Scene& scene, const std::vector<engine::Material>& materials,
                                    const engine::SourceSet& sources, const engine::GridPhotons& photons,
                                    const std::vector<SensorPoint>& sensors, const engine::CoefficientOptions& options,
                                    std::vector<float>* variance, engine::SensorRange rows,
                                    std::size_t block_values) {
  return sun_bin_coefficients_into(scene, materials, sources, photons, sensors, options, variance, rows, block_values);
}

metrics::IlluminanceTable direct_sun_table(const RadianceMatrix& direct,
                                           const std::vector<sky::SunRecord>& suns,
                                           const std::vector<metrics::TimeStamp>& steps) {
  if (direct.columns() != suns.size())
    throw std::invalid_argument("direct sun: " + std::to_string(direct.columns()) + " columns for " +
                                std::to_string(suns.size()) + " suns");
  check_suns(suns, steps.size());
  const Vec3 w = photometric_weights(direct.components());
  metrics::IlluminanceTable table(steps, direct.rows());
  for (std::size_t i = 0; i < suns.size(); ++i)
    for (std::size_t s = 0; s < direct.rows(); ++s) {
      double e = 0;
      for (int c = 0; c < direct.components(); ++c) e += w[c] * double(direct.at(s, i, c));
      table.lux(suns[i].step, s) = static_cast<float>(e * suns[i].disc_radiance);
    }
  return table;
}

metrics::IlluminanceTable indirect_sun_table(const RadianceMatrix& bin_coefficients,
                                             const engine::SunBins& bins,
                                             const std::vector<sky::SunRecord>& suns,
                                             const std::vector<metrics::TimeStamp>& steps) {
  if (bin_coefficients.columns() != bins.size())
    throw std::invalid_argument("indirect sun: " + std::to_string(bin_coefficients.columns()) +
                                " coefficient columns for " + std::to_string(bins.size()) + " sun bins");
  check_suns(suns, steps.size());
  const Vec3 w = photometric_weights(bin_coefficients.components());
  const std::size_t n_sensors = bin_coefficients.rows();
  // Illuminance per unit disc radiance of every (sensor, bin): 179 w . C.
  std::vector<double> lux(n_sensors * bins.size());
  for (std::size_t s = 0; s < n_sensors; ++s)
    for (std::size_t j = 0; j < bins.size(); ++j) {
      double e = 0;
      for (int c = 0; c < bin_coefficients.components(); ++c) e += w[c] * double(bin_coefficients.at(s, j, c));
      lux[s * bins.size() + j] = e;
    }
  metrics::IlluminanceTable table(steps, n_sensors);
  for (const sky::SunRecord& sun : suns) {
    const engine::SunStencil st = bins.weights(sun.direction);
    for (std::size_t s = 0; s < n_sensors; ++s) {
      double e = 0;
      for (int k = 0; k < st.count; ++k)
        e += st.weight[static_cast<std::size_t>(k)] *
             lux[s * bins.size() + static_cast<std::size_t>(st.index[static_cast<std::size_t>(k)])];
      table.lux(sun.step, s) = static_cast<float>(e * sun.disc_radiance);
    }
  }
  return table;
}

AnnualStudy compute_annual_study_with_sun(const RadianceMatrix& sky_coefficients,
                                          const AnnualSky& sky,
                                          const metrics::IlluminanceTable& direct_sun,
                                          const metrics::IlluminanceTable& indirect_sun,
                                          const AnnualStudySettings& settings, const SubPatchShares* shares) {
  const std::size_t n_steps = sky.steps.size(), n_sensors = sky_coefficients.rows();
  for (const metrics::IlluminanceTable* t : {&direct_sun, &indirect_sun})
    if (t->step_count() != n_steps || t->sensor_count() != n_sensors)
      throw std::invalid_argument("annual sun: a sun table of " + std::to_string(t->step_count()) + " steps x " +
                                  std::to_string(t->sensor_count()) + " sensors for a study of " +
                                  std::to_string(n_steps) + " x " + std::to_string(n_sensors));
  // The sky part and every metric as compute_annual_study does them, ASE from the direct
  // sun; then the sun added to the table and the illuminance metrics evaluated again on it.
  AnnualStudy study = compute_annual_study(sky_coefficients, sky, settings, &direct_sun, shares);
  for (std::size_t t = 0; t < n_steps; ++t)
    for (std::size_t s = 0; s < n_sensors; ++s)
      study.illuminance.lux(t, s) = static_cast<float>(double(study.illuminance.lux(t, s)) +
                                                       double(direct_sun.lux(t, s)) +
                                                       double(indirect_sun.lux(t, s)));
  const metrics::OccupancySchedule occupancy = occupancy_schedule(settings, sky.steps);
  study.sensors = metrics::compute_sensor_metrics(study.illuminance, occupancy, settings.metrics);
  summarize_annual_study(study, settings, true, sky.daylight_hours_quantity, sky.daylight_hours_source);
  return study;
}

AnnualStudy compute_annual_study_with_sun(const RadianceMatrix& sky_coefficients, const AnnualSky& sky,
                                          const GridSunCoefficients& sun, const AnnualStudySettings& settings,
                                          const SubPatchShares* shares) {
  const std::size_t n_steps = sky.steps.size(), n_sensors = sky_coefficients.rows();
  const SparseSunRows* sparse = sun.direct_rows;
  const RadianceMatrix* dense = sparse ? nullptr : sun.direct;
  const RadianceMatrix& bin_coefficients = *sun.bin_coefficients;
  const std::vector<sky::SunRecord>& suns = *sun.suns;
  const engine::SunBins& bins = *sun.bins;
  const std::size_t direct_rows = sparse ? sparse->rows : dense->rows();
  const std::size_t direct_columns = sparse ? sparse->columns : dense->columns();
  if (direct_columns != suns.size() || direct_rows != n_sensors)
    throw std::invalid_argument("annual sun: a direct sun of " + std::to_string(direct_rows) + " sensors x " +
                                std::to_string(direct_columns) + " suns for " + std::to_string(n_sensors) +
                                " sensors and " + std::to_string(suns.size()) + " suns");
  if (bin_coefficients.columns() != bins.size() || bin_coefficients.rows() != n_sensors)
    throw std::invalid_argument("annual sun: sun-bin coefficients of " + std::to_string(bin_coefficients.rows()) +
                                " sensors x " + std::to_string(bin_coefficients.columns()) + " bins for " +
                                std::to_string(n_sensors) + " sensors and " + std::to_string(bins.size()) + " bins");
  check_suns(suns, n_steps);
  const metrics::OccupancySchedule occupancy = occupancy_schedule(settings, sky.steps);
  AnnualStudy study;
  study.illuminance = annual_illuminance(sky_coefficients, sky.matrix, sky.steps, 0, shares, &sky.quadrant_deltas);
  study.sky_description = sky.description;
  study.occupied_hours = occupancy.occupied_count();
  // A step's last sun wins, as in direct_sun_table and indirect_sun_table.
  std::vector<std::size_t> last(n_steps, suns.size());
  for (std::size_t i = 0; i < suns.size(); ++i) last[suns[i].step] = i;
  std::vector<std::size_t> used;
  std::vector<engine::SunStencil> stencils;
  for (std::size_t i = 0; i < suns.size(); ++i)
    if (last[suns[i].step] == i) {
      used.push_back(i);
      stencils.push_back(bins.weights(suns[i].direction));
    }
  // ASE from the direct sun alone (metrics::ase_hours_per_sensor on the direct-sun table,
  // which is 0 at every step without a sun).
  const float zero = 0.0f;
  const double threshold = settings.metrics.ase_threshold_lux;
  std::size_t occupied_without_sun = study.occupied_hours;
  for (std::size_t i : used) occupied_without_sun -= occupancy.occupied(suns[i].step) ? 1 : 0;
  study.ase_hours.assign(n_sensors, zero >= threshold ? static_cast<int>(occupied_without_sun) : 0);
  const Vec3 wd = photometric_weights(sparse ? 1 : dense->components());
  const Vec3 wi = photometric_weights(bin_coefficients.components());
  // The sun added in place, the three parts summed in double as compute_annual_study_with_sun
  // of the tables does, each part rounded to float as its table stores it: the same values,
  // without the two steps x sensors tables.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n_sensors, 64), [&](const tbb::blocked_range<std::size_t>& r) {
    std::vector<double> lux(bins.size());
    for (std::size_t s = r.begin(); s != r.end(); ++s) {
      for (std::size_t j = 0; j < bins.size(); ++j) {
        double e = 0;
        for (int c = 0; c < bin_coefficients.components(); ++c) e += wi[c] * double(bin_coefficients.at(s, j, c));
        lux[j] = e;
      }
      // The sparse row's entries in sun order, as `used` is: a missing entry is the dense 0.
      std::uint64_t next = sparse ? sparse->row_start[s] : 0;
      const std::uint64_t row_end = sparse ? sparse->row_start[s + 1] : 0;
      for (std::size_t u = 0; u < used.size(); ++u) {
        const sky::SunRecord& record = suns[used[u]];
        double ed = 0;
        if (sparse) {
          while (next < row_end && sparse->column[next] < used[u]) ++next;
          if (next < row_end && sparse->column[next] == used[u]) ed += wd[0] * double(sparse->value[next]);
        } else {
          for (int c = 0; c < dense->components(); ++c) ed += wd[c] * double(dense->at(s, used[u], c));
        }
        const float d = static_cast<float>(ed * record.disc_radiance);
        const engine::SunStencil& st = stencils[u];
        double ei = 0;
        for (int k = 0; k < st.count; ++k)
          ei += st.weight[static_cast<std::size_t>(k)] * lux[static_cast<std::size_t>(st.index[static_cast<std::size_t>(k)])];
        const float ind = static_cast<float>(ei * record.disc_radiance);
        float& e = study.illuminance.lux(record.step, s);
        e = static_cast<float>(double(e) + double(d) + double(ind));
        if (occupancy.occupied(record.step) && d >= threshold) ++study.ase_hours[s];
      }
    }
  });
  study.sensors = metrics::compute_sensor_metrics(study.illuminance, occupancy, settings.metrics);
  summarize_annual_study(study, settings, true, sky.daylight_hours_quantity, sky.daylight_hours_source);
  return study;
}

void write_sun_bins_csv(const engine::SunBins& bins, const std::vector<sky::SunRecord>& suns,
                        const std::string& path) {
  std::vector<int> hours(bins.size(), 0);
  for (const sky::SunRecord& sun : suns) {
    const engine::SunStencil st = bins.weights(sun.direction);
    for (int k = 0; k < st.count; ++k) ++hours[static_cast<std::size_t>(st.index[static_cast<std::size_t>(k)])];
  }
  write_file_atomically(path, [&](std::ostream& out) {
    out << "bin,patch,altitude_deg,azimuth_deg,x,y,z,hours\n";
    for (std::size_t i = 0; i < bins.size(); ++i) {
      const Vec3 d = bins.direction(i);
      double azimuth = rad_to_deg(std::atan2(d.x, d.y));
      if (azimuth < 0) azimuth += 360.0;
      out << i << ',' << bins.patch(i) << ',' << fixed(rad_to_deg(std::asin(d.z)), 4) << ','
          << fixed(azimuth, 4) << ',' << fixed(d.x, 6) << ',' << fixed(d.y, 6) << ',' << fixed(d.z, 6) << ','
          << hours[i] << '\n';
    }
  });
}

}  // namespace dayphoton::study
