// Annual sky matrices and sky vectors; see sky_matrix.h. gendaymtx behaviour restated from
// ../shared/facts/sky-and-metrics.md sections 2.4 (normalisation, ground), 2.6 (edge cases),
// 4.4 (the sun spread over the 4 nearest patches with weights 1/(1.002 - cos)).
#include "dayphoton/sky/sky_matrix.h"

#include "dayphoton/sky/spread_sun.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/units.h"
#include "dayphoton/sky/perez.h"
#include "dayphoton/weather/site_clock.h"

namespace dayphoton::sky {

namespace {

/// Solid angle of the 0.533 degree sun disc (sr).
const double SunDiscSolidAngle_sr = 2.0 * Pi * (1.0 - std::cos(SunHalfAngle_rad));

/// Mean of f over a bin by an n x n midpoint rule in the bin's equal-solid-angle parameters.
template <typename F>
double bin_mean(const PatchBasis& basis, int bin, int n, const F& f) {
  double sum = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) sum += f(basis.sample_direction(bin, (i + 0.5) / n, (j + 0.5) / n));
  return sum / (n * n);
}

/// Mean of f over each quadrant of a bin (PatchBasis::quadrant) by an n x n midpoint rule.
template <typename F>
std::array<double, PatchBasis::QuadrantCount> quadrant_means(const PatchBasis& basis, int bin, int n, const F& f) {
  std::array<double, PatchBasis::QuadrantCount> mean{};
  for (int q = 0; q < PatchBasis::QuadrantCount; ++q) {
    const double u1_0 = 0.5 * (q / 2), u2_0 = 0.5 * (q % 2);
    double sum = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        sum += f(basis.sample_direction(bin, u1_0 + 0.5 * (i + 0.5) / n, u2_0 + 0.5 * (j + 0.5) / n));
    mean[static_cast<std::size_t>(q)] = sum / (n * n);
  }
  return mean;
}

/// Integral of cos(theta) over a sky bin (sr): dphi (sin^2 h_max - sin^2 h_min) / 2.
double projected_solid_angle_sr(const PatchBasis& basis, int bin) {
  const PatchBounds b = basis.bounds(bin);
  const double s0 = std::sin(b.altitude_min_rad), s1 = std::sin(b.altitude_max_rad);
  return (b.azimuth_max_rad - b.azimuth_min_rad) * (s1 * s1 - s0 * s0) / 2.0;
}

/// Integral of cos(theta) over quadrant q of a sky bin (PatchBasis::quadrant): half the
/// azimuth range times (s1^2 - s0^2) / 2 over its half in sine of altitude.
double quadrant_projected_solid_angle_sr(const PatchBasis& basis, int bin, int q) {
  const PatchBounds b = basis.bounds(bin);
  const double s0 = std::sin(b.altitude_min_rad), s1 = std::sin(b.altitude_max_rad), sm = 0.5 * (s0 + s1);
  const double half_azimuth = 0.5 * (b.azimuth_max_rad - b.azimuth_min_rad);
  return half_azimuth * (q / 2 == 0 ? sm * sm - s0 * s0 : s1 * s1 - sm * sm) / 2.0;
}

/// Midpoints per axis of a quadrant of `basis`'s bins for the quadrant deltas: the spacing of
/// QuadrantSamplesPerAxis on a Tregenza-sized patch, at least 1.
int quadrant_samples_of(const PatchBasis& basis) {
  return std::max(1, (QuadrantSamplesPerAxis + basis.multiplication_factor() - 1) / basis.multiplication_factor());
}

/// Add the sun to the 4 sky patches nearest to it, as gendaymtx does (spread_sun.h):
/// patch radiance += w E_nv / (179 Omega).
void spread_sun(const PatchBasis& basis, const Vec3& sun, double direct_normal_lux, RadianceMatrix& m,
                std::size_t column) {
  const SpreadSunPatches spread = spread_sun_patches(basis, sun);
  for (int k = 0; k < SpreadSunPatches::Count; ++k) {
    const double add =
        spread.weight[k] * direct_normal_lux / (RadianceWhiteEfficacy_lm_per_W * basis.solid_angle_sr(spread.bin[k]));
    for (int c = 0; c < 3; ++c) m.at(spread.bin[k], column, c) += static_cast<float>(add);
  }
}

void set_rgb(RadianceMatrix& m, std::size_t row, std::size_t column, const Vec3& rgb) {
  for (int c = 0; c < 3; ++c) m.at(row, column, c) = static_cast<float>(rgb[c]);
}

/// The records' hours are local standard time of the file's time zone: a site on another
/// clock would pair each record with the sun of another instant (sky_matrix.h).
void require_file_clock(const weather::HourlyWeather& weather, const SolarSite& site) {
  if (site.time_zone_h != weather.site.time_zone_h)
    throw std::invalid_argument("sky matrix: the site's time zone (" + format_number(site.time_zone_h) +
                                " h) is not the clock of " + weather.source_name + "'s records (" +
                                format_number(weather.site.time_zone_h) + " h)");
}

SolarPositionOptions solar_options_for(const weather::HourlyWeather& weather, const SkyMatrixOptions& options) {
  SolarPositionOptions solar = options.solar;
  solar.radiance_series_has_leap_day = weather.leap_day_present;
  return solar;
}

/// The sun of a record: at its mid-hour, local standard time (SiteClock).
SolarPosition record_sun(const SolarSite& site, const weather::SiteClock& clock, const weather::TimeStep& step,
                         const SolarPositionOptions& solar) {
  return solar_position(site, SolarTime{clock.year(), step.month, step.day, step.hour_lst}, solar);
}

/// BelowHorizonDirect's rule: direct light measured while the sun's centre is below the horizon.
bool direct_below_horizon(double direct_normal_W_m2, const SolarPosition& sun) {
  return direct_normal_W_m2 > 0 && sun.direction.z <= 0;
}

/// BelowHorizonDirect from each record's direct normal irradiance if it is below the horizon
/// (else 0) and the file's records.
BelowHorizonDirect tally_below_horizon(const std::vector<double>& below_W_m2, const weather::HourlyWeather& weather) {
  BelowHorizonDirect b;
  for (const double dni : below_W_m2) {
    if (!(dni > 0)) continue;
    ++b.records;
    if (dni > GendaymtxBelowHorizonWarning_W_m2) ++b.records_over_20_W_m2;
    b.direct_normal_Wh_m2 += dni;              // hourly records: W/m^2 x 1 h
    b.largest_W_m2 = std::max(b.largest_W_m2, dni);
  }
  for (const weather::WeatherRecord& r : weather.records)
    if (r.direct_normal_w_m2 && *r.direct_normal_w_m2 > 0) b.file_direct_normal_Wh_m2 += *r.direct_normal_w_m2;
  return b;
}

}  // namespace

