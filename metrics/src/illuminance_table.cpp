#include "dayphoton/metrics/illuminance_table.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "dayphoton/core/diagnostics.h"

namespace dayphoton::metrics {

namespace {
std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}
}  // namespace

IlluminanceTable read_illuminance_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(SourceLocation{path, 0, 0}, "cannot open illuminance table");
  std::string line;
  if (!std::getline(in, line)) throw InputError(SourceLocation{path, 1, 0}, "empty file");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const auto header = split_commas(line);
  if (header.size() < 4 || header[0] != "month" || header[1] != "day" || header[2] != "hour")
    throw InputError(SourceLocation{path, 1, 1}, "expected the header 'month,day,hour,<sensors...>'", line);
  const std::size_t sensors = header.size() - 3;

  std::vector<TimeStamp> steps;
  std::vector<float> values;
  int line_number = 1;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const auto fields = split_commas(line);
    if (fields.size() != header.size())
      throw InputError(SourceLocation{path, line_number, 0},
                       "expected " + std::to_string(header.size()) + " fields, found " +
                           std::to_string(fields.size()),
                       line);
    double numbers[3];
    for (std::size_t f = 0; f < fields.size(); ++f) {
      char* end = nullptr;
      const double v = std::strtod(fields[f].c_str(), &end);
      if (fields[f].empty() || *end != '\0')
        throw InputError(SourceLocation{path, line_number, static_cast<int>(f + 1)},
                         "field " + std::to_string(f + 1) + " (" + header[f] + ") is not a number: '" +
                             fields[f] + "'",
                         line);
      if (f < 3) numbers[f] = v;
      else values.push_back(static_cast<float>(v));
    }
    steps.push_back({static_cast<int>(numbers[0]), static_cast<int>(numbers[1]), numbers[2]});
  }
  IlluminanceTable table(steps, sensors);
  for (std::size_t s = 0; s < steps.size(); ++s)
    for (std::size_t k = 0; k < sensors; ++k) table.lux(s, k) = values[s * sensors + k];
  return table;
}

}  // namespace dayphoton::metrics
