#include "dayphoton/core/input_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/error_text.h"

namespace dayphoton {

std::string input_file_problem(const std::string& path) {
  if (path.empty()) return "is an empty file name";
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    if (errno == ENOENT || errno == ENOTDIR) return "not found";
    return std::string("cannot be read: ") + error_text(errno);
  }
  if (S_ISREG(info.st_mode)) return {};
  if (S_ISDIR(info.st_mode)) return "is a folder, not a file";
  if (S_ISFIFO(info.st_mode)) return "is a named pipe (FIFO), not a regular file";
  if (S_ISCHR(info.st_mode)) return "is a character device, not a regular file";
  if (S_ISBLK(info.st_mode)) return "is a block device, not a regular file";
  if (S_ISSOCK(info.st_mode)) return "is a socket, not a regular file";
  return "is not a regular file";
}

std::ifstream open_input_file(const std::string& path, const std::string& what,
                              const SourceLocation& referenced_from) {
  auto fail = [&](const std::string& problem) {
    if (referenced_from.known()) throw InputError(referenced_from, what + " '" + path + "' " + problem);
    throw InputError(SourceLocation{path, 0, 0}, what + " " + problem);
  };
  const std::string problem = input_file_problem(path);
  if (!problem.empty()) fail(problem);
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(std::string("cannot be opened: ") + error_text(errno));
  return in;
}

bool input_file_size(const std::string& path, std::uint64_t& size_bytes) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode)) return false;
  size_bytes = static_cast<std::uint64_t>(info.st_size);
  return true;
}

}  // namespace dayphoton