SkyMatrixOptions SkyMatrixOptions::gendaymtx_compatible() {
  SkyMatrixOptions o;
  o.patch_value = PatchValue::Centre;
  o.solar.algorithm = SolarPositionAlgorithm::Radiance;
  o.sky_colour = GendaymtxSkyColour;
  o.dew_point_from_weather = false;
  o.radiance_day_of_year = true;
  return o;
}

SolarSite solar_site_of(const weather::HourlyWeather& weather) {
  SolarSite site;
  site.latitude_deg = weather.site.latitude_deg;
  site.longitude_deg = weather.site.longitude_east_deg;
  site.time_zone_h = weather.site.time_zone_h;
  site.elevation_m = weather.site.elevation_m;
  return site;
}

BelowHorizonDirect below_horizon_direct(const weather::HourlyWeather& weather, const SolarSite& site,
                                        const SkyMatrixOptions& options) {
  require_file_clock(weather, site);
  const weather::SiteClock clock = weather::SiteClock::for_weather(weather);
  const std::vector<weather::TimeStep> steps = clock.steps(weather.records);
  const SolarPositionOptions solar = solar_options_for(weather, options);
  std::vector<double> below(steps.size(), 0.0);
  for (std::size_t t = 0; t < steps.size(); ++t) {
    const double dni = weather.records[t].direct_normal_w_m2.value_or(0.0);
    if (dni > 0 && direct_below_horizon(dni, record_sun(site, clock, steps[t], solar))) below[t] = dni;
  }
  return tally_below_horizon(below, weather);
}

