// Test support: a synthetic, valid hourly EPW text that tests corrupt line by line.
// Values are plausible TMY3-like numbers (Oakland header); no real data is needed.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "dayphoton/weather/epw_reader.h"

namespace dayphoton::weather::test {

struct SyntheticEpw {
  std::vector<std::string> lines;

  /// 8 header lines + one record per hour from 1/1 to 12/31 (with Feb 29 if `leap_records`).
  explicit SyntheticEpw(bool leap_flag = false, bool leap_records = false) {
    lines = {
        "LOCATION,Oakland Metropolitan Arpt,CA,USA,TMY3,724930,37.72,-122.22,-8.0,2.0",
        "DESIGN CONDITIONS,0",
        "TYPICAL/EXTREME PERIODS,0",
        "GROUND TEMPERATURES,0",
        std::string("HOLIDAYS/DAYLIGHT SAVINGS,") + (leap_flag ? "Yes" : "No") + ",0,0,0",
        "COMMENTS 1,synthetic test file",
        "COMMENTS 2,values are made up",
        "DATA PERIODS,1,1,Data,Sunday, 1/ 1,12/31",
    };
    for (int m = 1; m <= 12; ++m)
      for (int d = 1; d <= days_in_month(m, leap_records); ++d)
        for (int h = 1; h <= 24; ++h) lines.push_back(record(m, d, h));
  }

  /// One record; DNI/DHI depend on the hour so rows differ.
  static std::string record(int month, int day, int hour, int minute = 0) {
    const bool sun = hour >= 8 && hour <= 17;
    const int dni = sun ? 100 + 10 * hour : 0;
    const int dhi = sun ? 50 + hour : 0;
    std::ostringstream s;
    s << "1999," << month << ',' << day << ',' << hour << ',' << minute
      << ",?9?9?9?9E0?9?9?9?9?9?9?9?9?9?9?9?9?9?9?9*9*9?9*9*9,9.0,7.0,87,102000,"
      << (sun ? 800 : 0) << ',' << (sun ? 1300 : 0) << ",305," << (sun ? 400 : 0) << ',' << dni
      << ',' << dhi << ',' << (sun ? 45000 : 0) << ',' << (sun ? 30000 : 0) << ','
      << (sun ? 9000 : 0) << ',' << (sun ? 3000 : 0)
      << ",130,2.6,4,4,24.1,77777,9,999999999,129,0.1120,0,88,0.160,999.0,99.0";
    return s.str();
  }

  /// Line number (1-based) of the record for month/day/hour in a 365-day file.
  static int line_of(int month, int day, int hour) {
    int doy = day;
    for (int m = 1; m < month; ++m) doy += days_in_month(m, false);
    return 8 + (doy - 1) * 24 + hour;
  }

  /// Replace field `field` (1-based) of line `line` (1-based).
  void set_field(int line, int field, const std::string& value) {
    std::string& text = lines[static_cast<std::size_t>(line - 1)];
    std::size_t begin = 0;
    for (int f = 1; f < field; ++f) begin = text.find(',', begin) + 1;
    std::size_t end = text.find(',', begin);
    if (end == std::string::npos) end = text.size();
    text.replace(begin, end - begin, value);
  }

  std::string text() const {
    std::string out;
    for (const std::string& l : lines) out += l + "\r\n";
    return out;
  }

  EpwFile read(std::size_t max_errors = 50) const {
    std::istringstream in(text());
    return read_epw(in, "t.epw", max_errors);
  }
};

/// The formatted messages ("file:line:col: error: ...", first line of each diagnostic) of a
/// failed read; empty if the read succeeded.
inline std::vector<std::string> error_lines(const SyntheticEpw& epw, std::size_t max_errors = 50) {
  std::vector<std::string> out;
  try {
    epw.read(max_errors);
  } catch (const InputError& e) {
    for (const Diagnostic& d : e.diagnostics()) {
      const std::string f = d.format();
      out.push_back(f.substr(0, f.find('\n')));
    }
  }
  return out;
}

}  // namespace dayphoton::weather::test
