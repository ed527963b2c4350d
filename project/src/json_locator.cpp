// JsonLocator (json_locator.h): a recursive scan of JSON text that nlohmann-json accepted.
#include "json_locator.h"

#include <algorithm>

namespace dayphoton::project::detail {

std::pair<std::size_t, std::size_t> json_nesting(const std::string& text) {
  std::size_t depth = 0, deepest = 0, where = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '{' || c == '[') {
      if (++depth > deepest) {
        deepest = depth;
        where = i;
      }
    } else if ((c == '}' || c == ']') && depth > 0) {
      --depth;
    }
  }
  return {deepest, where};
}

SourceLocation JsonLocator::line_and_column(const std::string& text, const std::string& file, std::size_t offset) {
  SourceLocation loc;
  loc.file = file;
  loc.line = 1;
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i)
    if (text[i] == '\n') {
      ++loc.line;
      line_start = i + 1;
    }
  loc.column = static_cast<int>(offset - line_start + 1);
  return loc;
}

std::string json_member(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string json_element(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

namespace {

class Scanner {
 public:
  Scanner(const std::string& text, std::unordered_map<std::string, std::size_t>& offsets)
      : m_text(text), m_offsets(offsets) {}

  void run() {
    skip_space();
    value("", /*record=*/true);
  }

 private:
  void skip_space() {
    while (m_pos < m_text.size() &&
           (m_text[m_pos] == ' ' || m_text[m_pos] == '\t' || m_text[m_pos] == '\n' || m_text[m_pos] == '\r'))
      ++m_pos;
  }

  /// The string starting at m_pos (a '"'), unescaped only as far as keys need: escapes are
  /// kept verbatim except \" and \\ (Honeybee identifiers contain neither).
  std::string string() {
    std::string out;
    ++m_pos;  // opening quote
    while (m_pos < m_text.size() && m_text[m_pos] != '"') {
      if (m_text[m_pos] == '\\' && m_pos + 1 < m_text.size()) {
        const char c = m_text[m_pos + 1];
        if (c == '"' || c == '\\' || c == '/') {
          out += c;
        } else {
          out += '\\';
          out += c;
        }
        m_pos += 2;
        continue;
      }
      out += m_text[m_pos++];
    }
    ++m_pos;  // closing quote
    return out;
  }

  void value(const std::string& path, bool record) {
    if (m_pos >= m_text.size()) return;
    const char c = m_text[m_pos];
    if (c == '{' || c == '[' || record) m_offsets.emplace(path, m_pos);
    if (c == '{') {
      ++m_pos;
      skip_space();
      while (m_pos < m_text.size() && m_text[m_pos] != '}') {
        const std::string key = string();
        skip_space();
        ++m_pos;  // ':'
        skip_space();
        value(json_member(path, key), true);
        skip_space();
        if (m_pos < m_text.size() && m_text[m_pos] == ',') ++m_pos;
        skip_space();
      }
      ++m_pos;
    } else if (c == '[') {
      ++m_pos;
      skip_space();
      std::size_t index = 0;
      while (m_pos < m_text.size() && m_text[m_pos] != ']') {
        value(json_element(path, index++), false);
        skip_space();
        if (m_pos < m_text.size() && m_text[m_pos] == ',') ++m_pos;
        skip_space();
      }
      ++m_pos;
    } else if (c == '"') {
      string();
    } else {
      while (m_pos < m_text.size() && m_text[m_pos] != ',' && m_text[m_pos] != ']' && m_text[m_pos] != '}' &&
             m_text[m_pos] != ' ' && m_text[m_pos] != '\n' && m_text[m_pos] != '\r' && m_text[m_pos] != '\t')
        ++m_pos;
    }
  }

  const std::string& m_text;
  std::unordered_map<std::string, std::size_t>& m_offsets;
  std::size_t m_pos = 0;
};

}  // namespace

JsonLocator::JsonLocator(const std::string& text, std::string file) : m_file(std::move(file)) {
  m_line_starts.push_back(0);
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') m_line_starts.push_back(i + 1);
  Scanner(text, m_offsets).run();
}

SourceLocation JsonLocator::at_offset(std::size_t offset) const {
  const auto it = std::upper_bound(m_line_starts.begin(), m_line_starts.end(), offset);
  const std::size_t line = static_cast<std::size_t>(it - m_line_starts.begin());  // 1-based
  SourceLocation loc;
  loc.file = m_file;
  loc.line = static_cast<int>(line);
  loc.column = static_cast<int>(offset - m_line_starts[line - 1] + 1);
  return loc;
}

SourceLocation JsonLocator::locate(const std::string& path) const {
  std::string p = path;
  for (;;) {
    if (const auto it = m_offsets.find(p); it != m_offsets.end()) return at_offset(it->second);
    if (p.empty()) break;
    // Up one level: drop a trailing [i] or .key.
    const std::size_t cut = p.find_last_of(".[");
    p = cut == std::string::npos ? std::string() : p.substr(0, cut);
  }
  SourceLocation loc;
  loc.file = m_file;
  loc.line = 1;
  loc.column = 1;
  return loc;
}

}  // namespace dayphoton::project::detail
