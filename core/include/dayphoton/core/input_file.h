// Input files named by the user (on the command line or in a project file) must be regular
// files. A FIFO or a character device would block `open` or stream forever (`check fifo`,
// `sun /dev/zero`), and a folder reads as an empty file; so every reader checks the file's
// type first, without opening it, and reports a located error naming what the path is.
#pragma once

#include <cstdint>
#include <fstream>
#include <string>

#include "dayphoton/core/source_location.h"

namespace dayphoton {

/// Why `path` cannot be read as an input file ("not found", "is a folder", "is a named pipe
/// (FIFO)", "is a character device", ...), or "" if it is a regular file (after symlinks).
/// Never opens the path, so it never blocks.
std::string input_file_problem(const std::string& path);

/// Open `path` for binary reading. Throws InputError located at `path` (or at
/// `referenced_from` when the path was written in another file) if it is not a regular file
/// or cannot be opened; `what` names the file in the message ("weather file").
std::ifstream open_input_file(const std::string& path, const std::string& what,
                              const SourceLocation& referenced_from = {});

/// The size in bytes of a regular file; false if it is not one or cannot be examined.
bool input_file_size(const std::string& path, std::uint64_t& size_bytes);

}  // namespace dayphoton
