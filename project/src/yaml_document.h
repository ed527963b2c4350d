// YamlNode: the located node tree, stage 1 of project loading (STYLE.md A.3-A.4).
//
// yaml-cpp parses the text; we copy its nodes into a plain tree in which every node and every
// map key carries a 1-based file:line:column (yaml-cpp's Mark is 0-based). The tree is what the
// typed readers consume, so nothing downstream depends on yaml-cpp. A syntax error becomes a
// located diagnostic instead of an exception.
//
// SourceText keeps the raw lines so each diagnostic can print the offending line and a caret.
#pragma once

#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/source_location.h"

namespace dayphoton::project {

/// The text of an input file split into lines, for carets under errors.
class SourceText {
 public:
  SourceText(const std::string& file, const std::string& text);
  const std::string& file() const { return m_file; }
  /// Line `line` (1-based) without its newline; "" if out of range.
  std::string line(int line) const;

 private:
  std::string m_file;
  std::vector<std::string> m_lines;
};

/// Diagnostics plus the source text: every error gets its source line attached.
class Reporter {
 public:
  Reporter(Diagnostics& diagnostics, const SourceText& source)
      : m_diagnostics(diagnostics), m_source(source) {}
  void error(const SourceLocation& loc, std::string message);
  bool at_cap() const { return m_diagnostics.at_cap(); }
  bool has_errors() const { return m_diagnostics.has_errors(); }
  const SourceText& source() const { return m_source; }

 private:
  Diagnostics& m_diagnostics;
  const SourceText& m_source;
};

struct YamlEntry;

/// One node of the located tree. Scalars keep their text verbatim (conversion to numbers,
/// booleans and angles happens in the parameter reader, where the key name is known).
struct YamlNode {
  enum class Kind { Null, Scalar, Sequence, Map };
  Kind kind = Kind::Null;
  std::string scalar;              ///< Scalar: the text as written (unquoted)
  std::vector<YamlNode> items;     ///< Sequence
  std::vector<YamlEntry> entries;  ///< Map, in file order
  SourceLocation location;         ///< where the node starts

  bool is_null() const { return kind == Kind::Null; }
  bool is_scalar() const { return kind == Kind::Scalar; }
  bool is_sequence() const { return kind == Kind::Sequence; }
  bool is_map() const { return kind == Kind::Map; }
  /// Map entry with this key, or nullptr.
  const YamlEntry* find(const std::string& key) const;
  /// "a number", "a list", ... for "expected X, got Y" messages.
  std::string describe() const;
};

struct YamlEntry {
  std::string key;
  SourceLocation key_location;
  YamlNode value;
};

/// Parse `text` (the content of reporter.source()) into a located tree. On a YAML syntax error, reports it (located) and returns
/// a Null node. Duplicate map keys are reported; the first occurrence is kept.
YamlNode parse_yaml_document(const std::string& text, Reporter& reporter);

}  // namespace dayphoton::project
