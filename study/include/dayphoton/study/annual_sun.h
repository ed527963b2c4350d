// Annual sun with sun bins (issue 6 item 1; DESIGN.md section 5): the `sun: bins` mode of
// `dayphoton run`, in which the sun is not spread into sky patches but treated as what it is,
// a 0.533 degree disc of known radiance in a known direction every hour.
//
//   E[t][s] = sky coefficients x sky matrix WITHOUT the sun (gendaymtx -s conventions)
//           + direct sun  : traced EXACTLY for the hour's sun at every sensor (stratified
//                           shadow rays over the disc through the glazing), x disc radiance
//           + indirect sun: caustic + global photon coefficients of the sun bins
//                           (engine/sun_bins.h) interpolated to the hour's sun, x disc radiance
//
// The direct part alone is the direct-sun-only, zero-bounce illuminance that LM-83 defines ASE
// with (IES LM-83-12 section 2.2: direct sunlight only, no inter-reflection, blinds open), so
// ASE1000,250 comes from it (metrics::ase_hours_per_sensor).
//
// Units: the sun records' disc radiance L is in RADIANCE "visible" W/(sr m^2) (luminance /
// 179, grey), so that 179 L Omega_sun is the direct normal illuminance of the hour; every
// coefficient here is RGB irradiance W/m^2 per unit disc radiance, and illuminance is
// 179 (0.265 R + 0.670 G + 0.065 B) as everywhere else (docs/outputs.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/port_emission.h"
#include "dayphoton/engine/receiver_plane.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/engine/sensor_range.h"
#include "dayphoton/engine/sun_bins.h"
#include "dayphoton/metrics/illuminance_table.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/study/annual_study.h"
#include "dayphoton/study/plan_policy.h"
#include "dayphoton/study/sparse_sun_rows.h"
#include "dayphoton/weather/hourly_weather.h"

