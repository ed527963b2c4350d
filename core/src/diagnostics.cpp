#include "dayphoton/core/diagnostics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "dayphoton/core/terminal_text.h"

namespace dayphoton {

std::string SourceLocation::to_string() const {
  std::ostringstream s;
  s << file;
  if (line > 0) {
    s << ':' << line;
    if (column > 0) s << ':' << column;
  }
  return s.str();
}

namespace {
const char* severity_name(Severity s) {
  switch (s) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
  }
  return "error";
}
}  // namespace

// The echoed line of the input is cut after this many bytes: a wrongly named binary or
// minified file has lines of megabytes.
constexpr std::size_t MaxEchoBytes = 200;

std::string Diagnostic::format() const {
  // Everything taken from inputs (file name, message, line) is printed with its control
  // characters escaped (terminal_text.h).
  std::ostringstream s;
  if (!location.file.empty()) s << printable_text(location.to_string()) << ": ";
  s << severity_name(severity) << ": " << printable_text(message) << '\n';
  if (!source_line.empty()) {
    const bool cut = source_line.size() > MaxEchoBytes;
    const std::string_view shown = std::string_view(source_line).substr(0, MaxEchoBytes);
    s << "    " << printable_text(shown) << (cut ? "..." : "") << '\n';
    if (location.column > 0 && static_cast<std::size_t>(location.column) <= shown.size() + 1) {
      // Keep tabs so the caret lines up under the offending column; an escaped character
      // is as wide as its escape, a UTF-8 character one column.
      std::string pad;
      for (const char c : printable_text(shown.substr(0, static_cast<std::size_t>(location.column - 1))))
        if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) pad += c == '\t' ? '\t' : ' ';
      s << "    " << pad << "^\n";
    }
  }
  return s.str();
}

void Diagnostics::error(const SourceLocation& loc, std::string message, std::string source_line) {
  ++m_error_count;
  if (m_error_count > m_max_errors) return;
  m_entries.push_back({Severity::Error, loc, std::move(message), std::move(source_line)});
}

void Diagnostics::warning(const SourceLocation& loc, std::string message, std::string source_line) {
  m_entries.push_back({Severity::Warning, loc, std::move(message), std::move(source_line)});
}

std::string Diagnostics::format() const {
  std::ostringstream s;
  for (const auto& d : m_entries) s << d.format();
  if (m_error_count > m_max_errors)
    s << "note: " << (m_error_count - m_max_errors) << " more error(s) not shown\n";
  if (m_error_count > 0)
    s << m_error_count << (m_error_count == 1 ? " error" : " errors") << " generated.\n";
  return s.str();
}

void Diagnostics::throw_if_errors() const {
  if (has_errors()) throw InputError(m_entries, format());
}

InputError::InputError(const SourceLocation& loc, const std::string& message,
                       std::string source_line)
    : std::runtime_error(Diagnostic{Severity::Error, loc, message, source_line}.format()),
      m_diagnostics{Diagnostic{Severity::Error, loc, message, std::move(source_line)}} {}

std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

std::string format_coordinate(double value_m) {
  if (!(std::abs(value_m) >= 1e5)) return format_number(value_m);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.3f", value_m);
  std::string s = buffer;
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  return s;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string closest_match(std::string_view word, const std::vector<std::string>& candidates) {
  // A typo is plausible when at most a third of the letters differ (ninja's rule of thumb).
  const std::size_t limit = std::max<std::size_t>(1, word.size() / 3);
  std::string best;
  std::size_t best_distance = limit + 1;
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

std::string read_source_line(const std::string& path, int line) {
  std::ifstream in(path);
  std::string text;
  for (int i = 1; i <= line && std::getline(in, text); ++i)
    if (i == line) {
      if (!text.empty() && text.back() == '\r') text.pop_back();
      return text;
    }
  return {};
}

}  // namespace dayphoton