SkyMatrix build_sky_matrix(const weather::HourlyWeather& weather, const SolarSite& site, const PatchBasis& basis,
                           const SkyMatrixOptions& options) {
  require_file_clock(weather, site);
  const weather::SiteClock clock = weather::SiteClock::for_weather(weather);
  const std::vector<weather::TimeStep> steps = clock.steps(weather.records);
  const std::size_t n_steps = steps.size();
  const int n_bins = basis.bin_count();

  // Missing irradiance makes a daytime sky impossible: report every such record, located.
  Diagnostics diagnostics;
  for (const weather::WeatherRecord& r : weather.records) {
    for (const weather::WeatherValue v :
         {weather::WeatherValue::DirectNormalIrradiance, weather::WeatherValue::DiffuseHorizontalIrradiance})
      if (!(v == weather::WeatherValue::DirectNormalIrradiance ? r.direct_normal_w_m2 : r.diffuse_horizontal_w_m2))
        diagnostics.error(weather::weather_value_location(weather, r, v),
                          weather::weather_value_name(weather, v) + " is missing; the sky needs it");
  }
  diagnostics.throw_if_errors();

  // Reinhart MF n patches are n times smaller per axis than Tregenza's: keep the sample
  // spacing (not the count) per patch, at least 2 x 2.
  const int samples_per_axis =
      std::max(2, (options.mean_samples_per_axis + basis.multiplication_factor() - 1) / basis.multiplication_factor());
  const SolarPositionOptions solar = solar_options_for(weather, options);

  SkyMatrix result;
  result.matrix = RadianceMatrix(static_cast<std::size_t>(n_bins), n_steps, 3);
  const int quadrant_samples = quadrant_samples_of(basis);
  if (options.quadrant_deltas)
    result.quadrant_deltas =
        RadianceMatrix(static_cast<std::size_t>(PatchBasis::QuadrantCount * n_bins), n_steps, 1);
  const double colour_luminance = dot(RgbLuminanceWeights, options.sky_colour);
  std::vector<double> quadrant_projected_solid_angle(options.quadrant_deltas ? PatchBasis::QuadrantCount * n_bins : 0);
  for (int bin = 1; bin < n_bins && options.quadrant_deltas; ++bin)
    for (int q = 0; q < PatchBasis::QuadrantCount; ++q)
      quadrant_projected_solid_angle[static_cast<std::size_t>(PatchBasis::QuadrantCount * bin + q)] =
          quadrant_projected_solid_angle_sr(basis, bin, q);
  std::vector<std::optional<SunRecord>> suns(n_steps);
  std::vector<double> below_horizon_W_m2(n_steps, 0.0);  // direct normal of records below the horizon

  // Patch centres and projected solid angles, shared by every step.
  std::vector<double> centre_zenith(n_bins), centre_weight(n_bins), projected_solid_angle(n_bins);
  for (int bin = 1; bin < n_bins; ++bin) {
    projected_solid_angle[bin] = projected_solid_angle_sr(basis, bin);
    const Vec3 c = basis.centre(bin);
    centre_zenith[bin] = std::acos(std::clamp(c.z, -1.0, 1.0));
    centre_weight[bin] = c.z * basis.solid_angle_sr(bin);  // sin(h) Omega, gendaymtx's divisor
  }

  tbb::parallel_for(std::size_t(0), n_steps, [&](std::size_t t) {
    const weather::WeatherRecord& record = weather.records[t];
    const weather::TimeStep& step = steps[t];
    const double dni = *record.direct_normal_w_m2;
    const double dhi = *record.diffuse_horizontal_w_m2;
    if (dni + dhi <= 1e-4) return;  // night: the whole column stays zero (gendaymtx)

    const SolarPosition sun = record_sun(site, clock, step, solar);
    if (direct_below_horizon(dni, sun)) below_horizon_W_m2[t] = dni;
    PerezInputs inputs;
    inputs.direct_normal_irradiance_W_m2 = dni;
    inputs.diffuse_horizontal_irradiance_W_m2 = dhi;
    inputs.sun_direction = sun.direction;
    inputs.day_of_year = options.radiance_day_of_year
                             ? radiance_day_of_year(step.month, step.day, weather.leap_day_present)
                             : step.day_of_year;
    if (options.dew_point_from_weather && record.dew_point_c) inputs.dew_point_C = *record.dew_point_c;

    const PerezState state = perez_state(inputs);
    const double sun_lux_normal = state.direct_normal_illuminance_lux;
    const bool with_sky = options.sun != SunInMatrix::Only;
    double sky_horizontal_lux = 0;

    // Relative luminance lv of the Perez shape along d.
    auto lv_at = [&](const Vec3& d) {
      const double gamma = std::acos(std::clamp(dot(d, state.model_sun_direction), -1.0, 1.0));
      return perez_relative_luminance(state, std::acos(std::clamp(d.z, -1.0, 1.0)), gamma);
    };
    // The patch values (grey, W/(sr m^2)) for the quadrant deltas.
    std::vector<double> patch_radiance(options.quadrant_deltas ? n_bins : 0, 0.0);
    bool uniform_sky = false;
    auto set_deltas = [&](int bin, double value, double factor) {
      if (options.quadrant_deltas) patch_radiance[static_cast<std::size_t>(bin)] = value * factor;
    };
    if (with_sky) {
      if (options.patch_value == PatchValue::Centre) {
        std::vector<double> lv(n_bins, 0.0);
        double s = 0;
        for (int bin = 1; bin < n_bins; ++bin) {
          const double gamma = std::acos(std::clamp(dot(basis.centre(bin), state.model_sun_direction), -1.0, 1.0));
          lv[bin] = perez_relative_luminance(state, centre_zenith[bin], gamma);
          s += lv[bin] * centre_weight[bin];
        }
        uniform_sky = s <= 1e-9;
        if (uniform_sky) {  // lv vanished everywhere: uniform sky, as gendaymtx
          std::fill(lv.begin() + 1, lv.end(), 1.0);
          s = Pi;
        }
        sky_horizontal_lux = state.diffuse_horizontal_illuminance_lux;
        for (int bin = 1; bin < n_bins; ++bin) {
          const double value = lv[bin] * sky_horizontal_lux / (s * RadianceWhiteEfficacy_lm_per_W);
          set_rgb(result.matrix, bin, t, options.sky_colour * value);
          set_deltas(bin, lv[bin], sky_horizontal_lux / (s * RadianceWhiteEfficacy_lm_per_W));
        }
      } else {
        // The continuous Perez shape lv, averaged over each patch; normalised below.
        sky_horizontal_lux = state.diffuse_horizontal_illuminance_lux;
        const int n = samples_per_axis;
        std::vector<double> luminance(n_bins, 0.0);
        double horizontal = 0;
        for (int bin = 1; bin < n_bins; ++bin) {
          luminance[bin] = bin_mean(basis, bin, n, lv_at);
          horizontal += luminance[bin] * projected_solid_angle[bin];
        }
        uniform_sky = horizontal <= 1e-9;
        if (uniform_sky) {  // lv vanished everywhere: uniform sky, as gendaymtx
          std::fill(luminance.begin() + 1, luminance.end(), 1.0);
          horizontal = Pi;
        }
        // A patch mean times the patch's projected solid angle is not the patch's horizontal
        // illuminance when L varies with altitude inside the patch (low suns, horizon bands:
        // up to a few % for Tregenza). Rescale so that the discrete sky reproduces the measured
        // diffuse horizontal illuminance exactly, as gendaymtx's discrete normalisation does.
        const double scale = horizontal > 0 ? sky_horizontal_lux / horizontal : 0.0;
        for (int bin = 1; bin < n_bins; ++bin) {
          set_rgb(result.matrix, bin, t,
                  options.sky_colour * (scale * luminance[bin] / RadianceWhiteEfficacy_lm_per_W));
          set_deltas(bin, luminance[bin], scale / RadianceWhiteEfficacy_lm_per_W);
        }
      }
      if (options.quadrant_deltas && !uniform_sky) {
        // The quadrants' means of the Perez shape, normalised as the sky of quadrants they make
        // keeps the measured diffuse horizontal illuminance (the Mean mode's rule, on
        // quadrants; gendaymtx's discrete normalisation of the centre values misses it by
        // up to a percent), less the patch values.
        std::vector<std::array<double, PatchBasis::QuadrantCount>> mean(static_cast<std::size_t>(n_bins));
        double horizontal_q = 0;
        for (int bin = 1; bin < n_bins; ++bin) {
          mean[static_cast<std::size_t>(bin)] = quadrant_means(basis, bin, quadrant_samples, lv_at);
          for (int q = 0; q < PatchBasis::QuadrantCount; ++q)
            horizontal_q += mean[static_cast<std::size_t>(bin)][static_cast<std::size_t>(q)] *
                            quadrant_projected_solid_angle[static_cast<std::size_t>(PatchBasis::QuadrantCount * bin + q)];
        }
        const double to_radiance =
            horizontal_q > 0 ? sky_horizontal_lux / (horizontal_q * RadianceWhiteEfficacy_lm_per_W) : 0.0;
        for (int bin = 1; bin < n_bins; ++bin)
          for (int q = 0; q < PatchBasis::QuadrantCount; ++q)
            result.quadrant_deltas.at(static_cast<std::size_t>(PatchBasis::QuadrantCount * bin + q), t, 0) =
                static_cast<float>(colour_luminance * (to_radiance * mean[static_cast<std::size_t>(bin)][static_cast<std::size_t>(q)] -
                                                       patch_radiance[static_cast<std::size_t>(bin)]));
      }
      const Vec3 ground = ground_radiance_rgb(Vec3{1, 1, 1} * options.ground_reflectance, sky_horizontal_lux,
                                              sun_lux_normal, sun.direction);
      set_rgb(result.matrix, 0, t, ground);
    }

    if (sun_lux_normal > 0) {
      if (options.sun != SunInMatrix::None) spread_sun(basis, sun.direction, sun_lux_normal, result.matrix, t);
      if (sun.direction.z > 0) {
        suns[t] = sun_record(t, sun.direction, sun_lux_normal);
      }
    }
  });

  for (const auto& s : suns)
    if (s) result.suns.push_back(*s);
  result.below_horizon_direct = tally_below_horizon(below_horizon_W_m2, weather);
  return result;
}

