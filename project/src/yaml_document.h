// YamlNode: the located node tree, stage 1 of project loading (STYLE.md A.3-A.4).
//
// yaml-cpp parses the text; we copy its nodes into a plain tree in which every node and every
// map key carries a 1-based file:line:column (yaml-cpp's Mark is 0-based). The tree is what the
// typed readers consume, so nothing downstream depends on yaml-cpp. A syntax error becomes a
// located diagnostic instead of an exception.
//
// SourceText keeps the raw lines so each diagnostic can print the offending line and a caret.
//
// Limits, so that a small hostile file cannot take the loader's time or memory:
// - the text must be UTF-8 without control characters other than tab, line feed and carriage
//   return (YAML 1.2 section 5.1, "c-printable"; we accept UTF-8 only);
// - one document per file: a second one (after `---`) is an error, not silently ignored;
// - at most MaxYamlBytes of text (yaml-cpp's own node graph costs ~350 bytes a node, and
//   "1,1,1,..." is a node every 2 bytes);
// - at most MaxYamlNodes nodes after aliases are expanded (an alias is copied into the tree,
//   so nested aliases grow it exponentially: the "billion laughs" document);
// - at most MaxYamlDepth levels of nesting.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/source_location.h"

namespace dayphoton::project {

/// Policy: the largest project file, in bytes. A 25 000-vertex polygon written inline takes
/// ~0.6 MiB; larger geometry belongs in OBJ files and sensors in .pts files. With the node
/// limit below, loading the largest file stays under ~0.6 GB (measured: 1.1 GB for 4 MiB
/// of "1,1,1,...").
constexpr std::size_t MaxYamlBytes = 2u << 20;
/// Policy: the largest tree a project file may expand to, counting every node (map, list,
/// scalar) after aliases are copied. A project written out in full (a 25 000-vertex polygon:
/// 100 000 nodes; 10 000 inline sensor points: 70 000) stays well below it; the tree costs
/// about 270 bytes a node (1 000 000 nodes: 0.27 GB, measured).
constexpr std::size_t MaxYamlNodes = 1'000'000;
/// Policy: deeper nesting than this is never a project file (and would exhaust the stack).
constexpr int MaxYamlDepth = 64;

/// The text of an input file split into lines, for carets under errors.
class SourceText {
 public:
  SourceText(const std::string& file, const std::string& text);
  const std::string& file() const { return m_file; }
  /// Line `line` (1-based) without its newline, as printed under a diagnostic: control
  /// characters and bytes that are not UTF-8 become '?' (one per byte, so carets line up),
  /// so an error never sends raw escape sequences to the terminal. "" if out of range.
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
  /// Report an error; control characters in `message` (from names quoted in it) are shown
  /// as \xNN.
  void error(const SourceLocation& loc, std::string message);
  /// Report an error found in another input file (an HBJSON model), with its own line.
  void forward(const Diagnostic& diagnostic);
  bool at_cap() const { return m_diagnostics.at_cap(); }
  bool has_errors() const { return m_diagnostics.has_errors(); }
  const SourceText& source() const { return m_source; }
  /// For errors in other files (their own lines under the caret), e.g. a CSV the project names.
  Diagnostics& diagnostics() { return m_diagnostics; }

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

/// Parse `text` (the content of reporter.source()) into a located tree. On a YAML syntax
/// error, text that is not UTF-8, a second document or a tree over the limits above, reports it
/// (located) and returns a Null node. Duplicate map keys are reported; the first occurrence is
/// kept.
YamlNode parse_yaml_document(const std::string& text, Reporter& reporter);

}  // namespace dayphoton::project
