// EPW reader: parses and validates an EnergyPlus weather file into typed records.
//
// Source of the format: EnergyPlus "Auxiliary Programs" guide, "EnergyPlus Weather File
// (EPW) Data Dictionary" (field order, units, missing codes, LOCATION / HOLIDAYS/DAYLIGHT
// SAVINGS / DATA PERIODS layout), summarised in facts/sky-and-metrics.md §6.3.
// Physical limits (errors, not missing): the data dictionary's min/max where it gives one
// (temperatures -70..70 °C, relative humidity 0..110 %, pressure 31000..120000 Pa, wind
// direction 0..360°, wind speed 0..40 m/s, sky cover 0..10 tenths); radiation fields
// 0..1500 W/m^2 (the extraterrestrial direct normal irradiance is 1367 * 1.034 = 1414 W/m^2
// at perihelion, so no hourly mean may exceed 1500); infrared 0..1000 W/m^2 (sigma T^4 at
// 70 °C is 785 W/m^2); illuminances 0..150000 lux (extraterrestrial 127500 lux * 1.034 =
// 131800 lux, plus margin for cloud enhancement).
// Decisions on leap days, the minute field, data periods and missing values: epw_reader.h
// and docs/weather.md.
#include "dayphoton/weather/epw_reader.h"

#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "dayphoton/core/input_file.h"
#include "text_fields.h"

