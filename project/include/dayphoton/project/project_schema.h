// The project-file schema: for every section of a project file, its keys with type, unit,
// range, default and a one-line help (STYLE.md A.6-A.7). The same tables drive validation in
// the loader (unknown keys, missing keys, types, ranges, allowed values, defaults) and the
// key reference printed by format_project_schema() (docs/project-format.md is built from it).
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace dayphoton::project {

enum class ParamType {
  Number,       ///< real number
  Integer,      ///< whole number
  Boolean,      ///< true / false
  String,       ///< free text or a name
  Choice,       ///< one of `choices`
  Angle,        ///< decimal degrees or a DMS string (41d58'48"N)
  Vec3,         ///< [x, y, z]
  Rgb,          ///< a number (grey) or [r, g, b]
  Path,         ///< a file or folder path, relative to the project file
  PointList,    ///< [[x, y, z], ...]
  NumberList,   ///< [a, b, ...]: one or more numbers, each within the range
  NameList,     ///< [a, b, ...]: one or more names
  Section,      ///< a nested map with its own schema (`section` names it)
  SectionList,  ///< a list of maps with the schema `section`
  NameMap,      ///< a map from names to values (see help)
  Special,      ///< several accepted forms, described in help
};

/// Text used in docs and messages: "number", "list of room", ...
std::string param_type_name(ParamType type);

struct ParamSchema {
  std::string name;
  ParamType type = ParamType::Number;
  std::string unit;            ///< "m", "deg", "h", "" if dimensionless
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;  ///< range is (min, max] instead of [min, max]
  bool required = false;
  std::string default_value;   ///< as it would be written in the file; "" = none
  std::vector<std::string> choices;  ///< Choice: the allowed values
  std::string section;         ///< Section / SectionList: the nested schema's name
  std::string help;

  bool has_range() const;
  /// "[0, 1]", "> 0", ">= 0", "" (for messages and docs).
  std::string range_text() const;
  bool in_range(double value) const;
};

struct SectionSchema {
  std::string name;  ///< as used in messages: "unknown key 'x' in <name>"
  std::string help;
  std::vector<ParamSchema> params;

  const ParamSchema* find(const std::string& key) const;
  std::vector<std::string> keys() const;
};

/// Every section, in documentation order.
const std::vector<SectionSchema>& project_schema();
/// The section called `name`; throws std::logic_error if there is none (a programming error).
const SectionSchema& schema_section(const std::string& name);

/// The key reference as Markdown: one table per section (key, type, unit, range, default,
/// required, help).
std::string format_project_schema();

}  // namespace dayphoton::project
