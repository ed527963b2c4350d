// Test support: reading the RADIANCE reference results in ../shared/refdata, some of which
// are gzip-compressed (decompressed by zlib through dayphoton's GzipInput).
// Tests skip themselves when ../shared is absent (a user's clone), see each caller.
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