namespace dayphoton::weather {
namespace {

using detail::parse_double;
using detail::parse_int;
using detail::quoted;
using detail::split;
using detail::trim;

constexpr double Inf = std::numeric_limits<double>::infinity();

/// How one numeric data field is read and checked.
struct FieldSpec {
  int field;                                     ///< 1-based field number
  std::optional<double> WeatherRecord::*member;  ///< where it goes (nullptr: checked only)
  double missing_code;                           ///< value >= code (== if exact) is missing
  bool missing_exact;
  double min, max;                               ///< valid range, inclusive
  const char* unit;
};

const std::array<FieldSpec, 28> NumericFields{{
    {7, &WeatherRecord::dry_bulb_c, 99.9, false, -70, 70, "degC"},
    {8, &WeatherRecord::dew_point_c, 99.9, false, -70, 70, "degC"},
    {9, &WeatherRecord::relative_humidity_percent, 999, false, 0, 110, "%"},
    {10, &WeatherRecord::pressure_pa, 999999, false, 31000, 120000, "Pa"},
    {11, &WeatherRecord::extraterrestrial_horizontal_w_m2, 9999, false, 0, 1500, "W/m^2"},
    {12, &WeatherRecord::extraterrestrial_direct_normal_w_m2, 9999, false, 0, 1500, "W/m^2"},
    {13, &WeatherRecord::horizontal_infrared_w_m2, 9999, false, 0, 1000, "W/m^2"},
    {14, &WeatherRecord::global_horizontal_w_m2, 9999, false, 0, 1500, "W/m^2"},
    {15, &WeatherRecord::direct_normal_w_m2, 9999, false, 0, 1500, "W/m^2"},
    {16, &WeatherRecord::diffuse_horizontal_w_m2, 9999, false, 0, 1500, "W/m^2"},
    {17, &WeatherRecord::global_horizontal_lux, 999900, false, 0, 150000, "lux"},
    {18, &WeatherRecord::direct_normal_lux, 999900, false, 0, 150000, "lux"},
    {19, &WeatherRecord::diffuse_horizontal_lux, 999900, false, 0, 150000, "lux"},
    {20, &WeatherRecord::zenith_luminance_cd_m2, 9999, true, 0, Inf, "cd/m^2"},
    {21, &WeatherRecord::wind_direction_deg, 999, false, 0, 360, "deg"},
    {22, &WeatherRecord::wind_speed_m_s, 999, false, 0, 40, "m/s"},
    {23, &WeatherRecord::total_sky_cover_tenths, 99, false, 0, 10, "tenths"},
    {24, &WeatherRecord::opaque_sky_cover_tenths, 99, false, 0, 10, "tenths"},
    {25, &WeatherRecord::visibility_km, 9999, false, 0, Inf, "km"},
    {26, &WeatherRecord::ceiling_height_m, 99999, false, 0, Inf, "m"},
    {27, nullptr, 9, true, 0, 9, ""},
    {29, &WeatherRecord::precipitable_water_mm, 999, false, 0, Inf, "mm"},
    {30, &WeatherRecord::aerosol_optical_depth, 0.999, false, 0, Inf, ""},
    {31, &WeatherRecord::snow_depth_cm, 999, false, 0, Inf, "cm"},
    {32, &WeatherRecord::days_since_last_snowfall, 99, false, 0, Inf, "days"},
    {33, &WeatherRecord::albedo, 999, false, 0, Inf, ""},
    {34, &WeatherRecord::liquid_precipitation_depth_mm, 999, false, 0, Inf, "mm"},
    {35, &WeatherRecord::liquid_precipitation_quantity_h, 99, false, 0, Inf, "h"},
}};

const std::array<const char*, 36> FieldNames{{
    "unknown field",
    "year",
    "month",
    "day",
    "hour",
    "minute",
    "data source and uncertainty flags",
    "dry bulb temperature",
    "dew point temperature",
    "relative humidity",
    "atmospheric station pressure",
    "extraterrestrial horizontal radiation",
    "extraterrestrial direct normal radiation",
    "horizontal infrared radiation intensity",
    "global horizontal radiation",
    "direct normal radiation",
    "diffuse horizontal radiation",
    "global horizontal illuminance",
    "direct normal illuminance",
    "diffuse horizontal illuminance",
    "zenith luminance",
    "wind direction",
    "wind speed",
    "total sky cover",
    "opaque sky cover",
    "visibility",
    "ceiling height",
    "present weather observation",
    "present weather codes",
    "precipitable water",
    "aerosol optical depth",
    "snow depth",
    "days since last snowfall",
    "albedo",
    "liquid precipitation depth",
    "liquid precipitation quantity",
}};

const std::array<const char*, 8> HeaderKeywords{{
    "LOCATION", "DESIGN CONDITIONS", "TYPICAL/EXTREME PERIODS", "GROUND TEMPERATURES",
    "HOLIDAYS/DAYLIGHT SAVINGS", "COMMENTS 1", "COMMENTS 2", "DATA PERIODS"}};

const std::array<const char*, 11> LocationFieldNames{{
    "", "keyword", "city", "state/province/region", "country", "source", "WMO number",
    "latitude", "longitude", "time zone", "elevation"}};

std::string field_label(int field) {
  return "field " + std::to_string(field) + " (" + epw_field_name(field) + ")";
}

std::string number_text(double v) { return detail::format_number(v, 0); }

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  return out;
}

/// A (month, day, hour) position in the year; compares chronologically.
struct Stamp {
  int month = 1, day = 1, hour = 1;
  auto key() const { return std::make_tuple(month, day, hour); }
  bool operator==(const Stamp& o) const { return key() == o.key(); }
  bool operator<(const Stamp& o) const { return key() < o.key(); }
  std::string text() const {
    return std::to_string(month) + "/" + std::to_string(day) + " hour " + std::to_string(hour);
  }
};

Stamp next_stamp(Stamp s, bool leap) {
  if (++s.hour <= 24) return s;
  s.hour = 1;
  if (++s.day <= days_in_month(s.month, leap)) return s;
  s.day = 1;
  ++s.month;  // month 13 = past the end of the year
  return s;
}

int hours_between(Stamp first, Stamp last, bool leap) {
  int n = 0;
  for (Stamp s = first; !(last < s) && s.month <= 12; s = next_stamp(s, leap)) ++n;
  return n;
}

class EpwParser {
 public:
  EpwParser(const std::string& name, std::size_t max_errors)
      : m_name(name), m_diag(max_errors) {
    m_file.source_name = name;
  }

  EpwFile parse(const std::vector<std::string>& lines) {
    if (parse_header(lines)) parse_records(lines);
    m_diag.throw_if_errors();
    m_file.warnings = m_diag.entries();
    return std::move(m_file);
  }

 private:
  SourceLocation at(int line, int field) const { return SourceLocation{m_name, line, field}; }
  void error(int line, int field, const std::string& message) {
    m_diag.error(at(line, field), message);
  }

  // ---- header ----------------------------------------------------------------------

