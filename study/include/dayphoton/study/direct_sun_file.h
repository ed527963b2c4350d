// The exact direct sun of a grid as `dayphoton run` exports it for `dayphoton annual`
// (direct_sun.bin.gz in each grid folder of a sun-bins run; docs/outputs.md "direct_sun.bin.gz").
//
// What it holds: for every sun position of the run's weather file with the sun centre above
// the horizon (sky::daytime_sun_positions, at the run's site; not only the hours with direct
// light in that file, so that another weather file of the same site and clock finds every
// sun it needs), and every sensor, the direct-sun illuminance per unit disc radiance,
//   e[s][k] = 179 (0.265, 0.670, 0.065) . C_direct(sun_k)[s]     lx per W/(sr m^2),
// C_direct from study::direct_sun_coefficients (0.533 deg disc, stratified shadow rays through
// the glazing). The hour's direct illuminance is then e[s][k] L_k, L_k the disc radiance of
// that hour's sun (direct_sun_table computes exactly this, in double, from the same e).
//
// Layout (all of it gzip-compressed by zlib; little-endian numbers):
//   text header lines "key=value", ended by an empty line:
//     "dayphoton direct sun" (first line), version=1, sensors=N, suns=K, sun_bins_mf=M,
//     seed, samples, quantity, site (latitude, longitude, time zone, elevation), weather;
//   K sun records of 16 bytes: uint32 step (the record's index in the run's weather file),
//     float32 x, y, z (toward the sun, as the run used it: rounded to float);
//   per sensor: ceil(K / 8) bytes of a bit mask (bit k % 8 of byte k / 8 set: e[s][k] > 0),
//     then one float64 per set bit, in sun order.
// So a sensor costs ceil(K / 8) + 8 x (suns that reach it) bytes before compression: with
// 4,4 thousand daytime records about 550 bytes plus 8 per sunlit hour.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/core/resource_limits.h"
#include "dayphoton/core/vec3.h"
#include "dayphoton/sky/sky_matrix.h"

namespace dayphoton::study {

/// File name of the export in a grid folder.
inline constexpr const char* DirectSunFileName = "direct_sun.bin.gz";

/// The direct sun of one grid, sparse by sensor (compressed rows).
struct DirectSunExport {
  std::size_t sensors = 0;
  std::vector<std::uint32_t> steps;  ///< per sun: record index in the run's weather file
  std::vector<Vec3> directions;      ///< per sun: unit, toward the sun (float values, normalised)
  int sun_bins_mf = 0;               ///< Reinhart MF of sun_bins.csv's patches
  std::uint64_t seed = 0;            ///< the run's seed of the shadow rays
  int samples = 0;                   ///< shadow rays per sun and sensor
  std::string site;                  ///< the site sentence of the run (informational)
  std::string weather;               ///< the run's weather file (informational)
  /// Compressed rows: sensor s owns entries row_start[s] .. row_start[s + 1] - 1.
  std::vector<std::size_t> row_start;
  std::vector<std::uint32_t> sun;    ///< per entry: sun index
  std::vector<double> lux;           ///< per entry: e[s][sun] > 0, lx per W/(sr m^2)

  std::size_t sun_count() const { return steps.size(); }
};

/// e[s][k] of `direct` (sensors x suns x RGB, or x 1 luminance component: direct_sun_coefficients
/// for `suns`) summed as
/// direct_sun_table sums it, merged over several sets of suns and ordered by step. Every
/// set's matrix must have the same rows; a step given twice is std::invalid_argument.
struct DirectSunPart {
  const RadianceMatrix* direct = nullptr;
  const std::vector<sky::SunRecord>* suns = nullptr;
};
DirectSunExport make_direct_sun_export(const std::vector<DirectSunPart>& parts);

/// The daytime sun positions of `weather` at `site` (sky::daytime_sun_positions with the
/// options' solar algorithm) whose step is not among `lit` (the suns with direct light, which
/// the run traces anyway), rounded through float as suns_to_matrix stores suns: the further
/// suns whose direct sun the export holds.
std::vector<sky::SunRecord> daytime_suns_without_direct(const weather::HourlyWeather& weather,
                                                        const sky::SolarSite& site,
                                                        const sky::SkyMatrixOptions& options,
                                                        const std::vector<sky::SunRecord>& lit);

/// Write `e` as direct_sun.bin.gz (the layout above), atomically.
void write_direct_sun_file(const DirectSunExport& e, const std::string& path);

/// Read a direct_sun.bin.gz; InputError naming the file for anything malformed (a wrong
/// first line or version, missing keys, counts out of range, a short or corrupt stream, a
/// value that is not finite and positive), and for more than `max_decompressed_bytes`.
DirectSunExport read_direct_sun_file(const std::string& path,
                                     std::uint64_t max_decompressed_bytes = ResourceLimits{}.decompressed_bytes);

}  // namespace dayphoton::study
