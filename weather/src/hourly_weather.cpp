// HourlyWeather from EPW and .wea files, and the fill rule for missing irradiance
// (hourly_weather.h; docs/weather.md "Missing values in used fields", ".wea as the annual
// weather"). The .wea layout and its west-positive signs: RADIANCE epw2wea.c and gendaymtx,
// summarised in wea.h.
#include "dayphoton/weather/hourly_weather.h"

#include <cmath>
#include <cstdio>
#include <tuple>

#include "dayphoton/weather/epw_reader.h"
#include "dayphoton/weather/wea.h"

namespace dayphoton::weather {
namespace {

using Member = std::optional<double> WeatherRecord::*;

Member member_of(WeatherValue value) {
  return value == WeatherValue::DirectNormalIrradiance ? &WeatherRecord::direct_normal_w_m2
                                                       : &WeatherRecord::diffuse_horizontal_w_m2;
}

std::string stamp_text(const WeatherRecord& r) {
  return std::to_string(r.month) + "/" + std::to_string(r.day) + " hour " + std::to_string(r.hour);
}

/// Fills the gaps of one irradiance value (the rule of hourly_weather.h); long gaps are errors.
void fill_gaps(HourlyWeather& w, WeatherValue value, Diagnostics& diag, std::size_t& located) {
  const Member m = member_of(value);
  std::vector<WeatherRecord>& rec = w.records;
  const std::size_t n = rec.size();
  std::size_t i = 0;
  while (i < n) {
    if (rec[i].*m) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < n && !(rec[j].*m)) ++j;  // the gap is [i, j)
    const std::size_t length = j - i;
    const bool has_before = i > 0, has_after = j < n;
    if (length > static_cast<std::size_t>(MaxInterpolatedGap_h) || (!has_before && !has_after)) {
      diag.error(weather_value_location(w, rec[i], value),
                 weather_value_name(w, value) + " is missing for " + std::to_string(length) + " consecutive hour" +
                     (length == 1 ? "" : "s") + " (" + stamp_text(rec[i]) + " to " + stamp_text(rec[j - 1]) +
                     "); at most " + std::to_string(MaxInterpolatedGap_h) +
                     " are interpolated: fill the gap with a weather tool, or use another file");
      i = j;
      continue;
    }
    const std::string gap = std::to_string(length) + (length == 1 ? " hour" : " hours");
    for (std::size_t k = i; k < j; ++k) {
      double v = 0;
      std::string how;
      if (has_before && has_after) {
        // Linear in time between the valid hours i-1 and j.
        const double a = *(rec[i - 1].*m), b = *(rec[j].*m);
        v = a + (b - a) * static_cast<double>(k - i + 1) / static_cast<double>(length + 1);
        how = "interpolated to " + format_number(v) + " W/m^2 (a gap of " + gap + ")";
      } else {
        v = has_before ? *(rec[i - 1].*m) : *(rec[j].*m);
        how = "set to " + format_number(v) + " W/m^2, the value of the nearest hour (a gap of " + gap + " at the " +
              (has_before ? "end" : "start") + " of the file)";
      }
      rec[k].*m = v;
      ++w.filled_values;
      if (++located <= MaxLocatedFilledValues)
        diag.warning(weather_value_location(w, rec[k], value), weather_value_name(w, value) + " is missing; " + how);
    }
    i = j;
  }
}

void apply_fill_rule(HourlyWeather& w) {
  Diagnostics diag;
  std::size_t located = 0;
  fill_gaps(w, WeatherValue::DirectNormalIrradiance, diag, located);
  fill_gaps(w, WeatherValue::DiffuseHorizontalIrradiance, diag, located);
  if (w.filled_values > MaxLocatedFilledValues)
    diag.warning(SourceLocation{w.source_name, 0, 0},
                 std::to_string(w.filled_values) + " missing irradiance values were interpolated; the first " +
                     std::to_string(MaxLocatedFilledValues) + " are located above");
  diag.throw_if_errors();
  for (const Diagnostic& d : diag.entries()) w.warnings.push_back(d);
}

/// A (month, day, hour) position; compares chronologically.
auto key(const WeatherRecord& r) { return std::make_tuple(r.month, r.day, r.hour); }

WeatherRecord next_hour(WeatherRecord r, bool leap) {
  if (++r.hour <= 24) return r;
  r.hour = 1;
  if (++r.day <= days_in_month(r.month, leap)) return r;
  r.day = 1;
  ++r.month;
  return r;
}

std::string wea_stamp_text(const WeatherRecord& r) {
  char hour[32];
  std::snprintf(hour, sizeof hour, "%.3f", r.hour - 0.5);
  return stamp_text(r) + " (" + hour + ")";
}

}  // namespace

SourceLocation weather_value_location(const HourlyWeather& w, const WeatherRecord& r, WeatherValue value) {
  if (w.format == WeatherFormat::Wea) return SourceLocation{w.source_name, r.source_line, 0};
  return SourceLocation{w.source_name, r.source_line,
                        value == WeatherValue::DirectNormalIrradiance ? epw_field::DirectNormalRadiation
                                                                      : epw_field::DiffuseHorizontalRadiation};
}

