// Splitting a line of a plain-text geometry file (OBJ, .pts) into blank-separated tokens
// that remember their 1-based column, and strict number parsing, so that readers can
// place a caret under the offending token.
#pragma once

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace dayphoton::project::detail {

/// A text input file (OBJ, .pts) whose first this many lines with content are all errors is
/// not that kind of file (/etc/passwd named as a .pts): its reader stops there, so that the
/// messages echo no more than this many of its lines. (A file with valid lines is read on,
/// up to the diagnostics' cap, so that every mistake in a real file is shown.)
constexpr std::size_t MaxErrorsBeforeValidLine = 5;

/// Longest token quoted in a message ("found 'root:x:0:0:...'").
constexpr std::size_t MaxQuotedChars = 40;

/// `text` for a message: at most MaxQuotedChars characters, "..." marking a cut.
inline std::string quoted_token(const std::string& text) {
  return text.size() <= MaxQuotedChars ? text : text.substr(0, MaxQuotedChars) + "...";
}

struct Token {
  std::string text;
  int column = 0;  ///< 1-based
};

/// Tokens of `line` up to a '#' comment; a trailing '\r' is ignored.
inline std::vector<Token> tokenize(const std::string& line) {
  std::vector<Token> tokens;
  std::size_t i = 0;
  const std::size_t n = line.size();
  while (i < n) {
    const char c = line[i];
    if (c == '#') break;
    if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < n && line[i] != ' ' && line[i] != '\t' && line[i] != '\r' && line[i] != '#' &&
           line[i] != '\f' && line[i] != '\v')
      ++i;
    tokens.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
  }
  return tokens;
}

enum class NumberStatus { Ok, NotANumber, NotFinite };

/// Parse the whole of `text` as a decimal number (strtod syntax, no trailing characters).
inline NumberStatus parse_number(const std::string& text, double& value) {
  if (text.empty()) return NumberStatus::NotANumber;
  errno = 0;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return NumberStatus::NotANumber;
  if (!std::isfinite(value)) return NumberStatus::NotFinite;
  return NumberStatus::Ok;
}

/// Parse the whole of `text` as a (possibly negative) integer; false if it is not one.
inline bool parse_integer(const std::string& text, long long& value) {
  if (text.empty()) return false;
  errno = 0;
  char* end = nullptr;
  value = std::strtoll(text.c_str(), &end, 10);
  return end == text.c_str() + text.size() && errno == 0;
}

}  // namespace dayphoton::project::detail