  /// Returns false if the header is too broken to look for records.
  bool parse_header(const std::vector<std::string>& lines) {
    for (int i = 0; i < 8; ++i) {
      const int line = i + 1;
      if (i >= static_cast<int>(lines.size())) {
        error(line, 0,
              std::string(lines.empty() ? "empty file" : "file ends in the header") +
                  ": expected the '" + HeaderKeywords[i] + "' line (an EPW file has 8 header lines)");
        return false;
      }
      const std::vector<std::string_view> f = split(lines[i], ',');
      const std::string keyword = upper(trim(f[0]));
      const bool ok = keyword == HeaderKeywords[i] ||
                      (i == 4 && keyword == "HOLIDAYS/DAYLIGHT SAVING");
      if (!ok) {
        std::string msg = "header line " + std::to_string(line) + " should start with '" +
                          HeaderKeywords[i] + "', found " + quoted(trim(f[0]));
        if (parse_int(f[0])) msg += " (a header line is missing)";
        error(line, 1, msg);
        return false;
      }
      if (i == 0) parse_location(f);
      if (i == 4) parse_holidays(f);
      if (i == 7) parse_data_periods(f);
    }
    return true;
  }

  void parse_location(const std::vector<std::string_view>& f) {
    const int n = static_cast<int>(f.size());
    if (n < 10) {
      error(1, n + 1,
            "LOCATION line has " + std::to_string(n) + " fields, expected 10 (field " +
                std::to_string(n + 1) + " (" + LocationFieldNames[n + 1] + ") is missing)");
      return;
    }
    if (n > 10)  // e.g. a trailing comma or a note: fields 1-10 are still where they belong
      m_diag.warning(at(1, 11), "LOCATION line has " + std::to_string(n) +
                                    " fields, expected 10; the fields after field 10 (elevation) are ignored");
    EpwLocation& loc = m_file.header.location;
    loc.city = std::string(trim(f[1]));
    loc.state = std::string(trim(f[2]));
    loc.country = std::string(trim(f[3]));
    loc.source = std::string(trim(f[4]));
    loc.wmo = std::string(trim(f[5]));
    const auto number = [&](int field, double lo, double hi, const char* unit, double& out) {
      const std::string label = "field " + std::to_string(field) + " (" +
                                LocationFieldNames[field] + ")";
      const std::optional<double> v = parse_double(f[field - 1]);
      if (!v) {
        error(1, field, label + ": " + quoted(trim(f[field - 1])) + " is not a number");
      } else if (*v < lo || *v > hi) {
        error(1, field, label + ": " + number_text(*v) + " is outside [" + number_text(lo) +
                            ", " + number_text(hi) + "] " + unit);
      } else {
        out = *v;
      }
    };
    number(7, -90, 90, "degrees (north positive)", loc.latitude_deg);
    number(8, -180, 180, "degrees (east positive)", loc.longitude_east_deg);
    number(9, -12, 14, "hours (east positive)", loc.time_zone_h);
    number(10, -1000, 9999.9, "m", loc.elevation_m);
  }

  void parse_holidays(const std::vector<std::string_view>& f) {
    const std::string flag = f.size() < 2 ? std::string() : upper(trim(f[1]));
    if (flag.empty()) {
      // Written by some converters: the records decide the calendar (parse_records).
      m_leap_flag_empty = true;
      m_diag.warning(at(5, 2), std::string("field 2 (LeapYear observed) is ") +
                                   (f.size() < 2 ? "absent" : "empty") +
                                   "; the calendar follows the records (366 days if they hold February 29)");
    } else if (flag == "YES") {
      m_file.header.leap_year_observed = true;
    } else if (flag != "NO") {
      error(5, 2, "field 2 (LeapYear observed): expected 'Yes' or 'No', found " +
                      quoted(trim(f[1])));
    }
    if (f.size() > 2) m_file.header.dst_start = std::string(trim(f[2]));
    if (f.size() > 3) m_file.header.dst_end = std::string(trim(f[3]));
  }

