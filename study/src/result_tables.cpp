// Per-sensor result tables read back from disk; see result_tables.h.
#include "dayphoton/study/result_tables.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/input_file.h"

namespace dayphoton::study {

int SensorTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return static_cast<int>(i);
  return -1;
}

std::vector<double> SensorTable::values(const std::string& name) const {
  const int c = column(name);
  if (c < 0) throw std::out_of_range(path + ": no column '" + name + "'");
  std::vector<double> out;
  out.reserve(rows.size());
  for (const auto& row : rows) out.push_back(row[static_cast<std::size_t>(c)]);
  return out;
}

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return fields;
}

}  // namespace

SensorTable read_sensor_table(const std::string& path) {
  std::ifstream in = open_input_file(path, "result table");
  SensorTable table;
  table.path = path;
  std::string line;
  if (!std::getline(in, line)) throw InputError(SourceLocation{path, 1, 0}, "empty file, expected a header");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  table.columns = split(line);
  if (table.columns.size() < 4 || table.columns[0] != "index" || table.columns[1] != "x" ||
      table.columns[2] != "y" || table.columns[3] != "z")
    throw InputError(SourceLocation{path, 1, 1}, "expected a header starting with 'index,x,y,z'", line);
  int line_number = 1;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::vector<std::string> fields = split(line);
    if (fields.size() != table.columns.size())
      throw InputError(SourceLocation{path, line_number, 1},
                       "expected " + std::to_string(table.columns.size()) + " fields, found " +
                           std::to_string(fields.size()),
                       line);
    std::vector<double> row(fields.size());
    int column_number = 1;
    for (std::size_t f = 0; f < fields.size(); ++f) {
      const std::string& s = fields[f];
      const auto r = std::from_chars(s.data(), s.data() + s.size(), row[f]);
      if (r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(row[f]))
        throw InputError(SourceLocation{path, line_number, column_number},
                         "'" + table.columns[f] + "' is not a finite number: '" + s + "'", line);
      column_number += static_cast<int>(s.size()) + 1;
    }
    if (row[0] != static_cast<double>(table.rows.size()))
      throw InputError(SourceLocation{path, line_number, 1},
                       "index " + fields[0] + " out of sequence (expected " + std::to_string(table.rows.size()) + ")",
                       line);
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace dayphoton::study
