// Atomic output: every result file is written to a temporary file in the same folder and
// renamed over the target, so a crash or kill never leaves a partial output behind.
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace dayphoton {

/// Write `path` atomically: `write` fills a stream bound to "<path>.tmp.<pid>", which is
/// flushed, fsync'ed and renamed to `path`. Throws std::runtime_error (naming the path) on
/// any I/O failure, removing the temporary file.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary = false);

/// Convenience overload for a complete string.
void write_file_atomically(const std::string& path, const std::string& contents);

}  // namespace dayphoton
