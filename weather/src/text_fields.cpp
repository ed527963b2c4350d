// Shared text helpers of the weather readers and writers (see text_fields.h).
#include "text_fields.h"

#include <cmath>
#include <cstdio>
#include <istream>

namespace dayphoton::weather::detail {

std::string format_number(double value, int min_decimals) {
  if (!std::isfinite(value)) return "nan";
  char buffer[64];
  for (int decimals = min_decimals; decimals <= 17; ++decimals) {
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    const std::optional<double> back = parse_double(buffer);
    if (back && *back == value) break;
  }
  std::string text = buffer;
  if (text == "-0" || text.rfind("-0.", 0) == 0) {
    // Print a zero as "0", never "-0".
    bool all_zero = true;
    for (char c : text.substr(1)) all_zero = all_zero && (c == '0' || c == '.');
    if (all_zero) text.erase(0, 1);
  }
  return text;
}

std::vector<std::string> read_lines(std::istream& in) {
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    // A UTF-8 byte order mark, written by some Windows editors, is not part of the first line.
    if (lines.empty() && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace dayphoton::weather::detail
