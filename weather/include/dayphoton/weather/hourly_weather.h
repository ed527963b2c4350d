// HourlyWeather: the format-neutral hourly series the annual pipeline reads (sky matrix, sun,
// time stamps, daylight hours), whatever file it came from: an EPW file or a RADIANCE/DAYSIM
// .wea file. The sky and the study never see EpwFile or WeaFile.
//
// What a series guarantees (docs/weather.md):
//  - `records` run hour by hour, in time order, without gaps or duplicates, from the first
//    record's hour; each record's hour h (1..24) covers (h-1, h] local standard time of
//    `site.time_zone_h`.
//  - Every record has its direct normal and diffuse horizontal irradiance (W/m^2). A missing
//    value in the file is filled by the fill rule below, or the series is not built (a located
//    InputError).
//  - `leap_day_present`: the records include Feb 29 (366-day calendar, SiteClock).
//
// Fill rule for missing direct normal / diffuse horizontal irradiance (EPW missing code 9999
// or an empty field): a run of at most MaxInterpolatedGap_h consecutive missing hours is
// filled by linear interpolation in time between the valid hours on either side (the one
// valid neighbour's value if the run touches the start or the end of the file), each filled
// value counted and the first few located in `warnings`; a longer run is an error located at
// its first record. Other fields stay std::nullopt when missing; their consumers decide
// (the Perez dew point falls back to its default, the daylight-hours quantity to irradiance).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/source_location.h"
#include "dayphoton/weather/weather_record.h"
#include "dayphoton/weather/weather_site.h"

namespace dayphoton::weather {

struct EpwFile;
struct WeaFile;

/// The longest run of consecutive missing hours of a used irradiance that is interpolated.
/// Two hours: the sun's elevation changes by up to 30 degrees in two hours, so the straight
/// line between the hours either side still follows the day's course; over three or more
/// hours it can cut across sunrise, noon or a passing front, and the values the sky would get
/// are invented rather than interpolated, so the file is refused instead.
constexpr int MaxInterpolatedGap_h = 2;

/// How many filled values are located one by one in the warnings (the rest are counted).
constexpr std::size_t MaxLocatedFilledValues = 10;

enum class WeatherFormat { Epw, Wea };

/// The values of a record the pipeline may have to locate in its file.
enum class WeatherValue { DirectNormalIrradiance, DiffuseHorizontalIrradiance };

struct HourlyWeather {
  std::string source_name;  ///< path or display name used in diagnostics
  WeatherFormat format = WeatherFormat::Epw;
  WeatherSite site;
  std::vector<WeatherRecord> records;  ///< hourly, in time order (see above)
  bool leap_day_present = false;       ///< the records include Feb 29 (366-day calendar)
  /// EPW DATA PERIODS: the first day of the period and its weekday as written ("Sunday");
  /// a .wea file has none (start_weekday empty): a weekly occupancy then needs the weekday of
  /// 1 January from the project.
  int start_month = 1, start_day = 1;
  std::string start_weekday;
  std::vector<Diagnostic> warnings;    ///< the file reader's warnings, then the fill rule's
  std::size_t filled_values = 0;       ///< missing irradiance values filled by interpolation
};

/// Where `value` of `record` is in its file: file:line:field for EPW (field 15 or 16),
/// file:line for .wea (whose columns are character positions, not kept per record).
SourceLocation weather_value_location(const HourlyWeather& weather, const WeatherRecord& record,
                                      WeatherValue value);

/// "field 15 (direct normal radiation)" for EPW, "direct normal irradiance (column 4)" for .wea.
std::string weather_value_name(const HourlyWeather& weather, WeatherValue value);

/// The series of an EPW file: its LOCATION site, its records, its warnings, with the fill
/// rule applied. Throws InputError (located) for runs of missing irradiance too long to fill.
HourlyWeather hourly_weather_from_epw(const EpwFile& epw);

/// The series of a .wea file (units 1: direct normal and diffuse horizontal irradiance). The
/// site comes from the header (west-positive longitude and meridian converted to east
/// positive; place "<city>_<country>" split at its last underscore). Each data line must be
/// the mid-hour time stamp h - 0.5 of an hour h in 1..24 (what epw2wea writes), the lines
/// consecutive hours; units 2 and 3 are refused (the sky needs direct normal irradiance).
/// Throws InputError located at the line (and character column) of each problem.
HourlyWeather hourly_weather_from_wea(const WeaFile& wea);

/// Read a weather file by its extension: ".wea" (any case) as .wea, anything else as EPW.
/// Throws InputError for bad content, std::runtime_error if the file cannot be opened.
HourlyWeather read_hourly_weather(const std::string& path);

/// True if `path` names a .wea file (extension ".wea", any case).
bool is_wea_path(const std::string& path);

}  // namespace dayphoton::weather
