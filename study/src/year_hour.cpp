// "M/D/H" times of the weather year; see year_hour.h.
#include "dayphoton/study/year_hour.h"

#include <sstream>
#include <stdexcept>

namespace dayphoton::study {

std::string YearHour::text() const {
  std::ostringstream s;
  s << month << '/' << day << '/' << hour;
  return s.str();
}

YearHour parse_year_hour(const std::string& text) {
  YearHour h;
  std::istringstream in(text);
  char s1 = 0, s2 = 0;
  if (!(in >> h.month >> s1 >> h.day >> s2 >> h.hour) || s1 != '/' || s2 != '/' || !in.eof() ||
      h.month < 1 || h.month > 12 || h.day < 1 || h.day > 31 || !(h.hour > 0) || h.hour > 24)
    throw std::invalid_argument("expected M/D/H (month 1-12, day 1-31, hour of local standard time in (0, 24]), not '" +
                                text + "'");
  return h;
}

}  // namespace dayphoton::study
