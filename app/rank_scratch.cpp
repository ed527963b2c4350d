// The scratch folder of an MPI rank: see rank_scratch.h.
#include "rank_scratch.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace dayphoton::app {
namespace fs = std::filesystem;

int RankScratch::remove_stale(const std::string& temp_folder) {
  int removed = 0;
  std::error_code ec;
  for (fs::directory_iterator it(temp_folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(NamePrefix, 0) != 0 || !it->is_directory(ec)) continue;
    const int fd = ::open((it->path() / LockName).c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
    if (fd < 0) continue;
    // Free: its rank has ended without removing it. Removed while still holding the lock, so
    // no other sweeper removes it at the same time.
    if (::flock(fd, LOCK_EX | LOCK_NB) == 0) {
      std::error_code ignored;
      fs::remove_all(it->path(), ignored);
      ++removed;
    }
    ::close(fd);
  }
  return removed;
}

RankScratch::RankScratch(const std::string& temp_folder, int rank) {
  remove_stale(temp_folder);
  m_folder = (fs::path(temp_folder) / (NamePrefix + std::to_string(rank) + "-" + std::to_string(::getpid()))).string();
  fs::create_directories(m_folder);
  // Locked under another name, then renamed: a sweeper never finds the lock file unlocked.
  const std::string lock = m_folder + "/" + LockName;
  const std::string locking = lock + ".new";
  m_lock_fd = ::open(locking.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0600);
  if (m_lock_fd < 0 || ::flock(m_lock_fd, LOCK_EX | LOCK_NB) != 0 || ::rename(locking.c_str(), lock.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    if (m_lock_fd >= 0) ::close(m_lock_fd);
    throw std::runtime_error("cannot lock the rank's scratch folder " + lock + ": " + why);
  }
}

RankScratch::~RankScratch() {
  std::error_code ignored;
  fs::remove_all(m_folder, ignored);
  if (m_lock_fd >= 0) ::close(m_lock_fd);
}

}  // namespace dayphoton::app
