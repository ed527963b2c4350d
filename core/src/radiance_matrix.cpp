#include "dayphoton/core/radiance_matrix.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "dayphoton/core/atomic_file.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/input_file.h"

namespace dayphoton {

namespace {

bool native_big_endian() {
  const std::uint16_t probe = 1;
  unsigned char first;
  std::memcpy(&first, &probe, 1);
  return first == 0;
}

template <typename T>
T byte_swapped(T value) {
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
  std::memcpy(&value, bytes, sizeof(T));
  return value;
}

const char* format_name(MatrixFormat f) {
  switch (f) {
    case MatrixFormat::Ascii: return "ascii";
    case MatrixFormat::Float: return "float";
    case MatrixFormat::Double: return "double";
  }
  return "ascii";
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

}  // namespace

RadianceMatrix::RadianceMatrix(std::size_t rows, std::size_t columns, int components)
    : m_rows(rows), m_columns(columns), m_components(components),
      m_data(rows * columns * static_cast<std::size_t>(components), 0.0f) {}

MatrixFormat parse_matrix_format(const std::string& name) {
  if (name == "ascii") return MatrixFormat::Ascii;
  if (name == "float") return MatrixFormat::Float;
  if (name == "double") return MatrixFormat::Double;
  throw std::invalid_argument("unknown matrix format '" + name + "' (expected ascii, float or double)");
}

void RadianceMatrix::write(std::ostream& out, MatrixFormat format) const {
  out << "#?RADIANCE\n";
  for (const auto& line : m_header) out << line << '\n';
  out << "NROWS=" << m_rows << "\nNCOLS=" << m_columns << "\nNCOMP=" << m_components << '\n';
  if (format != MatrixFormat::Ascii) out << "BigEndian=" << (native_big_endian() ? 1 : 0) << '\n';
  out << "FORMAT=" << format_name(format) << "\n\n";
  if (format == MatrixFormat::Ascii) {
    char buf[64];
    for (std::size_t r = 0; r < m_rows; ++r) {
      for (std::size_t c = 0; c < m_columns; ++c) {
        for (int k = 0; k < m_components; ++k) {
          // %.7g round-trips every float value that matters here to 1e-7 relative.
          std::snprintf(buf, sizeof buf, k == 0 ? "%.7g" : " %.7g", static_cast<double>(at(r, c, k)));
          out << buf;
        }
        out << '\n';
      }
      if (m_columns > 1) out << '\n';
    }
  } else if (format == MatrixFormat::Float) {
    out.write(reinterpret_cast<const char*>(m_data.data()),
              static_cast<std::streamsize>(m_data.size() * sizeof(float)));
  } else {
    std::vector<double> wide(m_data.begin(), m_data.end());
    out.write(reinterpret_cast<const char*>(wide.data()),
              static_cast<std::streamsize>(wide.size() * sizeof(double)));
  }
}

void RadianceMatrix::write_file(const std::string& path, MatrixFormat format) const {
  write_file_atomically(path, [&](std::ostream& out) { write(out, format); },
                        format != MatrixFormat::Ascii);
}

RadianceMatrix RadianceMatrix::read(std::istream& in, const std::string& display_name) {
  auto fail = [&](int line, const std::string& message, const std::string& text = {}) {
    throw InputError(SourceLocation{display_name, line, 0}, message, text);
  };
  std::string line;
  int line_number = 0;
  if (!std::getline(in, line)) fail(1, "empty file: expected a RADIANCE matrix header");
  ++line_number;
  if (trim(line) != "#?RADIANCE")
    fail(1, "not a RADIANCE matrix: the first line must be '#?RADIANCE'", line);

  long long rows = -1, columns = -1, components = 3;
  MatrixFormat format = MatrixFormat::Ascii;
  int big_endian = native_big_endian() ? 1 : 0;
  std::vector<std::string> header;
  bool ended = false;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string t = trim(line);
    if (t.empty()) {
      ended = true;
      break;
    }
    auto value_of = [&](const char* key) -> std::string { return trim(t.substr(std::strlen(key))); };
    auto integer = [&](const char* key) -> long long {
      try {
        std::size_t used = 0;
        const long long v = std::stoll(value_of(key), &used);
        if (used != value_of(key).size() || v < 0) throw std::invalid_argument("");
        return v;
      } catch (const std::exception&) {
        fail(line_number, std::string("expected a non-negative integer after ") + key, line);
      }
      return 0;
    };
    if (t.rfind("NROWS=", 0) == 0) rows = integer("NROWS=");
    else if (t.rfind("NCOLS=", 0) == 0) columns = integer("NCOLS=");
    else if (t.rfind("NCOMP=", 0) == 0) components = integer("NCOMP=");
    else if (t.rfind("BigEndian=", 0) == 0) {
      big_endian = static_cast<int>(integer("BigEndian="));
      if (big_endian > 1) fail(line_number, "BigEndian= must be 0 or 1", line);
    }
    else if (t.rfind("FORMAT=", 0) == 0) {
      const std::string f = value_of("FORMAT=");
      try {
        format = parse_matrix_format(f);
      } catch (const std::invalid_argument&) {
        fail(line_number, "unsupported matrix FORMAT '" + f + "' (ascii, float or double)", line);
      }
    } else {
      header.push_back(line);
    }
  }
  if (!ended) fail(line_number, "the header does not end with an empty line");
  if (rows < 0 || columns < 0) fail(line_number, "the header lacks NROWS= or NCOLS=");
  if (components < 1 || components > 64) fail(line_number, "NCOMP must be between 1 and 64");