  /// "M/D", "M/D/YYYY" or "YYYY/M/D" (a first part of 4 digits is a year) -> month, day;
  /// false (and an error) if invalid. The year of a data period is not used: the records
  /// carry their own years (SiteClock).
  bool parse_date(std::string_view text, int field, const char* what, int& month, int& day) {
    const std::vector<std::string_view> p = split(text, '/');
    std::optional<int> m, d;
    if (p.size() == 2) {
      m = parse_int(p[0]);
      d = parse_int(p[1]);
    } else if (p.size() == 3 && trim(p[0]).size() == 4 && parse_int(p[0])) {
      m = parse_int(p[1]);
      d = parse_int(p[2]);
    } else if (p.size() == 3 && parse_int(p[2])) {
      m = parse_int(p[0]);
      d = parse_int(p[1]);
    }
    if (!m || !d || *m < 1 || *m > 12 || *d < 1 || *d > days_in_month(*m, true)) {
      error(8, field, std::string("field ") + std::to_string(field) + " (" + what +
                          "): expected a date M/D, M/D/YYYY or YYYY/M/D, found " + quoted(trim(text)));
      return false;
    }
    month = *m;
    day = *d;
    return true;
  }

  void parse_data_periods(const std::vector<std::string_view>& f) {
    const int n = static_cast<int>(f.size());
    if (n < 7) {
      error(8, n + 1,
            "DATA PERIODS line has " + std::to_string(n) +
                " fields, expected 7 (keyword, number of periods, records per hour, name, "
                "start weekday, start date, end date)");
      return;
    }
    EpwDataPeriod& dp = m_file.header.data_period;
    const std::optional<int> periods = parse_int(f[1]);
    if (!periods || *periods != 1)
      error(8, 2, "field 2 (number of data periods): only one data period is supported, found " +
                      quoted(trim(f[1])));
    const std::optional<int> per_hour = parse_int(f[2]);
    if (!per_hour || *per_hour != 1)
      error(8, 3, "field 3 (records per hour): only hourly data (1 record per hour) is "
                  "supported, found " + quoted(trim(f[2])));
    dp.name = std::string(trim(f[3]));
    dp.start_weekday = std::string(trim(f[4]));
    int sm = 1, sd = 1, em = 12, ed = 31;
    const bool start_ok = parse_date(f[5], 6, "start date", sm, sd);
    const bool end_ok = parse_date(f[6], 7, "end date", em, ed);
    if (start_ok && end_ok) {
      if (std::make_pair(em, ed) < std::make_pair(sm, sd)) {
        error(8, 7, "field 7 (end date): data periods that wrap around the new year are not "
                    "supported (start " + std::to_string(sm) + "/" + std::to_string(sd) +
                    ", end " + std::to_string(em) + "/" + std::to_string(ed) + ")");
      } else {
        dp.start_month = sm;
        dp.start_day = sd;
        dp.end_month = em;
        dp.end_day = ed;
      }
    }
    if (n > 7)
      error(8, 8, "DATA PERIODS line has " + std::to_string(n) +
                      " fields, expected 7 (only one data period is supported)");
  }

  // ---- records ---------------------------------------------------------------------

