// Located YAML tree (see yaml_document.h). yaml-cpp marks are 0-based line/column; we add 1
// to both so messages match what editors show (STYLE.md A.4).
#include "yaml_document.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <unordered_map>

namespace dayphoton::project {

namespace {

/// Length of the UTF-8 sequence at text[i] and its code point, or 0 if the bytes there are
/// not UTF-8 (RFC 3629 section 3: no overlong forms, no surrogates, nothing above U+10FFFF).
std::size_t utf8_sequence(const std::string& text, std::size_t i, char32_t& code) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b0 = byte(i);
  if (b0 < 0x80) {
    code = b0;
    return 1;
  }
  std::size_t length = 0;
  char32_t lowest = 0;
  if ((b0 & 0xE0) == 0xC0) length = 2, code = b0 & 0x1F, lowest = 0x80;
  else if ((b0 & 0xF0) == 0xE0) length = 3, code = b0 & 0x0F, lowest = 0x800;
  else if ((b0 & 0xF8) == 0xF0) length = 4, code = b0 & 0x07, lowest = 0x10000;
  else return 0;
  if (i + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (byte(i + k) & 0x3F);
  }
  if (code < lowest || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
  return length;
}

/// YAML 1.2 section 5.1 (c-printable), line breaks included.
bool printable(char32_t c) {
  return c == 0x09 || c == 0x0A || c == 0x0D || (c >= 0x20 && c <= 0x7E) || c == 0x85 ||
         (c >= 0xA0 && c <= 0xD7FF) || (c >= 0xE000 && c <= 0xFFFD) || c >= 0x10000;
}

std::string hex(unsigned value, int digits) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "%0*X", digits, value);
  return buffer;
}

/// Reports the first byte that is not UTF-8, or the first character YAML does not allow.
bool check_text(const std::string& text, Reporter& reporter) {
  int line = 1;
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < text.size();) {
    char32_t c = 0;
    const std::size_t n = utf8_sequence(text, i, c);
    const SourceLocation at{reporter.source().file(), line, static_cast<int>(i - line_start) + 1};
    if (n == 0) {
      reporter.error(at, "byte 0x" + hex(static_cast<unsigned char>(text[i]), 2) +
                             " is not UTF-8: a project file must be UTF-8 text");
      return false;
    }
    if (!printable(c)) {
      reporter.error(at, "character U+" + hex(static_cast<unsigned>(c), 4) +
                             " is not allowed in YAML (a control character; YAML 1.2, section 5.1)");
      return false;
    }
    i += n;
    if (c == '\n') {
      ++line;
      line_start = i;
    }
  }
  return true;
}

}  // namespace

SourceText::SourceText(const std::string& file, const std::string& text) : m_file(file) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    for (std::size_t i = 0; i < line.size();) {
      char32_t c = 0;
      const std::size_t n = utf8_sequence(line, i, c);
      // NEL (U+0085) is printable YAML but a C1 control to a terminal.
      if (n == 0 || (c != '\t' && !printable(c)) || c == 0x85) {
        for (std::size_t k = 0; k < std::max<std::size_t>(n, 1); ++k) line[i + k] = '?';
        i += std::max<std::size_t>(n, 1);
      } else {
        i += n;
      }
    }
    m_lines.push_back(line);
  }
}

std::string SourceText::line(int line) const {
  if (line < 1 || line > static_cast<int>(m_lines.size())) return {};
  return m_lines[static_cast<std::size_t>(line - 1)];
}

namespace {

// Messages quote names and values from the file, which YAML escapes (and JSON's \u escapes)
// can fill with any character: control characters (C0, DEL, C1) are shown as \xNN, never
// sent as they are.
std::string printable_message(const std::string& message) {
  std::string shown;
  for (std::size_t i = 0; i < message.size(); ++i) {
    const auto byte = static_cast<unsigned char>(message[i]);
    const bool c1 = byte == 0xC2 && i + 1 < message.size() &&
                    static_cast<unsigned char>(message[i + 1]) >= 0x80 &&
                    static_cast<unsigned char>(message[i + 1]) <= 0x9F;
    if (byte < 0x20 || byte == 0x7F || c1) {
      const unsigned value = c1 ? static_cast<unsigned char>(message[++i]) : byte;
      shown += "\\x" + hex(value, 2);
    } else {
      shown += message[i];
    }
  }
  return shown;
}

}  // namespace

void Reporter::error(const SourceLocation& loc, std::string message) {
  m_diagnostics.error(loc, printable_message(message), m_source.line(loc.line));
}

