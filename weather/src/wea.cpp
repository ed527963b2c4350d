// RADIANCE / DAYSIM .wea reading, writing and EPW -> .wea conversion.
//
// Format and sign conventions: facts/sky-and-metrics.md §6.2 (from RADIANCE epw2wea.c and
// the gendaymtx .wea parser): six header lines in a fixed order, longitude and time_zone in
// degrees WEST positive (time_zone = standard meridian = -15 * EPW time zone), data lines
// "month day hour direct diffuse" with hour = local standard time of the interval midpoint.
// Our conversion reproduces RADIANCE's epw2wea output for hourly files (checked against
// refdata/results/c_annual/oakland.wea in tests/weather/wea_test.cpp), except that half-hour
// time zones are kept (epw2wea truncates them with atoi, facts §6.2 / §7 item 8).
// Value limits: 0..1500 W/m^2 and 0..150000 lux, as for EPW (epw_reader.cpp).
#include "dayphoton/weather/wea.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "dayphoton/core/atomic_file.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/input_file.h"
#include "text_fields.h"

namespace dayphoton::weather {
namespace {

using detail::format_number;
using detail::parse_double;
using detail::parse_int;
using detail::quoted;

struct Token {
  std::string_view text;
  int column;  ///< 1-based
};

std::vector<Token> tokens(std::string_view line) {
  std::vector<Token> out;
  std::size_t i = 0;
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; };
  while (i < line.size()) {
    while (i < line.size() && blank(line[i])) ++i;
    if (i >= line.size()) break;
    const std::size_t b = i;
    while (i < line.size() && !blank(line[i])) ++i;
    out.push_back({line.substr(b, i - b), static_cast<int>(b) + 1});
  }
  return out;
}

const char* const HeaderKeywords[6] = {"place", "latitude", "longitude", "time_zone",
                                       "site_elevation", "weather_data_file_units"};

class WeaParser {
 public:
  WeaParser(const std::string& name, std::size_t max_errors) : m_name(name), m_diag(max_errors) {
    m_file.source_name = name;
  }

  WeaFile parse(const std::vector<std::string>& lines) {
    m_lines = &lines;
    if (parse_header(lines)) parse_records(lines);
    m_diag.throw_if_errors();
    return std::move(m_file);
  }

 private:
  void error(int line, int column, const std::string& message) {
    const std::string& text = (*m_lines)[static_cast<std::size_t>(line - 1)];
    m_diag.error(SourceLocation{m_name, line, column}, message,
                 text.size() <= 200 ? text : std::string());
  }

  bool parse_header(const std::vector<std::string>& lines) {
    for (int i = 0; i < 6; ++i) {
      const int line = i + 1;
      if (i >= static_cast<int>(lines.size())) {
        m_diag.error(SourceLocation{m_name, line, 0},
                     std::string(lines.empty() ? "empty file" : "file ends in the header") +
                         ": expected the '" + HeaderKeywords[i] +
                         "' line (a .wea file has 6 header lines)");
        return false;
      }
      const std::vector<Token> t = tokens(lines[static_cast<std::size_t>(i)]);
      if (t.empty() || t[0].text != HeaderKeywords[i]) {
        error(line, t.empty() ? 1 : t[0].column,
              "header line " + std::to_string(line) + " should start with '" + HeaderKeywords[i] +
                  "', found " + (t.empty() ? std::string("an empty line") : quoted(t[0].text)));
        return false;
      }
      if (i == 0) {
        if (t.size() < 2) {
          error(line, 0, "'place' needs a name");
        } else {
          const std::string& text = lines[0];
          std::string_view rest(text);
          rest.remove_prefix(static_cast<std::size_t>(t[1].column - 1));
          m_file.header.place = std::string(detail::trim(rest));
        }
        continue;
      }
      if (t.size() != 2) {
        error(line, t.size() < 2 ? 0 : t[2].column,
              std::string("'") + HeaderKeywords[i] + "' needs exactly one value");
        continue;
      }
      const std::optional<double> v = parse_double(t[1].text);
      if (!v) {
        error(line, t[1].column, std::string(HeaderKeywords[i]) + ": " + quoted(t[1].text) +
                                     " is not a number");
        continue;
      }
      const auto check = [&](double lo, double hi, const char* unit, double& out) {
        if (*v < lo || *v > hi)
          error(line, t[1].column, std::string(HeaderKeywords[i]) + ": " + format_number(*v, 0) +
                                       " is outside [" + format_number(lo, 0) + ", " +
                                       format_number(hi, 0) + "] " + unit);
        else
          out = *v;
      };
      WeaHeader& h = m_file.header;
      switch (i) {
        case 1: check(-90, 90, "degrees (north positive)", h.latitude_deg); break;
        case 2: check(-180, 180, "degrees (west positive)", h.longitude_west_deg); break;
        case 3: check(-210, 180, "degrees (standard meridian, west positive)", h.time_zone_west_deg); break;
        case 4: check(-1000, 9999.9, "m", h.site_elevation_m); break;
        case 5: {
          const std::optional<int> u = parse_int(t[1].text);
          if (!u || *u < 1 || *u > 3)
            error(line, t[1].column,
                  "weather_data_file_units: expected 1, 2 or 3, found " + quoted(t[1].text));
          else
            h.units = static_cast<WeaUnits>(*u);
          h.units_column = t[1].column;
          break;
        }
        default: break;
      }
    }
    return true;
  }