std::vector<SunRecord> daytime_sun_positions(const weather::HourlyWeather& weather, const SolarSite& site,
                                             const SkyMatrixOptions& options) {
  require_file_clock(weather, site);
  const weather::SiteClock clock = weather::SiteClock::for_weather(weather);
  const std::vector<weather::TimeStep> steps = clock.steps(weather.records);
  const SolarPositionOptions solar = solar_options_for(weather, options);
  std::vector<SunRecord> suns;
  for (std::size_t t = 0; t < steps.size(); ++t) {
    const SolarPosition sun = record_sun(site, clock, steps[t], solar);
    if (sun.direction.z > 0) suns.push_back(sun_record(t, sun.direction, 0.0));
  }
  return suns;
}

double sun_disc_solid_angle_sr() { return SunDiscSolidAngle_sr; }

SpreadSunPatches spread_sun_patches(const PatchBasis& basis, const Vec3& sun) {
  constexpr int N = SpreadSunPatches::Count;
  SpreadSunPatches r;
  std::array<double, N> best_cos{};
  r.bin.fill(-1);
  best_cos.fill(-2.0);
  for (int bin = 1; bin < basis.bin_count(); ++bin) {
    const double c = dot(basis.centre(bin), sun);
    for (int k = 0; k < N; ++k)
      if (c > best_cos[k]) {
        for (int j = N - 1; j > k; --j) {
          r.bin[j] = r.bin[j - 1];
          best_cos[j] = best_cos[j - 1];
        }
        r.bin[k] = bin;
        best_cos[k] = c;
        break;
      }
  }
  double weight_sum = 0;
  for (int k = 0; k < N; ++k) weight_sum += 1.0 / (1.002 - best_cos[k]);
  for (int k = 0; k < N; ++k) r.weight[k] = 1.0 / (1.002 - best_cos[k]) / weight_sum;
  return r;
}

