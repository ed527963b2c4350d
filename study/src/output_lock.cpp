// OutputLock: see output_lock.h.
#include "dayphoton/study/output_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <sstream>

#include "dayphoton/core/error_text.h"

namespace dayphoton::study {

namespace {

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

std::string host_name() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

std::string read_all(int fd) {
  std::string text;
  char buffer[4096];
  ::lseek(fd, 0, SEEK_SET);
  for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0 && text.size() < 65536;) text.append(buffer, static_cast<std::size_t>(n));
  return text;
}

/// The owner recorded in a lock file's text ("key value" lines); nullopt if it records none.
std::optional<LockOwner> parse_owner(const std::string& text) {
  LockOwner owner;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t space = line.find(' ');
    if (space == std::string::npos) continue;
    const std::string key = line.substr(0, space), value = line.substr(space + 1);
    if (key == "pid") owner.pid = std::strtol(value.c_str(), nullptr, 10);
    else if (key == "host") owner.host = value;
    else if (key == "started") owner.started_utc = value;
    else if (key == "command") owner.command = value;
  }
  if (owner.pid <= 0) return std::nullopt;
  return owner;
}

[[noreturn]] void fail(const std::string& what, const std::string& path) {
  throw std::runtime_error("cannot " + what + " the lock file " + path + ": " + error_text(errno));
}

}  // namespace

std::string LockOwner::describe() const {
  std::string s = "pid " + std::to_string(pid);
  if (!host.empty()) s += " on host " + host;
  if (!started_utc.empty()) s += ", started " + started_utc;
  if (!command.empty()) s += " (" + command + ")";
  return s;
}

OutputFolderBusy::OutputFolderBusy(const std::string& folder, const LockOwner& owner)
    : std::runtime_error("the output folder " + folder + " is in use by another dayphoton run: " + owner.describe() +
                         "; wait for it to finish or choose another output folder (lock file " +
                         (std::filesystem::path(folder) / OutputLock::FileName).string() + ")"),
      m_owner(owner) {}

OutputLock::OutputLock(std::string path, int fd, LockOwner owner, std::optional<LockOwner> taken_over)
    : m_path(std::move(path)), m_fd(fd), m_owner(std::move(owner)), m_taken_over(std::move(taken_over)) {}

OutputLock::OutputLock(OutputLock&& other) noexcept
    : m_path(std::move(other.m_path)),
      m_fd(other.m_fd),
      m_owner(std::move(other.m_owner)),
      m_taken_over(std::move(other.m_taken_over)) {
  other.m_fd = -1;
}

OutputLock::~OutputLock() {
  if (m_fd < 0) return;
  // Unlink while still holding the flock: a process that opened the old file before the
  // unlink finds it replaced (acquire() compares inodes) and retries on the path.
  ::unlink(m_path.c_str());
  ::close(m_fd);
}

OutputLock OutputLock::acquire(const std::string& dir, const std::string& command) {
  const std::string path = (std::filesystem::path(dir) / FileName).string();
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0) fail("create", path);
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      const std::optional<LockOwner> owner = parse_owner(read_all(fd));
      ::close(fd);
      errno = error;
      if (error != EWOULDBLOCK) fail("lock", path);
      // The holder may not have written its details yet: report what is known.
      throw OutputFolderBusy(dir, owner.value_or(LockOwner{}));
    }
    // Locked, but the file may have been unlinked (or replaced) by its previous holder
    // between our open and our flock: then the lock is on a dead inode; start again.
    struct stat held{}, named{};
    if (::fstat(fd, &held) != 0 || ::stat(path.c_str(), &named) != 0 || held.st_ino != named.st_ino ||
        held.st_dev != named.st_dev) {
      ::close(fd);
      continue;
    }
    std::optional<LockOwner> previous = parse_owner(read_all(fd));
    const LockOwner self{static_cast<long>(::getpid()), host_name(), utc_now(), command};
    std::ostringstream text;
    text << "pid " << self.pid << "\nhost " << self.host << "\nstarted " << self.started_utc << "\ncommand "
         << self.command << "\n";
    const std::string s = text.str();
    if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, s.data(), s.size(), 0) != static_cast<ssize_t>(s.size())) {
      const int error = errno;
      ::unlink(path.c_str());
      ::close(fd);
      errno = error;
      fail("write", path);
    }
    return OutputLock(path, fd, self, std::move(previous));
  }
  throw std::runtime_error("cannot take the lock file " + path + ": it keeps being replaced");
}

}  // namespace dayphoton::study
