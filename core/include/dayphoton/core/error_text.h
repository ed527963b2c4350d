// The text of a system error number (errno, or a code such as posix_spawn's) for messages,
// safe to call from parallel threads: std::strerror may return a buffer shared by all threads
// (POSIX.1-2017, strerror: "need not be thread-safe"), so this goes through strerror_r.
#pragma once

#include <string>

namespace dayphoton {

/// The system's text for the error number `code` ("No such file or directory" for ENOENT);
/// "unknown error <code>" where the system has none.
std::string error_text(int code);

}  // namespace dayphoton
