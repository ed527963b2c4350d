// Diagnostics: located input errors, collected up to a cap, printed compiler-style:
//
//   projects/office/project.yaml:12:7: error: unknown key 'sil' in window (did you mean 'sill'?)
//      sil: 0.9
//      ^
//
// Readers report into a Diagnostics object instead of throwing at the first problem, so a
// user sees every mistake in one go. InputError carries the collected list out of a loader.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "dayphoton/core/source_location.h"

namespace dayphoton {

enum class Severity { Error, Warning, Note };

struct Diagnostic {
  Severity severity = Severity::Error;
  SourceLocation location;
  std::string message;
  std::string source_line;  ///< the offending line of the input, if known (for the caret)

  /// Compiler-style text: "file:line:col: error: message", then the line and a caret.
  std::string format() const;
};

class Diagnostics {
 public:
  explicit Diagnostics(std::size_t max_errors = 50) : m_max_errors(max_errors) {}

  /// Record an error. Once the cap is reached further errors are counted but not kept.
  void error(const SourceLocation& loc, std::string message, std::string source_line = {});
  void warning(const SourceLocation& loc, std::string message, std::string source_line = {});

  bool has_errors() const { return m_error_count > 0; }
  std::size_t error_count() const { return m_error_count; }
  bool at_cap() const { return m_error_count >= m_max_errors; }
  const std::vector<Diagnostic>& entries() const { return m_entries; }

  /// All kept diagnostics formatted, plus "N errors" and a note if some were dropped.
  std::string format() const;

  /// Throw InputError with everything collected, if any error was recorded.
  void throw_if_errors() const;

 private:
  std::size_t m_max_errors;
  std::size_t m_error_count = 0;
  std::vector<Diagnostic> m_entries;
};

/// Thrown by loaders when their input is invalid; what() is the formatted diagnostic list.
class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<Diagnostic> diagnostics, const std::string& formatted)
      : std::runtime_error(formatted), m_diagnostics(std::move(diagnostics)) {}
  /// A single located error.
  InputError(const SourceLocation& loc, const std::string& message, std::string source_line = {});

  const std::vector<Diagnostic>& diagnostics() const { return m_diagnostics; }

 private:
  std::vector<Diagnostic> m_diagnostics;
};

/// A number for a message: up to 6 significant digits, no trailing zeros ("6", "0.9", "1e-05").
std::string format_number(double value);
/// A coordinate in metres for a message: format_number below 1e5 m in magnitude, millimetres
/// without trailing zeros beyond ("5000002.5", not "5e+06": survey coordinates).
std::string format_coordinate(double value_m);

/// Levenshtein distance (for "did you mean" hints).
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The candidate closest to `word` if it is close enough to be a plausible typo, else "".
std::string closest_match(std::string_view word, const std::vector<std::string>& candidates);

/// Line `line` (1-based) of a text file, without the newline; "" if unreadable.
std::string read_source_line(const std::string& path, int line);

}  // namespace dayphoton
