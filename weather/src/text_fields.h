// Small text helpers shared by the weather readers (private to the weather library):
// strict, locale-independent number parsing (std::from_chars) and field splitting.
#pragma once

#include <charconv>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dayphoton::weather::detail {

inline std::string_view trim(std::string_view s) {
  const char* ws = " \t\r\n\f\v";
  const std::size_t b = s.find_first_not_of(ws);
  if (b == std::string_view::npos) return {};
  const std::size_t e = s.find_last_not_of(ws);
  return s.substr(b, e - b + 1);
}

/// A decimal number (optional sign, digits, optional fraction and exponent); no "inf",
/// "nan", hex or trailing characters. Surrounding blanks are ignored.
inline std::optional<double> parse_double(std::string_view text) {
  std::string_view s = trim(text);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return std::nullopt;
  const char c = s.front() == '-' && s.size() > 1 ? s[1] : s.front();
  if (!((c >= '0' && c <= '9') || c == '.')) return std::nullopt;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return value;
}

/// A decimal integer (optional sign, digits only), surrounding blanks ignored.
inline std::optional<int> parse_int(std::string_view text) {
  std::string_view s = trim(text);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return std::nullopt;
  int value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return value;
}

/// Split at every `sep` (no quoting); "a,,b" gives three fields.
inline std::vector<std::string_view> split(std::string_view line, char sep) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t pos = line.find(sep, start);
    if (pos == std::string_view::npos) {
      out.push_back(line.substr(start));
      return out;
    }
    out.push_back(line.substr(start, pos - start));
    start = pos + 1;
  }
}

/// Quote a field for a message, shortened if very long and with control bytes shown as '?'.
inline std::string quoted(std::string_view s) {
  std::string out = "'";
  const std::size_t n = s.size() > 40 ? 40 : s.size();
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    out += (c < 0x20 || c == 0x7f) ? '?' : static_cast<char>(c);
  }
  if (s.size() > n) out += "...";
  out += "'";
  return out;
}

/// Shortest text that reads back as `value` ("%.17g" trimmed), with at least
/// `min_decimals` digits after the point: format_number(2.0, 1) == "2.0".
std::string format_number(double value, int min_decimals);

/// Read all lines of a stream (without '\n' or a trailing '\r'; a UTF-8 byte order mark at
/// the start of the stream is dropped).
std::vector<std::string> read_lines(std::istream& in);

}  // namespace dayphoton::weather::detail
