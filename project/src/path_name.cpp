// Path names: see dayphoton/project/path_name.h. The reserved device names are those of
// Microsoft, "Naming Files, Paths, and Namespaces" (Win32 documentation, section "Naming
// Conventions"): CON, PRN, AUX, NUL, COM1-COM9, LPT1-LPT9, also with an extension.
#include "dayphoton/project/path_name.h"

#include <cstdio>

namespace dayphoton::project {
namespace {

bool allowed(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == '.';
}

std::string upper(std::string s) {
  for (char& c : s)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  return s;
}

bool is_device_name(const std::string& name) {
  const std::string stem = upper(name.substr(0, name.find('.')));
  for (const char* reserved : {"CON", "PRN", "AUX", "NUL"})
    if (stem == reserved) return true;
  return stem.size() == 4 && (stem.compare(0, 3, "COM") == 0 || stem.compare(0, 3, "LPT") == 0) &&
         stem[3] >= '1' && stem[3] <= '9';
}

}  // namespace

std::string printable_name(const std::string& name) {
  std::string out;
  for (char c : name) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7F && c != '\\') {
      out += c;
    } else {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\x%02X", byte);
      out += buffer;
    }
  }
  return out;
}

std::string path_name_problem(const std::string& name) {
  if (name.empty()) return "it is empty";
  if (name.size() > MaxPathNameLength)
    return "it has " + std::to_string(name.size()) + " characters (at most " +
           std::to_string(MaxPathNameLength) + ")";
  for (char c : name)
    if (!allowed(c)) return "'" + printable_name(std::string(1, c)) + "' is not allowed";
  if (name.front() == '.') return "it starts with '.'";
  if (name.front() == '-') return "it starts with '-'";
  if (name.back() == '.') return "it ends with '.'";
  if (is_device_name(name)) return "'" + name.substr(0, name.find('.')) + "' is a device name";
  return {};
}

bool is_portable_folder_name(const std::string& name) { return path_name_problem(name).empty(); }

std::string path_name_fold(const std::string& name) { return upper(name); }

}  // namespace dayphoton::project