std::string weather_value_name(const HourlyWeather& w, WeatherValue value) {
  const bool direct = value == WeatherValue::DirectNormalIrradiance;
  if (w.format == WeatherFormat::Wea)
    return direct ? "direct normal irradiance (value 4 of the line)" : "diffuse horizontal irradiance (value 5 of the line)";
  const int field = direct ? epw_field::DirectNormalRadiation : epw_field::DiffuseHorizontalRadiation;
  return "field " + std::to_string(field) + " (" + epw_field_name(field) + ")";
}

HourlyWeather hourly_weather_from_epw(const EpwFile& epw) {
  HourlyWeather w;
  w.source_name = epw.source_name;
  w.format = WeatherFormat::Epw;
  w.site = epw.header.location;
  w.records = epw.records;
  w.leap_day_present = epw.leap_day_present;
  w.start_month = epw.header.data_period.start_month;
  w.start_day = epw.header.data_period.start_day;
  w.start_weekday = epw.header.data_period.start_weekday;
  w.warnings = epw.warnings;
  apply_fill_rule(w);
  return w;
}

HourlyWeather hourly_weather_from_wea(const WeaFile& wea) {
  HourlyWeather w;
  w.source_name = wea.source_name;
  w.format = WeatherFormat::Wea;
  const WeaHeader& h = wea.header;
  const std::size_t underscore = h.place.rfind('_');
  w.site.city = underscore == std::string::npos ? h.place : h.place.substr(0, underscore);
  if (underscore != std::string::npos) w.site.country = h.place.substr(underscore + 1);
  w.site.latitude_deg = h.latitude_deg;
  // RADIANCE: longitude and standard meridian in degrees WEST positive (wea.h).
  w.site.longitude_east_deg = h.longitude_west_deg == 0.0 ? 0.0 : -h.longitude_west_deg;
  w.site.time_zone_h = h.time_zone_west_deg == 0.0 ? 0.0 : -h.time_zone_west_deg / 15.0;
  w.site.elevation_m = h.site_elevation_m;

  Diagnostics diag;
  if (h.units != WeaUnits::DirectNormalDiffuseHorizontalIrradiance)
    diag.error(SourceLocation{wea.source_name, 6, h.units_column},
               "weather_data_file_units " + std::to_string(static_cast<int>(h.units)) +
                   ": the annual sky needs direct normal and diffuse horizontal irradiance (units 1)");
  bool leap = false;
  for (const WeaRecord& r : wea.records) leap = leap || (r.month == 2 && r.day == 29);

  std::optional<WeatherRecord> expected;
  for (const WeaRecord& r : wea.records) {
    const SourceLocation at{wea.source_name, r.source_line, r.hour_column};
    const double hour = r.hour_lst + 0.5;  // EPW hour h covers (h-1, h], its midpoint is h - 0.5
    const double whole = std::round(hour);
    if (std::abs(hour - whole) > 1e-6 || whole < 1 || whole > 24) {
      char text[32];
      std::snprintf(text, sizeof text, "%.3f", r.hour_lst);
      diag.error(at, std::string("hour ") + text +
                         " is not a mid-hour time stamp h - 0.5 (0.5, 1.5, .., 23.5) of hourly data");
      continue;
    }
    WeatherRecord rec;
    rec.year = 0;  // .wea has no year: SiteClock takes its reference year
    rec.month = r.month;
    rec.day = r.day;
    rec.hour = static_cast<int>(whole);
    rec.minute = 0;
    rec.source_line = r.source_line;
    rec.direct_normal_w_m2 = r.direct;
    rec.diffuse_horizontal_w_m2 = r.diffuse;
    if (expected && key(rec) != key(*expected)) {
      if (key(rec) < key(*expected)) {
        diag.error(at, "record " + wea_stamp_text(rec) + " is out of order or repeated: expected " +
                           wea_stamp_text(*expected));
        continue;
      }
      diag.error(at, "missing record(s): expected " + wea_stamp_text(*expected) + ", found " + wea_stamp_text(rec));
    }
    w.records.push_back(rec);
    expected = next_hour(rec, leap);
  }
  if (w.records.empty() && !diag.has_errors())
    diag.error(SourceLocation{wea.source_name, 7, 0}, "no data lines after the 6 header lines");
  diag.throw_if_errors();
  w.leap_day_present = leap;
  return w;
}

bool is_wea_path(const std::string& path) {
  if (path.size() < 5) return false;
  std::string ext = path.substr(path.size() - 4);
  for (char& c : ext) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  const char before = path[path.size() - 5];
  return ext == ".wea" && before != '/';
}

HourlyWeather read_hourly_weather(const std::string& path) {
  if (is_wea_path(path)) return hourly_weather_from_wea(read_wea(path));
  return hourly_weather_from_epw(read_epw(path));
}

}  // namespace dayphoton::weather
