// JsonLocator: where each value of a JSON text starts, so that errors found after parsing
// (a missing field, a non-planar face, an unknown modifier) name file:line:column as well as
// the value's path. nlohmann-json keeps no positions in its values; this is a second, small
// scan of a text that nlohmann-json has already accepted (RFC 8259 grammar: objects, arrays,
// strings with escapes, numbers, true/false/null), recording the byte offset of every object,
// array and object member by its path. Scalars inside arrays (coordinates) are not recorded:
// they are located at their array.
//
// Paths are written as in messages: `rooms[1].faces[3].geometry.boundary` (members by key,
// array elements by 0-based index); the root is "".
#pragma once

#include <cstddef>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "dayphoton/core/source_location.h"

namespace dayphoton::project::detail {

class JsonLocator {
 public:
  /// Scan `text` (valid JSON); `file` is the name locations carry.
  JsonLocator(const std::string& text, std::string file);

  /// Location of the value at `path`, else of its nearest recorded ancestor.
  SourceLocation locate(const std::string& path) const;
  /// Location of byte `offset` (0-based) of the text.
  SourceLocation at_offset(std::size_t offset) const;
  /// Location of byte `offset` of `text` without building a locator (for text that is not
  /// valid JSON).
  static SourceLocation line_and_column(const std::string& text, const std::string& file, std::size_t offset);

 private:
  std::string m_file;
  std::vector<std::size_t> m_line_starts;  ///< byte offset of each line's first byte
  std::unordered_map<std::string, std::size_t> m_offsets;
};

/// The deepest nesting of objects and arrays in `text` (strings skipped) and the byte offset
/// where it is first reached. Linear, no recursion: checked before a JsonLocator is built,
/// whose scan recurses once per level.
std::pair<std::size_t, std::size_t> json_nesting(const std::string& text);

/// `parent.key` ("key" at the root).
std::string json_member(const std::string& parent, const std::string& key);
/// `parent[index]`.
std::string json_element(const std::string& parent, std::size_t index);

}  // namespace dayphoton::project::detail
