// Test helper: a text as a JSON string literal (quotes, backslashes and control characters
// escaped), for writing HBJSON with a BSDF's XML inline.
#pragma once

#include <string>

namespace dayphoton::test {

inline std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += std::string("\\") + c;
    else if (c == '\n') out += "\\n";
    else if (c == '\t') out += "\\t";
    else if (c == '\r') out += "\\r";
    else out += c;
  }
  return out + "\"";
}

}  // namespace dayphoton::test
