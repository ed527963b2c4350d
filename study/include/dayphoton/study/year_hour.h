// A time of the weather year written "M/D/H" (`dayphoton report --sky-hour`, `render --sky`).
#pragma once

#include <string>

namespace dayphoton::study {

/// A time of the weather year, "M/D/H": month, day, hour of local standard time (decimal).
/// The record is the one whose interval (h - 1, h] contains H (EPW hour h), so "6/21/12.5"
/// is the record stamped 12.5 (EPW hour 13).
struct YearHour {
  int month = 6, day = 21;
  double hour = 12.5;
  std::string text() const;  ///< "6/21/12.5"
};

/// Throws std::invalid_argument for bad text.
YearHour parse_year_hour(const std::string& text);

}  // namespace dayphoton::study