  void parse_records(const std::vector<std::string>& lines) {
    const EpwDataPeriod& dp = m_file.header.data_period;
    m_leap = m_file.header.leap_year_observed;
    const Stamp start{dp.start_month, dp.start_day, 1};
    const Stamp end{dp.end_month, dp.end_day, 24};
    Stamp expected = start;
    bool past_end = false;
    std::optional<Stamp> previous;
    int previous_line = 0;

    // Trailing blank lines are ignored; blank lines between records are errors.
    std::size_t last = lines.size();
    while (last > 8 && trim(lines[last - 1]).empty()) --last;

    for (std::size_t i = 8; i < last; ++i) {
      const int line = static_cast<int>(i) + 1;
      if (trim(lines[i]).empty()) {
        error(line, 0, "blank line between records");
        continue;
      }
      std::optional<WeatherRecord> rec = parse_record(lines[i], line);
      if (!rec) {
        // Unusable record: assume it was the expected hour so later records are not all
        // reported as out of sequence.
        if (!past_end) {
          previous = expected;
          previous_line = line;
          expected = next_stamp(expected, m_leap);
          past_end = end < expected || expected.month > 12;
        }
        continue;
      }
      Stamp s{rec->month, rec->day, rec->hour};
      if (s.month == 2 && s.day == 29 && !m_leap) {
        m_leap = true;
        if (!m_leap_flag_empty)  // an empty flag was already reported, with this rule
          m_diag.warning(at(line, 3),
                       "February 29 present although the HOLIDAYS/DAYLIGHT SAVINGS line says "
                       "LeapYear observed = No; the leap day is kept (366-day year)");
        if (previous) expected = next_stamp(*previous, true);
      }
      if (past_end) {
        error(line, 2, "record " + s.text() + " is after the end of the data period (" +
                           end.text() + ")");
        continue;
      }
      if (s == expected) {
        m_file.records.push_back(*rec);
      } else if (s < expected) {
        if (previous && s == *previous)
          error(line, 2, "duplicate record " + s.text() + " (already on line " +
                             std::to_string(previous_line) + ")");
        else
          error(line, 2, "record " + s.text() + " is out of order: expected " + expected.text() +
                             (previous ? " after " + previous->text() + " on line " +
                                             std::to_string(previous_line)
                                       : std::string()));
        continue;
      } else {
        std::string msg = "missing record(s): expected " + expected.text() + ", found " + s.text();
        if (expected.month == 2 && expected.day == 29)
          msg += " (the header says LeapYear observed = Yes, so February 29 must be present)";
        error(line, 2, msg);
        m_file.records.push_back(*rec);
      }
      previous = s;
      previous_line = line;
      expected = next_stamp(s, m_leap);
      past_end = end < expected || expected.month > 12;
    }
    if (!past_end) {
      const int n_expected = hours_between(start, end, m_leap);
      error(static_cast<int>(last) + 1, 0,
            "file ends before the end of the data period: expected " + std::to_string(n_expected) +
                " hourly records (" + std::to_string(dp.start_month) + "/" +
                std::to_string(dp.start_day) + " hour 1 to " + end.text() + "), found " +
                std::to_string(m_file.records.size()) + "; next expected " + expected.text());
    }
    report_ignored_values();
    m_file.leap_day_present = false;
    for (const WeatherRecord& r : m_file.records)
      if (r.month == 2 && r.day == 29) m_file.leap_day_present = true;
  }

  std::optional<WeatherRecord> parse_record(const std::string& text, int line) {
    const std::vector<std::string_view> f = split(text, ',');
    const int n = static_cast<int>(f.size());
    if (n != epw_field::Count) {
      if (n < epw_field::Count)
        error(line, n + 1, "record has " + std::to_string(n) + " fields, expected 35 (" +
                               field_label(n + 1) + " is missing)");
      else
        error(line, epw_field::Count + 1,
              "record has " + std::to_string(n) + " fields, expected 35");
      return std::nullopt;
    }
    WeatherRecord r;
    r.source_line = line;
    bool date_ok = true;
    const auto integer = [&](int field, int lo, int hi, int& out, const std::string& range) {
      const std::optional<int> v = parse_int(f[field - 1]);
      if (!v) {
        error(line, field, field_label(field) + ": " + quoted(trim(f[field - 1])) +
                               " is not an integer");
        date_ok = false;
      } else if (*v < lo || *v > hi) {
        error(line, field, field_label(field) + ": " + std::to_string(*v) + " is outside " + range);
        date_ok = false;
      } else {
        out = *v;
      }
    };
    integer(epw_field::Year, -9999, 9999, r.year, "-9999..9999");
    integer(epw_field::Month, 1, 12, r.month, "1..12");
    if (date_ok) {
      const int dim = days_in_month(r.month, true);
      integer(epw_field::Day, 1, dim, r.day,
              "1.." + std::to_string(dim) + " (days of month " + std::to_string(r.month) + ")");
    } else {
      integer(epw_field::Day, 1, 31, r.day, "1..31");
    }
    integer(epw_field::Hour, 1, 24, r.hour, "1..24 (EPW hour h covers (h-1, h])");
    const std::optional<int> minute = parse_int(f[epw_field::Minute - 1]);
    if (!minute || (*minute != 0 && *minute != 60)) {
      error(line, epw_field::Minute,
            field_label(epw_field::Minute) + ": " + quoted(trim(f[epw_field::Minute - 1])) +
                " is not valid for hourly data (expected 0 or 60)");
      date_ok = false;
    } else {
      r.minute = *minute;
    }

    for (const FieldSpec& spec : NumericFields) {
      const std::string_view raw = trim(f[spec.field - 1]);
      if (raw.empty()) continue;  // empty = missing
      const bool used = epw_field_is_used(spec.field);
      const std::optional<double> v = parse_double(raw);
      if (!v) {
        if (used)
          error(line, spec.field, field_label(spec.field) + ": " + quoted(raw) + " is not a number");
        else
          ignore(line, spec.field, field_label(spec.field) + ": " + quoted(raw) + " is not a number");
        continue;
      }
      const bool missing = spec.missing_exact ? *v == spec.missing_code : *v >= spec.missing_code;
      if (missing) continue;
      if (*v < spec.min || *v > spec.max) {
        const std::string range = "[" + number_text(spec.min) + ", " +
                                  (std::isinf(spec.max) ? std::string("inf") : number_text(spec.max)) + "]";
        if (!used) {
          ignore(line, spec.field, field_label(spec.field) + ": " + std::string(raw) +
                                       (*spec.unit ? std::string(" ") + spec.unit : std::string()) +
                                       " is outside " + range);
          continue;
        }
        std::string msg = field_label(spec.field) + ": " + std::string(raw) + " " + spec.unit;
        if (*v < 0 && spec.min == 0)
          msg += " is negative";
        else
          msg += " is outside the physical range";
        msg += " " + range;
        error(line, spec.field, msg);
        continue;
      }
      if (spec.member) r.*(spec.member) = *v;
    }
    if (!date_ok) return std::nullopt;
    return r;
  }

