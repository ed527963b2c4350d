#include "dayphoton/core/radiance_matrix.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
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
    // Subnormal floats (|v| < 1.2e-38) carry no information at 7 digits and would read as
    // byte-swapped data (read()): they are written as 0.
    const auto subnormal = [](float v) { return v != 0 && std::fpclassify(v) == FP_SUBNORMAL; };
    if (std::none_of(m_data.begin(), m_data.end(), subnormal)) {
      out.write(reinterpret_cast<const char*>(m_data.data()),
                static_cast<std::streamsize>(m_data.size() * sizeof(float)));
    } else {
      std::vector<float> flushed(m_data);
      for (float& v : flushed) v = subnormal(v) ? 0.0f : v;
      out.write(reinterpret_cast<const char*>(flushed.data()),
                static_cast<std::streamsize>(flushed.size() * sizeof(float)));
    }
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

namespace {

// A header longer than this is not a RADIANCE matrix header (gendaymtx's and rfluxmtx's are
// a few hundred bytes); the cap keeps a binary file without newlines from being read whole
// as one "line".
constexpr std::size_t MaxHeaderBytes = 1 << 20;
// Longest ascii number token ("-1.234567890123456789e-308" is 26 characters).
constexpr std::size_t MaxTokenChars = 64;
// Characters of an ascii data line kept for the echo under an error.
constexpr std::size_t MaxEchoChars = 200;

/// One header line (without '\n') read with a cap on the header's total size; false at the
/// end of the stream with nothing read.
bool read_header_line(std::istream& in, std::string& line, std::uint64_t& header_bytes, bool& too_long) {
  line.clear();
  std::streambuf* buf = in.rdbuf();
  for (;;) {
    const int c = buf->sbumpc();
    if (c == std::char_traits<char>::eof()) {
      in.setstate(std::ios::eofbit);
      return !line.empty();
    }
    ++header_bytes;
    if (c == '\n') return true;
    if (header_bytes > MaxHeaderBytes) {
      too_long = true;
      return true;
    }
    line.push_back(static_cast<char>(c));
  }
}

std::string element_text(std::size_t index, std::size_t columns, int components) {
  const std::size_t per_row = columns * static_cast<std::size_t>(components);
  return "row " + std::to_string(index / per_row) + ", column " +
         std::to_string(index % per_row / static_cast<std::size_t>(components)) + ", component " +
         std::to_string(index % static_cast<std::size_t>(components)) + " (counted from 0)";
}

/// What is wrong with a value, or "" if nothing: not finite, beyond float, negative.
std::string value_problem(double v, bool non_negative) {
  if (std::isnan(v)) return "NaN";
  if (std::isinf(v)) return "an infinite value";
  if (std::fabs(v) > static_cast<double>(std::numeric_limits<float>::max()))
    return "value " + format_number(v) + " beyond the range of a float (3.4e38)";
  if (non_negative && v < 0) return "negative value " + format_number(v);
  return {};
}

/// Reads ascii values one character at a time (no whole lines: a file of one endless line
/// must not be read into memory), keeping the line and column of each token and the start
/// of the current line for the echo under an error.
class AsciiScanner {
 public:
  AsciiScanner(std::istream& in, int first_line) : m_buf(in.rdbuf()), m_line(first_line) {}

  /// The next whitespace-separated token; false at the end of the stream.
  bool next(std::string& token, int& line, int& column) {
    token.clear();
    int c = skip_space();
    if (c == std::char_traits<char>::eof()) return false;
    line = m_line;
    column = m_column + 1;
    while (c != std::char_traits<char>::eof() && !std::isspace(c)) {
      if (token.size() <= MaxTokenChars) token.push_back(static_cast<char>(c));
      take(c);
      c = m_buf->sgetc();
    }
    return true;
  }

  /// The current line, as far as it goes within MaxEchoChars (reads up to its end).
  std::string echo_line() {
    for (int c = m_buf->sgetc(); c != std::char_traits<char>::eof() && c != '\n' && m_text.size() < MaxEchoChars;
         c = m_buf->sgetc())
      take(c);
    std::string text = m_text;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    return text;
  }

  int line() const { return m_line; }

 private:
  int skip_space() {
    int c = m_buf->sgetc();
    while (c != std::char_traits<char>::eof() && std::isspace(c)) {
      take(c);
      c = m_buf->sgetc();
    }
    return c;
  }
  void take(int c) {
    m_buf->sbumpc();
    if (c == '\n') {
      ++m_line;
      m_column = 0;
      m_text.clear();
    } else {
      ++m_column;
      if (m_text.size() < MaxEchoChars) m_text.push_back(static_cast<char>(c));
    }
  }

