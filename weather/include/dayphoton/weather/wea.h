// RADIANCE / DAYSIM .wea weather tapes: read, write, and convert from EPW.
//
// Format (facts/sky-and-metrics.md §6.2; RADIANCE epw2wea.c and the gendaymtx .wea parser):
//   place <city>_<country>
//   latitude <deg, north positive>
//   longitude <deg, WEST positive>          (= -EPW longitude)
//   time_zone <standard meridian, deg WEST positive>   (= -15 * EPW time zone)
//   site_elevation <m>
//   weather_data_file_units <1|2|3>
//   month day hour direct diffuse           (one line per time step)
// `hour` is decimal LOCAL STANDARD TIME of the interval midpoint (EPW hour 1 -> 0.5).
// Units 1: direct normal + diffuse horizontal irradiance (W/m^2); 2: direct horizontal +
// diffuse horizontal irradiance (W/m^2); 3: direct normal + diffuse horizontal illuminance
// (lux). The writer prints rows as epw2wea does ("%d %d %.3f %.0f %.0f").
// Sign conventions are converted here and only here: WeaHeader holds RADIANCE's west-positive
// values, EpwLocation holds east-positive ones.
#pragma once

#include <cstddef>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "dayphoton/weather/epw_reader.h"

namespace dayphoton::weather {

/// What the two data columns of a .wea file hold (header `weather_data_file_units`).
enum class WeaUnits {
  DirectNormalDiffuseHorizontalIrradiance = 1,     ///< W/m^2 (what epw2wea writes)
  DirectHorizontalDiffuseHorizontalIrradiance = 2, ///< W/m^2
  DirectNormalDiffuseHorizontalIlluminance = 3,    ///< lux
};

/// The six header lines, in RADIANCE's WEST-positive convention.
struct WeaHeader {
  std::string place;                 ///< e.g. "Oakland Metropolitan Arpt_USA"
  double latitude_deg = 0.0;         ///< north positive
  double longitude_west_deg = 0.0;   ///< WEST positive (122.22 for Oakland)
  double time_zone_west_deg = 0.0;   ///< standard meridian, WEST positive (120 for UTC-8)
  double site_elevation_m = 0.0;
  WeaUnits units = WeaUnits::DirectNormalDiffuseHorizontalIrradiance;
  int units_column = 0;  ///< 1-based character column of the units value on line 6 (0 if not read)
};

/// One data line.
struct WeaRecord {
  int month = 1;
  int day = 1;
  double hour_lst = 0.5;  ///< decimal local standard time of the midpoint, (0, 24]
  double direct = 0.0;    ///< W/m^2 or lux, see WeaUnits
  double diffuse = 0.0;   ///< W/m^2 or lux
  int source_line = 0;    ///< 1-based line in the source file (0 if not read)
  int hour_column = 0;    ///< 1-based character column of the hour on that line (0 if not read)
};

struct WeaFile {
  std::string source_name;  ///< path or display name used in diagnostics
  WeaHeader header;
  std::vector<WeaRecord> records;
};

/// Read and validate a .wea file. Errors are located file:line:column (1-based character
/// column of the offending token) and thrown together as dayphoton::InputError;
/// std::runtime_error if the file cannot be opened.
WeaFile read_wea(const std::string& path, std::size_t max_errors = 50);

/// Same, from a stream; `display_name` is used as the file name in diagnostics.
WeaFile read_wea(std::istream& in, const std::string& display_name, std::size_t max_errors = 50);

/// Write `wea` as text: header values with the fewest digits that read back exactly (at
/// least 2 decimals for latitude/longitude, 1 for elevation), rows "%d %d %.3f %.0f %.0f".
void write_wea(std::ostream& out, const WeaFile& wea);

/// Write to `path` atomically (core/atomic_file.h).
void write_wea_file(const std::string& path, const WeaFile& wea);

/// EPW -> .wea (units 1: DNI and DHI in W/m^2), as RADIANCE epw2wea does: place
/// "<city>_<country>", longitude and time zone negated/scaled to west-positive degrees
/// (half-hour zones are kept, not truncated), hour = EPW hour - 0.5, all records kept.
/// Throws dayphoton::InputError located at the EPW line and field (15 or 16) for every
/// record whose DNI or DHI is missing.
WeaFile epw_to_wea(const EpwFile& epw);

}  // namespace dayphoton::weather
