// ParamReader: reads one map of the located YAML tree against its schema section
// (STYLE.md A.5-A.6). Every read marks the key; finish() reports every key that was never
// read as "unknown key 'x' in <section> (did you mean 'y'?)" at the key's own location.
// Absent keys take the schema default (parsed by the same converter as file values, so a
// default is declared exactly once); absent required keys are reported at the section's node.
// Each read_* returns true when `out` holds a valid value (from the file or the default) and
// false when the key is absent without default or its value was wrong (error reported).
#pragma once

#include <set>
#include <string>
#include <vector>

#include "dayphoton/core/vec3.h"
#include "dayphoton/project/project_schema.h"
#include "dayphoton/project/site_geodesy.h"
#include "yaml_document.h"

namespace dayphoton::project {

class ParamReader {
 public:
  /// `node` must be a map (callers check with expect_map first).
  ParamReader(const YamlNode& node, const SectionSchema& schema, Reporter& reporter);

  /// The value node, or nullptr if absent (reports a missing required key). Marks it read.
  const YamlNode* take(const std::string& key);
  /// Location of the key's value, or of the section if absent.
  SourceLocation location_of(const std::string& key) const;
  bool has(const std::string& key) const { return m_node.find(key) != nullptr; }

  bool read_number(const std::string& key, double& out);
  bool read_integer(const std::string& key, long long& out);
  bool read_bool(const std::string& key, bool& out);
  bool read_string(const std::string& key, std::string& out);
  bool read_choice(const std::string& key, std::string& out);
  bool read_angle(const std::string& key, AngleKind kind, double& out);
  bool read_vec3(const std::string& key, Vec3& out);
  bool read_rgb(const std::string& key, Vec3& out);
  bool read_points(const std::string& key, std::vector<Vec3>& out);
  /// A non-empty list of numbers, each checked against the key's range.
  bool read_numbers(const std::string& key, std::vector<double>& out);

  /// Report unread keys. Call once after all reads.
  void finish();

  const SectionSchema& schema() const { return m_schema; }
  const YamlNode& node() const { return m_node; }
  Reporter& reporter() { return m_reporter; }

 private:
  const ParamSchema& param(const std::string& key) const;
  /// The node to convert: the file's value, or a node holding the default text; nullptr if
  /// neither.
  const YamlNode* value_or_default(const std::string& key, YamlNode& scratch);
  bool check_range(const ParamSchema& p, const YamlNode& at, double value);

  const YamlNode& m_node;
  const SectionSchema& m_schema;
  Reporter& m_reporter;
  std::set<std::string> m_read;
};

/// Report "expected a map for '<what>', got ..." unless `node` is a map.
bool expect_map(const YamlNode& node, const std::string& what, Reporter& reporter);
/// Report "expected a list for '<what>', got ..." unless `node` is a sequence.
bool expect_list(const YamlNode& node, const std::string& what, Reporter& reporter);

/// Strict conversions of a scalar's text (the whole text must be consumed; finite only).
bool parse_double(const std::string& text, double& out);
bool parse_integer(const std::string& text, long long& out);
bool parse_bool(const std::string& text, bool& out);

}  // namespace dayphoton::project