  std::streambuf* m_buf;
  int m_line;
  int m_column = 0;
  std::string m_text;
};

template <typename T>
bool is_subnormal(T v) {
  return v != 0 && std::fpclassify(v) == FP_SUBNORMAL;
}

/// Binary values of type T (float or double), checked one by one.
template <typename T>
void read_binary_values(std::istream& in, const std::string& display_name, std::uint64_t header_bytes,
                        std::size_t count, std::size_t columns, int components, bool swap, bool big_endian,
                        const MatrixReadOptions& options, std::vector<float>& data) {
  constexpr std::size_t Chunk = 1 << 16;
  std::vector<T> chunk(Chunk);
  std::size_t done = 0;
  while (done < count) {
    const std::size_t n = std::min(Chunk, count - done);
    in.read(reinterpret_cast<char*>(chunk.data()), static_cast<std::streamsize>(n * sizeof(T)));
    const std::size_t got = static_cast<std::size_t>(in.gcount()) / sizeof(T);
    for (std::size_t i = 0; i < got; ++i) {
      const T raw = chunk[i];
      const T v = swap ? byte_swapped(raw) : raw;
      std::string problem = value_problem(static_cast<double>(v), options.non_negative);
      if (problem.empty() && is_subnormal(v)) problem = "subnormal value " + format_number(static_cast<double>(v));
      if (!problem.empty()) {
        const std::size_t index = done + i;
        std::string message = problem + " at byte " + std::to_string(header_bytes + index * sizeof(T)) + ", in " +
                              element_text(index, columns, components);
        // The other byte order: if it makes a plausible value, the header's BigEndian= (or its
        // absence, meaning this machine's order) is wrong.
        const T other = swap ? raw : byte_swapped(raw);
        if (value_problem(static_cast<double>(other), options.non_negative).empty() && !is_subnormal(other))
          message += "; in the other byte order it reads " + format_number(static_cast<double>(other)) +
                     ", so the data look byte-swapped (the header says BigEndian=" + (big_endian ? "1" : "0") + ")";
        throw InputError(SourceLocation{display_name, 0, 0}, message);
      }
      data.push_back(static_cast<float>(v));
    }
    done += got;
    if (got < n)
      throw InputError(SourceLocation{display_name, 0, 0},
                       "truncated binary matrix data: " + std::to_string(done) + " of " + std::to_string(count) +
                           " values present");
  }
  if (in.rdbuf()->sgetc() != std::char_traits<char>::eof())
    throw InputError(SourceLocation{display_name, 0, 0},
                     "data after the NROWS x NCOLS x NCOMP = " + std::to_string(count) + " values, at byte " +
                         std::to_string(header_bytes + count * sizeof(T)));
}

}  // namespace

