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
#include <iosfwd>
#include <string>
#include <vector>

namespace dayphoton {

enum class MatrixFormat { Ascii, Float, Double };

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

  /// Read any of ascii/float/double, either byte order. Errors throw InputError located at
  /// the header line or the element index ("file:line" for ascii data).
  static RadianceMatrix read(std::istream& in, const std::string& display_name);
  static RadianceMatrix read_file(const std::string& path);

 private:
  std::size_t m_rows = 0, m_columns = 0;
  int m_components = 3;
  std::vector<float> m_data;
  std::vector<std::string> m_header;
};

MatrixFormat parse_matrix_format(const std::string& name);  ///< "ascii" | "float" | "double"

}  // namespace dayphoton
