// RadianceMatrix: a rows x columns matrix of RGB (NCOMP components) values in RADIANCE's
// matrix file format, as written by gendaymtx / rcontrib / rfluxmtx and read by dctimestep
// and rmtxop. Reference: ../shared/facts/sky-and-metrics.md section 6.1.
//
//   #?RADIANCE
//   <producing command line(s)>
//   NROWS=146
//   NCOLS=8760
//   NCOMP=3
//   FORMAT=ascii | float | double      (BigEndian=0|1 for the binary formats)
//   <empty line>
//   data, row-major: for each row, NCOLS elements of NCOMP values each
//
// Sky matrices: rows = patches (0 = ground), columns = time steps, values = radiance
// W/(sr m^2). Daylight-coefficient matrices: rows = sensors, columns = patches, values =
// irradiance per unit patch radiance (sr). Values are stored as float (what the format's
// binary variant carries and well below Monte Carlo noise).
#pragma once

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "dayphoton/core/resource_limits.h"

namespace dayphoton {

enum class MatrixFormat { Ascii, Float, Double };

/// What RadianceMatrix::read accepts beyond the format itself.
struct MatrixReadOptions {
  /// Most values NROWS x NCOLS x NCOMP (ResourceLimits::matrix_values).
  std::uint64_t max_values = ResourceLimits{}.matrix_values;
  /// How the user raises max_values, for the message ("--max-matrix-values").
  std::string max_values_raised_by = "--max-matrix-values";
  /// Bytes the stream holds from its first byte, if known (a regular file's size).
  std::optional<std::uint64_t> stream_bytes;
  /// Negative values are errors (sky radiances and daylight coefficients never are negative;
  /// in binary data they are the usual sign of the wrong byte order).
  bool non_negative = false;
};

class RadianceMatrix {
 public:
  RadianceMatrix() = default;
  RadianceMatrix(std::size_t rows, std::size_t columns, int components = 3);

  std::size_t rows() const { return m_rows; }
  std::size_t columns() const { return m_columns; }
  int components() const { return m_components; }

  float& at(std::size_t row, std::size_t column, int component) {
    return m_data[(row * m_columns + column) * m_components + component];
  }
  float at(std::size_t row, std::size_t column, int component) const {
    return m_data[(row * m_columns + column) * m_components + component];
  }
  const std::vector<float>& data() const { return m_data; }
  std::vector<float>& data() { return m_data; }

  /// Free-form header lines written after "#?RADIANCE" (command line, LATLONG=, ...).
  std::vector<std::string>& header_lines() { return m_header; }
  const std::vector<std::string>& header_lines() const { return m_header; }

  /// Write in RADIANCE format. Ascii: one "%g %g %g" element per line, an empty line after
  /// each row (as gendaymtx). Float/Double: native byte order declared with BigEndian=.
  void write(std::ostream& out, MatrixFormat format) const;
  /// Atomic write to a file.
  void write_file(const std::string& path, MatrixFormat format) const;

  /// Read any of ascii/float/double, either byte order. Every problem throws InputError
  /// located in the file: the header line; "file:line:column" and the element (row, column,
  /// component, counted from 0) for ascii data; the byte offset and the element for binary
  /// data. Rejected: values that are not numbers, NaN, infinities, values beyond the range
  /// of a float (|v| > 3.4e38), binary values that can only come from the wrong byte order
  /// (subnormal, or negative when options.non_negative), fewer or more values than
  /// NROWS x NCOLS x NCOMP, and more values than options.max_values. When the stream's size
  /// is known (options.stream_bytes; read_file sets it) the header's size is checked
  /// against it before anything is allocated; otherwise memory grows with the data present.
  static RadianceMatrix read(std::istream& in, const std::string& display_name,
                             const MatrixReadOptions& options);
  static RadianceMatrix read(std::istream& in, const std::string& display_name) {
    return read(in, display_name, MatrixReadOptions{});
  }
  /// read() on a regular file (a FIFO or device is refused; input_file.h), its size known.
  static RadianceMatrix read_file(const std::string& path, const MatrixReadOptions& options);
  static RadianceMatrix read_file(const std::string& path) { return read_file(path, MatrixReadOptions{}); }

 private:
  std::size_t m_rows = 0, m_columns = 0;
  int m_components = 3;
  std::vector<float> m_data;
  std::vector<std::string> m_header;
};

MatrixFormat parse_matrix_format(const std::string& name);  ///< "ascii" | "float" | "double"

}  // namespace dayphoton