RadianceMatrix RadianceMatrix::read(std::istream& in, const std::string& display_name,
                                    const MatrixReadOptions& options) {
  auto fail = [&](int line, const std::string& message, const std::string& text = {}) {
    throw InputError(SourceLocation{display_name, line, 0}, message, text);
  };
  std::string line;
  int line_number = 0;
  std::uint64_t header_bytes = 0;
  bool too_long = false;
  auto next_header_line = [&]() {
    if (!read_header_line(in, line, header_bytes, too_long)) return false;
    ++line_number;
    if (too_long) fail(line_number, "the header is longer than " + std::to_string(MaxHeaderBytes) + " bytes: not a RADIANCE matrix");
    return true;
  };
  if (!next_header_line()) fail(1, "empty file: expected a RADIANCE matrix header");
  if (trim(line) != "#?RADIANCE")
    fail(1, "not a RADIANCE matrix: the first line must be '#?RADIANCE'", line.substr(0, MaxEchoChars));

  long long rows = -1, columns = -1, components = 3;
  MatrixFormat format = MatrixFormat::Ascii;
  int big_endian = native_big_endian() ? 1 : 0;
  std::vector<std::string> header;
  bool ended = false;
  while (next_header_line()) {
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

  // Sizes before any allocation: the limit, then what the stream can hold.
  const std::uint64_t max_values = options.max_values;
  const std::uint64_t r = static_cast<std::uint64_t>(rows), c = static_cast<std::uint64_t>(columns),
                      k = static_cast<std::uint64_t>(components);
  const std::string shape = "NROWS x NCOLS x NCOMP = " + std::to_string(rows) + " x " + std::to_string(columns) +
                            " x " + std::to_string(components);
  const std::string over_limit = shape + " values is " + over_limit_text(max_values, options.max_values_raised_by);
  std::uint64_t count64 = 0;
  // Beyond 2^60 values no file holds the data and the byte counts below would overflow.
  if (__builtin_mul_overflow(r, c, &count64) || __builtin_mul_overflow(count64, k, &count64) ||
      count64 > (std::uint64_t(1) << 60))
    fail(line_number, over_limit);
  const std::size_t count = static_cast<std::size_t>(count64);
  // What the file holds first: a small file claiming a huge size is truncated, whatever the
  // limit says.
  if (options.stream_bytes) {
    const std::uint64_t data_bytes = *options.stream_bytes > header_bytes ? *options.stream_bytes - header_bytes : 0;
    const std::string held = "the file holds " + std::to_string(data_bytes) + " bytes after its header";
    if (format == MatrixFormat::Ascii) {
      // Every ascii value takes a digit and a separator (the last one's may be missing).
      if (count > 0 && data_bytes < 2 * static_cast<std::uint64_t>(count) - 1)
        fail(line_number, "truncated matrix: " + shape + " = " + std::to_string(count) +
                              " ascii values need at least " + std::to_string(2 * count - 1) + " bytes, but " + held);
    } else {
      const std::uint64_t need = count * (format == MatrixFormat::Float ? sizeof(float) : sizeof(double));
      if (data_bytes < need)
        fail(line_number, "truncated binary matrix data: " + shape + " values take " + std::to_string(need) +
                              " bytes, but " + held);
      if (data_bytes > need)
        fail(line_number, "data after the " + shape + " values: they take " + std::to_string(need) + " bytes, but " +
                              held);
    }
  }

  if (count64 > max_values) fail(line_number, over_limit);

  RadianceMatrix m;
  m.m_rows = static_cast<std::size_t>(rows);
  m.m_columns = static_cast<std::size_t>(columns);
  m.m_components = static_cast<int>(components);
  m.m_header = std::move(header);
  // With the size checked, all at once; otherwise as the data arrive (a compressed stream
  // claiming a huge size must not allocate before it delivers).
  m.m_data.reserve(options.stream_bytes ? count : std::min<std::size_t>(count, std::size_t(1) << 20));
  if (format == MatrixFormat::Ascii) {
    AsciiScanner scan(in, line_number + 1);
    std::string token;
    int token_line = 0, token_column = 0;
    auto fail_at = [&](const std::string& message) {
      throw InputError(SourceLocation{display_name, token_line, token_column}, message, scan.echo_line());
    };
    while (m.m_data.size() < count && scan.next(token, token_line, token_column)) {
      const std::size_t index = m.m_data.size();
      char* end = nullptr;
      const double v = token.size() > MaxTokenChars ? 0.0 : std::strtod(token.c_str(), &end);
      if (token.size() > MaxTokenChars || end == token.c_str() || *end != '\0')
        fail_at("not a number: '" + token.substr(0, MaxTokenChars) + (token.size() > MaxTokenChars ? "...'" : "'") +
                " in " + element_text(index, m.m_columns, m.m_components));
      const std::string problem = value_problem(v, options.non_negative);
      if (!problem.empty()) fail_at(problem + " in " + element_text(index, m.m_columns, m.m_components));
      m.m_data.push_back(static_cast<float>(v));
    }
    if (m.m_data.size() < count)
      fail(scan.line(), "truncated matrix: " + std::to_string(m.m_data.size()) + " of " + std::to_string(count) +
                            " values present");
    if (scan.next(token, token_line, token_column))
      fail_at("data after the " + shape + " = " + std::to_string(count) + " values");
  } else {
    const bool swap = (big_endian != 0) != native_big_endian();
    if (format == MatrixFormat::Float)
      read_binary_values<float>(in, display_name, header_bytes, count, m.m_columns, m.m_components, swap,
                                big_endian != 0, options, m.m_data);
    else
      read_binary_values<double>(in, display_name, header_bytes, count, m.m_columns, m.m_components, swap,
                                 big_endian != 0, options, m.m_data);
  }
  return m;
}

RadianceMatrix RadianceMatrix::read_file(const std::string& path, const MatrixReadOptions& options) {
  std::ifstream in = open_input_file(path, "matrix file");
  MatrixReadOptions sized = options;
  std::uint64_t size = 0;
  if (input_file_size(path, size)) sized.stream_bytes = size;
  return read(in, path, sized);
}

}  // namespace dayphoton