namespace dayphoton::study {

/// Which bins of `emitter` (built on SunBins::sources) to trace under the rule of
/// SunBinMinimumBoundFraction (plan_policy.h).
std::vector<char> sun_bins_to_trace(const engine::PortEmitter& emitter, std::size_t bins);

/// The forward pass of sun bin `bin` ALONE: a set of one disc at its centre, traced with the
/// seed sun_bin_seed(options.seed, mf, patch), photons labelled source 0. Its photons
/// therefore depend on the bin's patch, not on its index among this year's bins, so they
/// can be cached per patch and shared by weather files with other sun hours.
engine::TracedPhotons trace_sun_bin(const engine::Scene& scene,
                                    const std::vector<engine::Material>& materials,
                                    const engine::SunBins& bins, std::size_t bin,
                                    const std::vector<engine::ReceiverPlane>& planes,
                                    const engine::TracingOptions& options);

/// What trace_sun_bin traces: the set of bin `bin`'s one disc, and the options with the
/// bin's seed and no per-source factors.
engine::SourceSet sun_bin_source(const engine::SunBins& bins, std::size_t bin);
engine::TracingOptions sun_bin_tracing(const engine::TracingOptions& options, const engine::SunBins& bins,
                                       std::size_t bin);

/// The seed of a sun bin's photons: SplitMix64-mixed (seed, mf, patch).
std::uint64_t sun_bin_seed(std::uint64_t seed, int mf, int patch);

/// Set the source of every photon to `source` (a bin's photons traced alone are source 0;
/// in a grid's photon maps bin i must be source i).
void relabel_photons(engine::TracedPhotons& photons, std::uint32_t source);

/// trace_sun_bin for every bin to trace (parallel over bins), labelled with their bin index;
/// skipped bins give no photons and a zero tally. The layout of engine::trace_photons. For
/// tests and benches: the pipeline caches each bin's photons itself (sun_bin_steps.cpp).
engine::TracedPhotons trace_sun_bins(const engine::Scene& scene,
                                     const std::vector<engine::Material>& materials,
                                     const engine::SunBins& bins,
                                     const std::vector<engine::ReceiverPlane>& planes,
                                     const engine::TracingOptions& options);

/// The sun bins' bandwidth for a project bandwidth (SunBinBandwidthFraction, plan_policy.h).
std::size_t sun_bin_bandwidth(std::size_t bandwidth);

/// The annual sky without the sun and the hourly suns that go with it.
struct SkyAndSuns {
  AnnualSky sky;                     ///< sky and ground only (SunInMatrix::None)
  std::vector<sky::SunRecord> suns;  ///< steps with the sun above the horizon and direct light
};

/// The RADIANCE-compatible options (radiance_compatible_sky_options) with the sun left out
/// of the matrix, as gendaymtx -s: the sky of the sun-bins mode.
sky::SkyMatrixOptions sun_excluded_sky_options(double ground_reflectance = 0.2);

/// SkyAndSuns::sky.description of annual_sky_and_suns (the same whether built or cached).
std::string sky_and_suns_description(const weather::HourlyWeather& weather, const sky::PatchBasis& basis);

/// Sky-only matrix and suns of a weather file for the sun of `site` (study/sun_site.h;
/// build_sky_matrix with options.sun = None is enforced). The suns are rounded through float exactly as suns_to_matrix stores them, so a
/// run that reads them back from the cache computes the same numbers.
SkyAndSuns annual_sky_and_suns(const weather::HourlyWeather& weather, const sky::SolarSite& site,
                               const sky::PatchBasis& basis, sky::SkyMatrixOptions options);

/// Suns as a matrix for the cache: one row per sun, 6 columns of 1 component: step,
/// direction x, y, z, direct normal illuminance (lux), disc radiance. And back (throws
/// std::runtime_error on a wrong shape or a non-finite value).
RadianceMatrix suns_to_matrix(const std::vector<sky::SunRecord>& suns);
std::vector<sky::SunRecord> suns_from_matrix(const RadianceMatrix& m);

/// Exact direct sun per unit disc radiance: sensors x suns x RGB, W/m^2 per W/(sr m^2):
/// integral over the hour's disc of T(w) max(0, w . n) dw by `samples` stratified shadow
/// rays (engine::sky_transmittance: straight through the glazing up to the first port,
/// anything else blocks), the disc sampled as engine::SourceSet does. Sensor s of sun k uses
/// Rng(seed, step of sun k, s, Direct), so a sun's numbers do not depend on the other suns.
/// Parallel over sensors, the same for any thread count. `rows`: only those sensors' rows
/// (engine/sensor_range.h; s is the index in the whole of `sensors`). With DirectSunValues::Luminance one
/// component per sun instead of three: (0.265 R + 0.670 G + 0.065 B) of the same sums, the
/// quantity every illuminance is made of (weight 179 as a one-component matrix), in a third of
/// the memory (what the pipeline keeps for a grid's hourly suns; docs/photon-tracing.md "Scale").
/// `variance`, if given, receives the Monte Carlo variance of each value's luminance (rows x
/// suns, per unit disc radiance squared; engine/estimate_variance.h): the k x k strata of the
/// disc, one ray each, by engine::StratifiedVariance (collapsed strata, second differences
/// along each row of k). It is zero wherever the disc is wholly seen or wholly hidden (every
/// ray the same), and counts the penumbra, where a frame or a shading edge crosses the disc.
enum class DirectSunValues { Rgb, Luminance };
RadianceMatrix direct_sun_coefficients(const engine::Scene& scene,
                                       const std::vector<engine::Material>& materials,
                                       const std::vector<SensorPoint>& sensors,
                                       const std::vector<sky::SunRecord>& suns,
                                       int samples = SunDirectSamples, std::uint64_t seed = 1,
                                       DirectSunValues values = DirectSunValues::Rgb,
                                       engine::SensorRange rows = {}, std::vector<double>* variance = nullptr);

/// Photon part (caustic + global) of the sun-bin coefficients at `sensors`: sensors x bins x
/// RGB, W/m^2 per unit disc radiance (what coefficients_sun.mtx holds). `photons` are the
/// sun bins' photons, source i = bin i = sources[i] (the discs, for a final gather's
/// specular paths; engine::photon_coefficients). `variance`, if given, receives each entry's
/// variance (sensors x bins, engine/estimate_variance.h). `rows`: only those sensors' rows.
/// Receiver-plane estimates are made a
/// block of sensors at a time (SunCoefficientBlockValues), with the same values.
/// A block's double-precision parts (two RGB parts and a variance, 56 bytes a value) are
/// 56 MiB at SunCoefficientBlockValues (2^18 cost the open-plan bench's sun step +29 % CPU:
/// each block's tasks start their lookups without a hint; docs/photon-tracing.md "Scale").
constexpr std::size_t SunCoefficientBlockValues = std::size_t(1) << 20;
RadianceMatrix sun_bin_coefficients(const engine::Scene& scene,
                                    const std::vector<engine::Material>& materials,
                                    const engine::SourceSet& sources,
                                    const engine::GridPhotons& photons,
                                    const std::vector<SensorPoint>& sensors,
                                    const engine::CoefficientOptions& options,
                                    std::vector<double>* variance = nullptr,
                                    engine::SensorRange rows = {},
                                    std::size_t block_values = SunCoefficientBlockValues);
/// The same, each variance rounded to single precision as it is made (what the cache and the
/// verdicts keep: no sensors x bins doubles held).
RadianceMatrix sun_bin_coefficients(const engine::Scene& scene, const std::vector<engine::Material>& materials,
                                    const engine::SourceSet& sources, const engine::GridPhotons& photons,
                                    const std::vector<SensorPoint>& sensors, const engine::CoefficientOptions& options,
                                    std::vector<float>* variance, engine::SensorRange rows = {},
                                    std::size_t block_values = SunCoefficientBlockValues);

/// Direct-sun illuminance (lux), steps x sensors: 179 w . C_direct[s][k] L_k for each sun k
/// at its step, 0 at every other step. `direct` from direct_sun_coefficients.
metrics::IlluminanceTable direct_sun_table(const RadianceMatrix& direct,
                                           const std::vector<sky::SunRecord>& suns,
                                           const std::vector<metrics::TimeStamp>& steps);

/// Indirect-sun illuminance (lux), steps x sensors: 179 w . sum_j w_j C_sun[s][bin_j] L_k
/// with the interpolation weights of bins.weights(sun k). `bin_coefficients` from
/// sun_bin_coefficients (columns = bins).
metrics::IlluminanceTable indirect_sun_table(const RadianceMatrix& bin_coefficients,
                                             const engine::SunBins& bins,
                                             const std::vector<sky::SunRecord>& suns,
                                             const std::vector<metrics::TimeStamp>& steps);

/// The annual study of the sun-bins mode: illuminance = sky coefficients x sky-only matrix +
/// direct_sun + indirect_sun (summed in double, stored as float), every metric of
/// compute_annual_study on it, and ASE from `direct_sun` alone. Throws std::invalid_argument
/// on shape mismatches.
AnnualStudy compute_annual_study_with_sun(const RadianceMatrix& sky_coefficients,
                                          const AnnualSky& sky,
                                          const metrics::IlluminanceTable& direct_sun,
                                          const metrics::IlluminanceTable& indirect_sun,
                                          const AnnualStudySettings& settings,
                                          const SubPatchShares* shares = nullptr);

/// A grid's sun as the sun-bins mode computes it: the exact direct sun per unit disc radiance
/// (direct_sun_coefficients: sensors x suns) of the suns `suns`, and the sun bins'
/// coefficients (sun_bin_coefficients: sensors x bins) on `bins`.
struct GridSunCoefficients {
  const RadianceMatrix* direct = nullptr;
  const std::vector<sky::SunRecord>* suns = nullptr;
  const RadianceMatrix* bin_coefficients = nullptr;
  const engine::SunBins* bins = nullptr;
  /// The same direct sun held sparse (luminance form), used instead of `direct` where given
  /// (compute_annual_study_with_sun; the values and so the results are the same).
  const SparseSunRows* direct_rows = nullptr;
};

/// The same study as compute_annual_study_with_sun(sky_coefficients, sky,
/// direct_sun_table(...), indirect_sun_table(...), settings), value for value, with the sun
/// added in place: it holds one steps x sensors table, not three (docs/photon-tracing.md
/// "Scale"). Parallel over sensors. Throws std::invalid_argument on shape mismatches.
/// `shares`: the sky coefficients' sub-patch shares (compute_annual_study).
AnnualStudy compute_annual_study_with_sun(const RadianceMatrix& sky_coefficients, const AnnualSky& sky,
                                          const GridSunCoefficients& sun, const AnnualStudySettings& settings,
                                          const SubPatchShares* shares = nullptr);

/// sun_bins.csv (docs/outputs.md): `bin,patch,altitude_deg,azimuth_deg,x,y,z,hours`: the
/// column of coefficients_sun.mtx, the Reinhart patch, the centre direction, and the number
/// of hourly suns whose interpolation uses the bin. Atomic.
void write_sun_bins_csv(const engine::SunBins& bins, const std::vector<sky::SunRecord>& suns,
                        const std::string& path);

}  // namespace dayphoton::study