  /// A bad value in a field dayphoton does not use: read as missing, counted, the first
  /// MaxLocatedIgnoredValues located (report_ignored_values summarises the rest).
  void ignore(int line, int field, const std::string& problem) {
    ++m_file.ignored_value_count;
    ++m_ignored_by_field[static_cast<std::size_t>(field)];
    if (m_file.ignored_value_count <= MaxLocatedIgnoredValues)
      m_diag.warning(at(line, field), problem + "; dayphoton does not use this field, the value is ignored");
  }

  void report_ignored_values() {
    const std::size_t n = m_file.ignored_value_count;
    if (n <= MaxLocatedIgnoredValues) return;
    std::string by_field;
    for (std::size_t f = 1; f < m_ignored_by_field.size(); ++f) {
      if (m_ignored_by_field[f] == 0) continue;
      if (!by_field.empty()) by_field += ", ";
      by_field += field_label(static_cast<int>(f)) + ": " + std::to_string(m_ignored_by_field[f]);
    }
    m_diag.warning(SourceLocation{m_name, 0, 0},
                   std::to_string(n) + " values in fields dayphoton does not use were ignored (" + by_field +
                       "); the first " + std::to_string(MaxLocatedIgnoredValues) + " are located above");
  }

  std::string m_name;
  Diagnostics m_diag;
  EpwFile m_file;
  bool m_leap = false;
  bool m_leap_flag_empty = false;  ///< HOLIDAYS/DAYLIGHT SAVINGS field 2 empty or absent
  std::array<std::size_t, epw_field::Count + 1> m_ignored_by_field{};
};

}  // namespace

int days_in_month(int month, bool leap) {
  static constexpr std::array<int, 12> Days{{31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31}};
  if (month < 1 || month > 12) return 0;
  return month == 2 && leap ? 29 : Days[static_cast<std::size_t>(month - 1)];
}

bool epw_field_is_used(int field) {
  switch (field) {
    case epw_field::Year:
    case epw_field::Month:
    case epw_field::Day:
    case epw_field::Hour:
    case epw_field::Minute:
    case epw_field::DewPoint:
    case epw_field::DirectNormalRadiation:
    case epw_field::DiffuseHorizontalRadiation:
    case epw_field::DiffuseHorizontalIlluminance:
      return true;
    default:
      return false;
  }
}

const char* epw_field_name(int field) {
  if (field < 1 || field > epw_field::Count) return FieldNames[0];
  return FieldNames[static_cast<std::size_t>(field)];
}

SourceLocation epw_field_location(const EpwFile& file, const WeatherRecord& record, int field) {
  return SourceLocation{file.source_name, record.source_line, field};
}

EpwFile read_epw(std::istream& in, const std::string& display_name, std::size_t max_errors) {
  const std::vector<std::string> lines = detail::read_lines(in);
  return EpwParser(display_name, max_errors).parse(lines);
}

EpwFile read_epw(const std::string& path, std::size_t max_errors) {
  std::ifstream in = open_input_file(path, "weather file");
  return read_epw(in, path, max_errors);
}

}  // namespace dayphoton::weather
