// Test support: the numeric rows of a result CSV (daylight_factor.csv, point_in_time.csv,
// illuminance.csv), its header line set aside.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace dayphoton::test {

/// The rows of the CSV file at `path` below its header, every cell read as a number; the
/// header's column names into `header`.
inline std::vector<std::vector<double>> read_csv(const std::filesystem::path& path, std::vector<std::string>& header) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::stringstream h(line);
  header.clear();
  for (std::string cell; std::getline(h, cell, ',');) header.push_back(cell);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::vector<double> row;
    for (std::string cell; std::getline(s, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

inline std::vector<std::vector<double>> read_csv(const std::filesystem::path& path) {
  std::vector<std::string> header;
  return read_csv(path, header);
}

}  // namespace dayphoton::test
