// SparseSunRows: a grid's exact direct sun (sensors x suns, one component: the luminance
// form of direct_sun_coefficients, annual_sun.h) held by its non-zero values, row by row
// (compressed sparse rows). Most (sensor, sun) pairs of a deep room see no sun at all (the
// sun reaches a strip behind the windows), so the annual phase holds 8 bytes per sunlit pair
// instead of 4 bytes per pair (docs/photon-tracing.md "Scale").
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dayphoton/core/radiance_matrix.h"

namespace dayphoton::study {

struct SparseSunRows {
  std::size_t rows = 0, columns = 0;
  std::vector<std::uint64_t> row_start;  ///< rows + 1 offsets into column and value
  std::vector<std::uint32_t> column;     ///< ascending within a row
  std::vector<float> value;              ///< never 0

  /// The non-zero values of a one-component matrix, exactly. Throws std::invalid_argument for
  /// another component count or more than 2^32 columns.
  static SparseSunRows of(const RadianceMatrix& dense);

  /// Bytes held by the three arrays.
  std::size_t bytes() const;
};

}  // namespace dayphoton::study
