// Atomic output: every result file is written to a temporary file in the same folder and
// renamed over the target, so a crash or kill never leaves a partial output behind.
#pragma once

#include <cstddef>
#include <functional>
#include <ostream>
#include <string>

namespace dayphoton {

/// Write `path` atomically: `write` fills a stream bound to "<path>.tmp.<pid>", which is
/// flushed, fsync'ed (unless `sync` is false) and renamed to `path`. Throws
/// std::runtime_error (naming the path) on any I/O failure, removing the temporary file.
/// Without the fsync the rename is still atomic for the process (a kill never leaves a
/// partial file) but not across a power failure: for caches whose files carry their own
/// checksum (study/artifact_store.h), where a sync per file would cost more than the work.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary = false, bool sync = true);

/// Convenience overload for a complete string.
void write_file_atomically(const std::string& path, const std::string& contents);

/// The writer's process id if `file_name` is a temporary of write_file_atomically
/// ("<name>.tmp.<pid>"), else 0.
long temporary_file_owner(const std::string& file_name);

/// Delete every temporary of write_file_atomically under `dir` (recursively, symbolic links
/// not followed) whose writing process no longer exists: what a kill or a crash during a
/// write leaves behind. Temporaries of running processes are kept. Returns how many were
/// deleted; a folder that does not exist has none.
std::size_t remove_dead_temporaries(const std::string& dir);

}  // namespace dayphoton
