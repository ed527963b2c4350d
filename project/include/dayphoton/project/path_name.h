// Path names: the one rule for every name from a project file that becomes a file or folder
// name under the output folder (sensor grids and point sets: <output>/<name>/; variants:
// <output>/variants/<name>/; and the per-project folders of `run --output` with several
// projects). A name that passes cannot leave its folder ('/', '..'), hide itself ('.x'),
// look like an option ('-x'), collide with a device (Windows 'nul', 'com1'), or differ
// between file systems (spaces, non-ASCII, a trailing '.', which Windows drops).
#pragma once

#include <cstddef>
#include <string>

namespace dayphoton::project {

/// Policy: the longest path name, in characters (far below every file system's 255 bytes, so
/// <output>/variants/<variant>/<grid>/<file> stays short).
constexpr std::size_t MaxPathNameLength = 64;

/// The rule in words, for messages and docs/project-format.md.
constexpr const char* PathNameRule =
    "1 to 64 of A-Z a-z 0-9 _ - ., not starting with '.' or '-', not ending with '.', not a "
    "device name such as 'nul'";

/// Why `name` cannot be a file or folder name ("'/' is not allowed", "it starts with '.'",
/// ...), or "" if it can. Case-insensitive file systems are the caller's concern (see
/// path_name_fold).
std::string path_name_problem(const std::string& name);

/// True if path_name_problem(name) is "".
bool is_portable_folder_name(const std::string& name);

/// The name as case-insensitive file systems (Windows, macOS) compare it: two names with the
/// same fold share one folder there.
std::string path_name_fold(const std::string& name);

/// `name` for a message: printable ASCII as written, every other byte as \xNN, so a
/// message never carries a NUL, a newline or a terminal escape sequence.
std::string printable_name(const std::string& name);

}  // namespace dayphoton::project
