// SparseSunRows: see sparse_sun_rows.h.
#include "dayphoton/study/sparse_sun_rows.h"

#include <stdexcept>
#include <string>

namespace dayphoton::study {

SparseSunRows SparseSunRows::of(const RadianceMatrix& dense) {
  if (dense.components() != 1)
    throw std::invalid_argument("sparse sun rows: a matrix of " + std::to_string(dense.components()) +
                                " components (one expected)");
  if (dense.columns() > 0xffffffffu) throw std::invalid_argument("sparse sun rows: more than 2^32 columns");
  SparseSunRows s;
  s.rows = dense.rows();
  s.columns = dense.columns();
  const float* data = dense.data().data();
  std::size_t non_zero = 0;
  for (std::size_t i = 0; i < s.rows * s.columns; ++i) non_zero += data[i] != 0.0f ? 1 : 0;
  s.row_start.reserve(s.rows + 1);
  s.column.reserve(non_zero);
  s.value.reserve(non_zero);
  s.row_start.push_back(0);
  for (std::size_t r = 0; r < s.rows; ++r) {
    const float* row = data + r * s.columns;
    for (std::size_t c = 0; c < s.columns; ++c)
      if (row[c] != 0.0f) {
        s.column.push_back(static_cast<std::uint32_t>(c));
        s.value.push_back(row[c]);
      }
    s.row_start.push_back(s.column.size());
  }
  return s;
}

std::size_t SparseSunRows::bytes() const {
  return row_start.size() * sizeof(std::uint64_t) + column.size() * sizeof(std::uint32_t) +
         value.size() * sizeof(float);
}

}  // namespace dayphoton::study
