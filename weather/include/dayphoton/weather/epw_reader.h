// EPW (EnergyPlus weather) reader with validation.
//
// Format: EnergyPlus "Auxiliary Programs, EPW Data Dictionary" (ESP-r/EnergyPlus format,
// April 2002); field table, missing codes and semantics as summarised in
// facts/sky-and-metrics.md §6.3. Decisions (docs/weather.md):
//  - 8 header lines, keywords checked; LOCATION, HOLIDAYS/DAYLIGHT SAVINGS and DATA PERIODS
//    are parsed, the others only recognised.
//  - One data period, hourly data only (records per hour = 1). The records must run hour by
//    hour from the period's start date, hour 1, to its end date, hour 24 (8760 records for
//    1/1..12/31, 8784 with a leap day). Gaps, duplicates and out-of-order records are errors.
//  - Feb 29 records are kept. If the header says "LeapYear observed = No" but Feb 29 records
//    are present they are still kept, with a warning; "Yes" requires them.
//  - Minute field: 0 or 60 (both mean the whole hour); anything else is an error.
//  - Missing-value codes become std::nullopt (weather_record.h), never errors; an empty
//    numeric field is also missing. Values outside physical limits are errors.
//  - Only fields dayphoton uses (epw_field_is_used) can be errors; a bad value in another
//    field is ignored with a counted warning (EpwFile::ignored_value_count).
//  - DATA PERIODS dates may be M/D, M/D/YYYY or YYYY/M/D; a LOCATION line with more than 10
//    fields and an empty LeapYear field are warnings.
//  - Every problem is reported as file:LINE:FIELD (SourceLocation column = 1-based field
//    number) with "field N (name)" in the message; up to `max_errors` are collected and
//    thrown together as dayphoton::InputError. No input makes the reader crash.
#pragma once

#include <cstddef>
#include <istream>
#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/source_location.h"
#include "dayphoton/weather/weather_record.h"
#include "dayphoton/weather/weather_site.h"

namespace dayphoton::weather {

/// LOCATION line (header line 1): the site. Longitude and time zone are EAST positive, as in EPW.
using EpwLocation = WeatherSite;

/// DATA PERIODS line (header line 8); only one period is supported.
struct EpwDataPeriod {
  int records_per_hour = 1;
  std::string name;           ///< e.g. "Data"
  std::string start_weekday;  ///< e.g. "Sunday" (as written; not used for sky evaluation)
  int start_month = 1, start_day = 1;
  int end_month = 12, end_day = 31;
};

/// The parsed header.
struct EpwHeader {
  EpwLocation location;
  bool leap_year_observed = false;  ///< HOLIDAYS/DAYLIGHT SAVINGS field 2 ("Yes"; "No" or empty: false)
  std::string dst_start;            ///< as written ("0" = none); never applied (docs/weather.md)
  std::string dst_end;
  EpwDataPeriod data_period;
};

/// A whole EPW file: header, records in file order (= time order), warnings.
struct EpwFile {
  std::string source_name;             ///< path or display name used in diagnostics
  EpwHeader header;
  std::vector<WeatherRecord> records;  ///< one per hour, in time order
  bool leap_day_present = false;       ///< true if the records include Feb 29 (366-day calendar)
  std::vector<Diagnostic> warnings;    ///< non-fatal findings (e.g. undeclared leap day)
  /// Values of fields dayphoton does not use (epw_field_is_used) that were not numbers or out
  /// of range: ignored (read as missing) and counted, the first MaxLocatedIgnoredValues located
  /// in `warnings`, then one summary warning by field.
  std::size_t ignored_value_count = 0;
};

/// How many ignored values of unused fields are located one by one in EpwFile::warnings.
constexpr std::size_t MaxLocatedIgnoredValues = 10;

/// 1-based EPW field numbers (field 1 = year) of the values the sky and tools need.
namespace epw_field {
constexpr int Year = 1, Month = 2, Day = 3, Hour = 4, Minute = 5;
constexpr int DryBulb = 7, DewPoint = 8, RelativeHumidity = 9, Pressure = 10;
constexpr int GlobalHorizontalRadiation = 14, DirectNormalRadiation = 15,
              DiffuseHorizontalRadiation = 16;
constexpr int GlobalHorizontalIlluminance = 17, DirectNormalIlluminance = 18,
              DiffuseHorizontalIlluminance = 19, ZenithLuminance = 20;
constexpr int TotalSkyCover = 23;
constexpr int Count = 35;  ///< fields per data record
}  // namespace epw_field

/// True for the data fields dayphoton uses, whose broken values are errors: the date and time
/// (1-5), the dew point (8, Perez's precipitable water), direct normal and diffuse horizontal
/// irradiance (15, 16, the sky) and diffuse horizontal illuminance (19, the daylight-hours
/// quantity). A broken value in any other field is a counted warning and reads as missing.
bool epw_field_is_used(int field);

/// Read and validate an EPW file. Throws dayphoton::InputError (all collected problems,
/// formatted "path:line:field: error: ...") if anything is wrong, std::runtime_error if the
/// file cannot be opened. `max_errors` caps how many errors are kept.
EpwFile read_epw(const std::string& path, std::size_t max_errors = 50);

/// Same, from a stream; `display_name` is used as the file name in diagnostics.
EpwFile read_epw(std::istream& in, const std::string& display_name, std::size_t max_errors = 50);

/// The data-dictionary name of a 1-based data field, e.g. 15 -> "direct normal radiation";
/// "unknown field" outside 1..35.
const char* epw_field_name(int field);

/// Where a record's field is in the file (file:line:field), for consumers that report a
/// value they need but find missing, e.g. a sky model lacking DNI.
SourceLocation epw_field_location(const EpwFile& file, const WeatherRecord& record, int field);

/// Number of days in `month` (1..12); February has 29 if `leap`.
int days_in_month(int month, bool leap);

}  // namespace dayphoton::weather
