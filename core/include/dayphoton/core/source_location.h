// SourceLocation: where a value came from in an input file (project YAML, EPW, OBJ, .pts).
// Lines and columns are 1-based, as editors and compilers print them; column 0 means
// "the whole line" (used for record-oriented files where a field number is given instead).
#pragma once

#include <string>

namespace dayphoton {

struct SourceLocation {
  std::string file;  ///< path as given by the user (printed verbatim)
  int line = 0;      ///< 1-based; 0 = unknown
  int column = 0;    ///< 1-based; 0 = unknown / whole line

  bool known() const { return line > 0; }
  /// "file:line:col", "file:line" or "file" depending on what is known.
  std::string to_string() const;
};

}  // namespace dayphoton
