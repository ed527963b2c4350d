#include "occupancy_csv.h"

#include <sstream>

#include "text_tokens.h"

namespace dayphoton::project {

std::vector<bool> read_occupancy_csv_text(const std::string& text, const std::string& path, Diagnostics& diag) {
  std::vector<bool> values;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  bool any_content = false;
  const std::size_t errors_before = diag.error_count();
  while (std::getline(in, line) && !diag.at_cap()) {
    ++line_no;
    if (values.empty() && diag.error_count() - errors_before >= detail::MaxErrorsBeforeValidLine) {
      diag.error({path, line_no, 0}, "stopping after " + std::to_string(detail::MaxErrorsBeforeValidLine) +
                                         " errors and no valid line: is this an occupancy schedule (0 or 1 per line)?");
      break;
    }
    if (!line.empty() && line.back() == '\r') line.pop_back();
    // Commas separate fields: "1," has two (the second empty).
    std::string spaced = line;
    for (char& c : spaced)
      if (c == ',') c = ' ';
    const std::vector<detail::Token> tokens = detail::tokenize(spaced);
    const bool has_comma = line.find(',') != std::string::npos && line.find(',') < line.find('#');
    if (tokens.empty() && !has_comma) continue;
    const bool first = !any_content;
    any_content = true;
    if (tokens.size() != 1 || has_comma) {
      const std::size_t comma = line.find(',');
      const int column = has_comma ? static_cast<int>(comma) + 1 : tokens.empty() ? 1 : tokens[0].column;
      diag.error({path, line_no, column},
                 "expected one value per line (1 occupied, 0 not), found " +
                     std::to_string(has_comma ? std::max<std::size_t>(2, tokens.size()) : tokens.size()) + " fields",
                 line);
      continue;
    }
    double v = 0;
    const detail::NumberStatus status = detail::parse_number(tokens[0].text, v);
    if (status == detail::NumberStatus::NotANumber && first) continue;  // a header
    if (status != detail::NumberStatus::Ok) {
      diag.error({path, line_no, tokens[0].column},
                 "expected 0 or 1, found '" + detail::quoted_token(tokens[0].text) + "'", line);
      continue;
    }
    if (v != 0 && v != 1) {
      diag.error({path, line_no, tokens[0].column},
                 "occupancy must be 0 or 1, found " + format_number(v) +
                     (v > 0 && v < 1 ? " (a fraction: the metrics count whole occupied hours; round or threshold "
                                       "the schedule first)"
                                     : ""),
                 line);
      continue;
    }
    if (values.size() == MaxOccupancyValues) {
      diag.error({path, line_no, tokens[0].column},
                 "more than " + std::to_string(MaxOccupancyValues) + " values (a leap year of one-minute records)",
                 line);
      break;
    }
    values.push_back(v == 1);
  }
  if (values.empty() && !diag.has_errors()) diag.error({path, line_no > 0 ? 1 : 0, 0}, "no values in the occupancy schedule");
  return values;
}

}  // namespace dayphoton::project