void Reporter::forward(const Diagnostic& diagnostic) {
  m_diagnostics.error(diagnostic.location, printable_message(diagnostic.message), diagnostic.source_line);
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

SourceLocation to_location(const YAML::Mark& mark, const std::string& file,
                           const SourceLocation& fallback) {
  if (mark.line < 0 || mark.column < 0) return fallback;
  return SourceLocation{file, mark.line + 1, mark.column + 1};
}

/// yaml-cpp's node graph -> our tree, counting nodes against MaxYamlNodes as it goes (an
/// alias is a second reference to one node in yaml-cpp, but a full copy here).
class Converter {
 public:
  explicit Converter(Reporter& reporter) : m_reporter(reporter) {}

  YamlNode convert(const YAML::Node& node, const SourceLocation& fallback, int depth) {
    YamlNode out;
    out.location = to_location(node.Mark(), m_reporter.source().file(), fallback);
    if (m_stopped) return out;
    if (++m_nodes > MaxYamlNodes) {
      m_reporter.error(out.location, "the YAML document has more than " +
                                         std::to_string(MaxYamlNodes) +
                                         " nodes, counting each alias as a copy of its anchor's node "
                                         "(aliases nested in aliases?)");
      m_stopped = true;
      return out;
    }
    if (depth > MaxYamlDepth) {
      m_reporter.error(out.location, "YAML nesting deeper than " + std::to_string(MaxYamlDepth) +
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
        for (const auto& item : node) {
          out.items.push_back(convert(item, out.location, depth + 1));
          if (m_stopped) break;
        }
        break;
      case YAML::NodeType::Map: {
        out.kind = YamlNode::Kind::Map;
        // Key -> index of its entry: duplicate keys are found in constant time, so a map of
        // n keys costs O(n), not O(n^2).
        std::unordered_map<std::string, std::size_t> index;
        for (const auto& kv : node) {
          const SourceLocation key_loc =
              to_location(kv.first.Mark(), m_reporter.source().file(), out.location);
          if (!kv.first.IsScalar()) {
            m_reporter.error(key_loc, "map keys must be plain names");
            continue;
          }
          const std::string key = kv.first.Scalar();
          const auto [first, inserted] = index.emplace(key, out.entries.size());
          if (!inserted) {
            m_reporter.error(key_loc, "duplicate key '" + key + "' (first given at line " +
                                          std::to_string(out.entries[first->second].key_location.line) +
                                          ")");
            continue;
          }
          YamlEntry entry;
          entry.key = key;
          entry.key_location = key_loc;
          entry.value = convert(kv.second, key_loc, depth + 1);
          out.entries.push_back(std::move(entry));
          if (m_stopped) break;
        }
        break;
      }
    }
    return out;
  }

  bool stopped() const { return m_stopped; }

 private:
  Reporter& m_reporter;
  std::size_t m_nodes = 0;
  bool m_stopped = false;  ///< over MaxYamlNodes: the tree is abandoned
};

/// Where the second document starts: its `---` line if one precedes its first node with
/// only blank lines, comments or a `...` end marker in between, else that node.
SourceLocation second_document_start(const YAML::Node& document, const SourceText& source) {
  const SourceLocation node = to_location(document.Mark(), source.file(), {source.file(), 1, 1});
  for (int line = node.line; line >= 1; --line) {
    const std::string text = source.line(line);
    if (text.compare(0, 3, "---") == 0) return {source.file(), line, 1};
    const std::size_t first = text.find_first_not_of(" \t");
    const bool skippable = first == std::string::npos || text[first] == '#' ||
                           text.compare(0, 3, "...") == 0 || line == node.line;
    if (!skippable) break;
  }
  return node;
}

}  // namespace

YamlNode parse_yaml_document(const std::string& text, Reporter& reporter) {
  const SourceLocation start{reporter.source().file(), 1, 1};
  YamlNode null;  // what an empty file or a reported error gives
  null.location = start;
  if (text.size() > MaxYamlBytes) {
    reporter.error(start, "the file is larger than " + std::to_string(MaxYamlBytes) +
                              " bytes (2 MiB), the limit of a project file: put large geometry in "
                              "OBJ files and sensors in .pts files");
    return null;
  }
  if (!check_text(text, reporter)) return null;
  std::vector<YAML::Node> documents;
  try {
    documents = YAML::LoadAll(text);
  } catch (const YAML::Exception& e) {
    // ParserException (and its DeepRecursion subclass) carry the mark of the bad token.
    reporter.error(to_location(e.mark, reporter.source().file(), start), "invalid YAML: " + e.msg);
    return null;
  }
  if (documents.empty()) return null;
  if (documents.size() > 1) {
    reporter.error(second_document_start(documents[1], reporter.source()),
                   "a second YAML document starts here: a project file holds one document");
    return null;
  }
  Converter converter(reporter);
  YamlNode root = converter.convert(documents[0], start, 0);
  if (converter.stopped()) return null;
  return root;
}

}  // namespace dayphoton::project