SunRecord sun_record(std::size_t step, const Vec3& direction, double direct_normal_illuminance_lux) {
  SunRecord r;
  r.step = step;
  r.direction = direction;
  r.direct_normal_illuminance_lux = direct_normal_illuminance_lux;
  r.disc_radiance = direct_normal_illuminance_lux / (RadianceWhiteEfficacy_lm_per_W * SunDiscSolidAngle_sr);
  return r;
}

RadianceMatrix sky_vector(const SkyModel& sky, const PatchBasis& basis, const Vec3& ground_radiance,
                          PatchValue patch_value, int mean_samples_per_axis) {
  RadianceMatrix m(static_cast<std::size_t>(basis.bin_count()), 1, 3);
  set_rgb(m, 0, 0, ground_radiance);
  std::vector<Vec3> values(basis.bin_count());
  double horizontal = 0;
  for (int bin = 1; bin < basis.bin_count(); ++bin) {
    if (patch_value == PatchValue::Centre) {
      values[bin] = sky.radiance_rgb(basis.centre(bin));
      horizontal += rgb_to_photometric(values[bin]) * basis.centre(bin).z * basis.solid_angle_sr(bin);
    } else {
      const int n = mean_samples_per_axis;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) values[bin] += sky.radiance_rgb(basis.sample_direction(bin, (i + 0.5) / n, (j + 0.5) / n));
      values[bin] = values[bin] / double(n * n);
      horizontal += rgb_to_photometric(values[bin]) * projected_solid_angle_sr(basis, bin);
    }
  }
  // Same discrete normalisation as the annual matrices: the vector keeps the sky's horizontal
  // illuminance exactly (Centre: gendaymtx's sin(h) Omega weights; Mean: projected solid angles).
  const double target = sky.horizontal_illuminance_lux();
  const double scale = horizontal > 0 ? target / horizontal : 0.0;
  for (int bin = 1; bin < basis.bin_count(); ++bin) set_rgb(m, bin, 0, values[bin] * scale);
  return m;
}

