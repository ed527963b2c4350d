// Test support: reading the RADIANCE reference results in tests/data/radiance (README.md
// there), some of which are gzip-compressed (decompressed by zlib through dayphoton's
// GzipInput).
#pragma once

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "dayphoton/core/gzip_input.h"
#include "dayphoton/core/radiance_matrix.h"
#include "dayphoton/core/resource_limits.h"

namespace dayphoton::test {

/// Our gendaymtx-compatible sky matrices agree with gendaymtx's within this relative
/// difference on every element above 1 % of its hour's maximum (gendaymtx prints 3
/// significant digits, up to 0.5 % rounding): asserted by tests/sky/sky_matrix_test.cpp, and
/// the base of the DA300 bound in tests/study/annual_study_test.cpp.
constexpr double GendaymtxElementTolerance = 0.01;

/// A gzip-compressed RADIANCE matrix (e.g. gendaymtx output).
inline RadianceMatrix read_gzip_matrix(const std::string& path) {
  GzipInput in(path, ResourceLimits{}.decompressed_bytes, "reference file", "the test");
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