  void parse_records(const std::vector<std::string>& lines) {
    std::size_t last = lines.size();
    while (last > 6 && detail::trim(lines[last - 1]).empty()) --last;
    const bool lux = m_file.header.units == WeaUnits::DirectNormalDiffuseHorizontalIlluminance;
    const double limit = lux ? 150000.0 : 1500.0;
    const char* unit = lux ? "lux" : "W/m^2";
    for (std::size_t i = 6; i < last; ++i) {
      const int line = static_cast<int>(i) + 1;
      const std::vector<Token> t = tokens(lines[i]);
      if (t.size() != 5) {
        error(line, t.size() > 5 ? t[5].column : 0,
              "expected 5 values (month day hour direct diffuse), found " +
                  std::to_string(t.size()));
        continue;
      }
      WeaRecord r;
      r.source_line = line;
      bool ok = true;
      const std::optional<int> m = parse_int(t[0].text);
      if (!m || *m < 1 || *m > 12) {
        error(line, t[0].column, "month: expected 1..12, found " + quoted(t[0].text));
        ok = false;
      } else {
        r.month = *m;
      }
      const std::optional<int> d = parse_int(t[1].text);
      const int dim = ok ? days_in_month(r.month, true) : 31;
      if (!d || *d < 1 || *d > dim) {
        error(line, t[1].column,
              "day: expected 1.." + std::to_string(dim) + ", found " + quoted(t[1].text));
        ok = false;
      } else {
        r.day = *d;
      }
      const std::optional<double> h = parse_double(t[2].text);
      if (!h || *h < 0.0 || *h > 24.0) {
        error(line, t[2].column,
              "hour: expected decimal local standard time in [0, 24], found " + quoted(t[2].text));
        ok = false;
      } else {
        r.hour_lst = *h;
        r.hour_column = t[2].column;
      }
      const auto value = [&](const Token& tok, const char* what, double& out) {
        const std::optional<double> v = parse_double(tok.text);
        if (!v) {
          error(line, tok.column, std::string(what) + ": " + quoted(tok.text) + " is not a number");
          ok = false;
        } else if (*v < 0.0 || *v > limit) {
          error(line, tok.column, std::string(what) + ": " + std::string(tok.text) + " " + unit +
                                      (*v < 0 ? " is negative" : " is outside the physical range") +
                                      " [0, " + format_number(limit, 0) + "]");
          ok = false;
        } else {
          out = *v;
        }
      };
      value(t[3], "direct", r.direct);
      value(t[4], "diffuse", r.diffuse);
      if (ok) m_file.records.push_back(r);
    }
  }

  std::string m_name;
  Diagnostics m_diag;
  WeaFile m_file;
  const std::vector<std::string>* m_lines = nullptr;
};

}  // namespace

WeaFile read_wea(std::istream& in, const std::string& display_name, std::size_t max_errors) {
  const std::vector<std::string> lines = detail::read_lines(in);
  return WeaParser(display_name, max_errors).parse(lines);
}

WeaFile read_wea(const std::string& path, std::size_t max_errors) {
  std::ifstream in = open_input_file(path, "weather file");
  return read_wea(in, path, max_errors);
}

void write_wea(std::ostream& out, const WeaFile& wea) {
  const WeaHeader& h = wea.header;
  out << "place " << h.place << '\n'
      << "latitude " << format_number(h.latitude_deg, 2) << '\n'
      << "longitude " << format_number(h.longitude_west_deg, 2) << '\n'
      << "time_zone " << format_number(h.time_zone_west_deg, 0) << '\n'
      << "site_elevation " << format_number(h.site_elevation_m, 1) << '\n'
      << "weather_data_file_units " << static_cast<int>(h.units) << '\n';
  char row[128];
  for (const WeaRecord& r : wea.records) {
    std::snprintf(row, sizeof row, "%d %d %.3f %.0f %.0f\n", r.month, r.day, r.hour_lst, r.direct,
                  r.diffuse);
    out << row;
  }
}

void write_wea_file(const std::string& path, const WeaFile& wea) {
  write_file_atomically(path, [&](std::ostream& out) { write_wea(out, wea); });
}

WeaFile epw_to_wea(const EpwFile& epw) {
  const EpwLocation& loc = epw.header.location;
  WeaFile wea;
  wea.source_name = epw.source_name;
  wea.header.place = loc.city + "_" + loc.country;
  wea.header.latitude_deg = loc.latitude_deg;
  // RADIANCE: longitude and standard meridian in degrees WEST positive (facts §0, §6.2).
  wea.header.longitude_west_deg = loc.longitude_east_deg == 0.0 ? 0.0 : -loc.longitude_east_deg;
  wea.header.time_zone_west_deg = loc.time_zone_h == 0.0 ? 0.0 : -15.0 * loc.time_zone_h;
  wea.header.site_elevation_m = loc.elevation_m;
  wea.header.units = WeaUnits::DirectNormalDiffuseHorizontalIrradiance;

  Diagnostics diag;
  wea.records.reserve(epw.records.size());
  for (const WeatherRecord& r : epw.records) {
    const bool have_dni = r.direct_normal_w_m2.has_value();
    const bool have_dhi = r.diffuse_horizontal_w_m2.has_value();
    if (!have_dni)
      diag.error(epw_field_location(epw, r, epw_field::DirectNormalRadiation),
                 "field 15 (direct normal radiation) is missing; a .wea file needs it");
    if (!have_dhi)
      diag.error(epw_field_location(epw, r, epw_field::DiffuseHorizontalRadiation),
                 "field 16 (diffuse horizontal radiation) is missing; a .wea file needs it");
    if (!have_dni || !have_dhi) continue;
    WeaRecord w;
    w.month = r.month;
    w.day = r.day;
    w.hour_lst = r.hour - 0.5;  // midpoint of (hour-1, hour]
    w.direct = *r.direct_normal_w_m2;
    w.diffuse = *r.diffuse_horizontal_w_m2;
    wea.records.push_back(w);
  }
  diag.throw_if_errors();
  return wea;
}

}  // namespace dayphoton::weather
