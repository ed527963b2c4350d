// Test support: reading the RADIANCE reference results in tests/data/radiance (README.md
// there), some of which are gzip-compressed (decompressed with the system's gzip).
#pragma once

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"

namespace dayphoton::test {

/// Our gendaymtx-compatible sky matrices agree with gendaymtx's within this relative
/// difference on every element above 1 % of its hour's maximum (gendaymtx prints 3
/// significant digits, up to 0.5 % rounding): asserted by tests/sky/sky_matrix_test.cpp, and
/// the base of the DA300 bound in tests/study/annual_study_test.cpp.
constexpr double GendaymtxElementTolerance = 0.01;

/// The whole decompressed text of a .gz file; throws if gzip cannot read it.
inline std::string read_gzip_text(const std::string& path) {
  FILE* pipe = popen(("gzip -dc '" + path + "'").c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot run gzip on " + path);
  std::string text;
  char buffer[1 << 16];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) text.append(buffer, n);
  if (pclose(pipe) != 0) throw std::runtime_error("gzip failed on " + path);
  return text;
}

/// A gzip-compressed RADIANCE matrix (e.g. gendaymtx output).
inline RadianceMatrix read_gzip_matrix(const std::string& path) {
  std::istringstream in(read_gzip_text(path));
  return RadianceMatrix::read(in, path);
}

/// rtrace's overcast daylight factor per sensor, % (refdata a_daylight_factor/df_office.csv,
/// column DF_main_pct, the 6th), in the order of sensors/grid_0p8m.pts.
inline std::vector<double> read_reference_df(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::string line;
  std::getline(in, line);  // header
  std::vector<double> df;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string field;
    for (int i = 0; i < 6 && std::getline(ss, field, ','); ++i) {
    }
    df.push_back(std::stod(field));
  }
  return df;
}

}  // namespace dayphoton::test