RadianceMatrix sky_vector_quadrant_deltas(const SkyModel& sky, const PatchBasis& basis, const RadianceMatrix& vector) {
  const int n_bins = basis.bin_count();
  if (vector.rows() != static_cast<std::size_t>(n_bins) || vector.columns() != 1 || vector.components() != 3)
    throw std::invalid_argument("sky vector quadrant deltas: a vector of " + std::to_string(vector.rows()) + " x " +
                                std::to_string(vector.columns()) + " x " + std::to_string(vector.components()) +
                                " for " + std::to_string(n_bins) + " bins x 1 x 3");
  RadianceMatrix deltas(static_cast<std::size_t>(PatchBasis::QuadrantCount * n_bins), 1, 1);
  // The quadrants' means of the sky's luminance, normalised as the sky of quadrants they make
  // keeps the sky's horizontal illuminance (as sky_vector's bin means and build_sky_matrix's
  // quadrant deltas are), less the vector's bin values.
  const int n = quadrant_samples_of(basis);
  auto luminance_at = [&sky](const Vec3& d) { return dot(RgbLuminanceWeights, sky.radiance_rgb(d)); };
  std::vector<std::array<double, PatchBasis::QuadrantCount>> mean(static_cast<std::size_t>(n_bins));
  double horizontal = 0;
  for (int bin = 1; bin < n_bins; ++bin) {
    mean[static_cast<std::size_t>(bin)] = quadrant_means(basis, bin, n, luminance_at);
    for (int q = 0; q < PatchBasis::QuadrantCount; ++q)
      horizontal += RadianceWhiteEfficacy_lm_per_W * mean[static_cast<std::size_t>(bin)][static_cast<std::size_t>(q)] *
                    quadrant_projected_solid_angle_sr(basis, bin, q);
  }
  const double scale = horizontal > 0 ? sky.horizontal_illuminance_lux() / horizontal : 0.0;
  for (int bin = 1; bin < n_bins; ++bin) {
    const double value = dot(RgbLuminanceWeights, Vec3{vector.at(bin, 0, 0), vector.at(bin, 0, 1), vector.at(bin, 0, 2)});
    for (int q = 0; q < PatchBasis::QuadrantCount; ++q)
      deltas.at(static_cast<std::size_t>(PatchBasis::QuadrantCount * bin + q), 0, 0) =
          static_cast<float>(scale * mean[static_cast<std::size_t>(bin)][static_cast<std::size_t>(q)] - value);
  }
  return deltas;
}

double column_horizontal_illuminance_lux(const RadianceMatrix& matrix, std::size_t column,
                                         const PatchBasis& basis) {
  double e = 0;
  for (int bin = 1; bin < basis.bin_count(); ++bin) {
    const Vec3 rgb{matrix.at(bin, column, 0), matrix.at(bin, column, 1), matrix.at(bin, column, 2)};
    e += rgb_to_photometric(rgb) * projected_solid_angle_sr(basis, bin);
  }
  return e;
}

}  // namespace dayphoton::sky
