// Located YAML tree (see yaml_document.h). yaml-cpp marks are 0-based line/column; we add 1
// to both so messages match what editors show (STYLE.md A.4).
#include "yaml_document.h"

#include <yaml-cpp/yaml.h>

#include <sstream>

namespace dayphoton::project {

SourceText::SourceText(const std::string& file, const std::string& text) : m_file(file) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    m_lines.push_back(line);
  }
}

std::string SourceText::line(int line) const {
  if (line < 1 || line > static_cast<int>(m_lines.size())) return {};
  return m_lines[static_cast<std::size_t>(line - 1)];
}

void Reporter::error(const SourceLocation& loc, std::string message) {
  m_diagnostics.error(loc, std::move(message), m_source.line(loc.line));
}

const YamlEntry* YamlNode::find(const std::string& key) const {
  for (const auto& e : entries)
    if (e.key == key) return &e;
  return nullptr;
}

std::string YamlNode::describe() const {
  switch (kind) {
    case Kind::Null: return "nothing";
    case Kind::Scalar: {
      // A whole wrongly named file can parse as one scalar: quote its start only.
      constexpr std::size_t MaxQuoted = 60;
      if (scalar.size() <= MaxQuoted) return "'" + scalar + "'";
      return "'" + scalar.substr(0, MaxQuoted) + "...' (" + std::to_string(scalar.size()) + " characters)";
    }
    case Kind::Sequence: return "a list";
    case Kind::Map: return "a map";
  }
  return "nothing";
}

namespace {

// Deeper nesting than this is never a project file (and guards against alias cycles).
constexpr int MaxDepth = 64;

SourceLocation to_location(const YAML::Mark& mark, const std::string& file,
                           const SourceLocation& fallback) {
  if (mark.line < 0 || mark.column < 0) return fallback;
  return SourceLocation{file, mark.line + 1, mark.column + 1};
}

YamlNode convert(const YAML::Node& node, const SourceLocation& fallback, int depth,
                 Reporter& reporter) {
  YamlNode out;
  out.location = to_location(node.Mark(), reporter.source().file(), fallback);
  if (depth > MaxDepth) {
    reporter.error(out.location, "YAML nesting deeper than " + std::to_string(MaxDepth) +
                                     " levels (recursive alias?)");
    return out;
  }
  switch (node.Type()) {
    case YAML::NodeType::Undefined:
    case YAML::NodeType::Null:
      out.kind = YamlNode::Kind::Null;
      break;
    case YAML::NodeType::Scalar:
      out.kind = YamlNode::Kind::Scalar;
      out.scalar = node.Scalar();
      break;
    case YAML::NodeType::Sequence:
      out.kind = YamlNode::Kind::Sequence;
      for (const auto& item : node) out.items.push_back(convert(item, out.location, depth + 1, reporter));
      break;
    case YAML::NodeType::Map:
      out.kind = YamlNode::Kind::Map;
      for (const auto& kv : node) {
        const SourceLocation key_loc = to_location(kv.first.Mark(), reporter.source().file(),
                                                   out.location);
        if (!kv.first.IsScalar()) {
          reporter.error(key_loc, "map keys must be plain names");
          continue;
        }
        const std::string key = kv.first.Scalar();
        if (const YamlEntry* first = out.find(key)) {
          reporter.error(key_loc, "duplicate key '" + key + "' (first given at line " +
                                      std::to_string(first->key_location.line) + ")");
          continue;
        }
        YamlEntry entry;
        entry.key = key;
        entry.key_location = key_loc;
        entry.value = convert(kv.second, key_loc, depth + 1, reporter);
        out.entries.push_back(std::move(entry));
      }
      break;
  }
  return out;
}

}  // namespace

YamlNode parse_yaml_document(const std::string& text, Reporter& reporter) {
  const SourceLocation start{reporter.source().file(), 1, 1};
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    // ParserException (and its DeepRecursion subclass) carry the mark of the bad token.
    reporter.error(to_location(e.mark, reporter.source().file(), start), "invalid YAML: " + e.msg);
    return YamlNode{};
  }
  return convert(root, start, 0, reporter);
}

}  // namespace dayphoton::project