  // Guard the allocation: a corrupt header must give a located error, not an overflow or an
  // out-of-memory abort. 2^31 elements (8 GiB of floats) is far beyond any daylight matrix.
  constexpr long long MaxElements = 1LL << 31;
  if (rows > 0 && (columns > MaxElements / rows || rows * columns > MaxElements / components))
    fail(line_number, "NROWS x NCOLS x NCOMP is implausibly large (more than 2^31 values)");
  RadianceMatrix m(static_cast<std::size_t>(rows), static_cast<std::size_t>(columns),
                   static_cast<int>(components));
  m.m_header = std::move(header);
  const std::size_t count = m.m_data.size();
  if (format == MatrixFormat::Ascii) {
    std::size_t i = 0;
    while (i < count && std::getline(in, line)) {
      ++line_number;
      std::istringstream fields(line);
      std::string token;
      while (fields >> token) {
        if (i == count) fail(line_number, "more values than NROWS x NCOLS x NCOMP", line);
        char* end = nullptr;
        const double v = std::strtod(token.c_str(), &end);
        if (end == token.c_str() || *end != '\0') fail(line_number, "not a number: '" + token + "'", line);
        m.m_data[i++] = static_cast<float>(v);
      }
    }
    if (i < count)
      fail(line_number, "truncated matrix: " + std::to_string(i) + " of " + std::to_string(count) +
                            " values present");
  } else {
    const bool swap = (big_endian != 0) != native_big_endian();
    if (format == MatrixFormat::Float) {
      in.read(reinterpret_cast<char*>(m.m_data.data()), static_cast<std::streamsize>(count * sizeof(float)));
      if (static_cast<std::size_t>(in.gcount()) != count * sizeof(float))
        fail(line_number, "truncated binary matrix data");
      if (swap)
        for (float& v : m.m_data) v = byte_swapped(v);
    } else {
      std::vector<double> wide(count);
      in.read(reinterpret_cast<char*>(wide.data()), static_cast<std::streamsize>(count * sizeof(double)));
      if (static_cast<std::size_t>(in.gcount()) != count * sizeof(double))
        fail(line_number, "truncated binary matrix data");
      for (std::size_t i = 0; i < count; ++i) m.m_data[i] = static_cast<float>(swap ? byte_swapped(wide[i]) : wide[i]);
    }
  }
  return m;
}

RadianceMatrix RadianceMatrix::read_file(const std::string& path) {
  std::ifstream in = open_input_file(path, "matrix file");
  return read(in, path);
}

}  // namespace dayphoton
