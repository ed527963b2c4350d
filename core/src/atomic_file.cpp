#include "dayphoton/core/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "dayphoton/core/error_text.h"

namespace dayphoton {

namespace {
std::string errno_text() { return error_text(errno); }
}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary, bool sync) {
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(tmp, binary ? std::ios::binary | std::ios::trunc : std::ios::trunc);
    if (!out) throw std::runtime_error("cannot create " + tmp + ": " + errno_text());
    try {
      write(out);
    } catch (...) {
      out.close();
      std::remove(tmp.c_str());
      throw;
    }
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      throw std::runtime_error("cannot write " + tmp + ": " + errno_text());
    }
  }
  // fsync so the rename never exposes a file whose data is not yet on disk.
  const int fd = sync ? ::open(tmp.c_str(), O_RDONLY) : -1;
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = errno_text();
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot rename " + tmp + " to " + path + ": " + why);
  }
}

void write_file_atomically(const std::string& path, const std::string& contents) {
  write_file_atomically(path, [&](std::ostream& out) { out << contents; });
}

long temporary_file_owner(const std::string& file_name) {
  static const std::string marker = ".tmp.";
  const std::size_t at = file_name.rfind(marker);
  if (at == std::string::npos || at == 0) return 0;
  const std::string digits = file_name.substr(at + marker.size());
  if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) return 0;
  return std::stol(digits);
}

std::size_t remove_dead_temporaries(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return 0;
  std::vector<fs::path> dead;
  for (fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end;
       !ec && it != end; it.increment(ec)) {
    if (!it->is_regular_file(ec)) continue;
    const long pid = temporary_file_owner(it->path().filename().string());
    // kill(pid, 0) probes without signalling: ESRCH means no such process (POSIX.1-2017, kill()).
    if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) dead.push_back(it->path());
  }
  std::size_t removed = 0;
  for (const fs::path& p : dead) removed += fs::remove(p, ec) ? 1 : 0;
  return removed;
}

}  // namespace dayphoton
