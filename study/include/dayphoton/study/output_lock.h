// The lock of an output folder: at most one `dayphoton run` writes a folder at a time
// (docs/outputs.md, "Complete or marked incomplete").
//
// The lock is `<folder>/.dayphoton.lock`, held with flock(2) for as long as the run lasts and
// holding the owner's pid, host, start time and command line. The kernel releases a flock when
// its process ends however it ends (kill -9 included), so a lock file whose flock is free was
// left by a run that no longer exists: it is taken over, and taken_over() says whose it was.
// A run that ends normally removes the file.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

namespace dayphoton::study {

/// Who holds (or held) a lock, as written in the lock file.
struct LockOwner {
  long pid = 0;
  std::string host;
  std::string started_utc;  ///< ISO 8601, e.g. 2026-12-02T01:40:00Z
  std::string command;
  /// "pid 1234 on host h, started 2026-12-02T01:40:00Z (dayphoton run p.yaml)"
  std::string describe() const;
};

/// Another running process holds the output folder's lock.
class OutputFolderBusy : public std::runtime_error {
 public:
  OutputFolderBusy(const std::string& folder, const LockOwner& owner);
  const LockOwner& owner() const { return m_owner; }

 private:
  LockOwner m_owner;
};

class OutputLock {
 public:
  static constexpr const char* FileName = ".dayphoton.lock";

  /// Take the lock of the existing folder `dir` for this process, recording `command`.
  /// Throws OutputFolderBusy when a running process holds it, std::runtime_error (naming the
  /// lock file) when it cannot be created.
  static OutputLock acquire(const std::string& dir, const std::string& command);

  OutputLock(OutputLock&& other) noexcept;
  OutputLock& operator=(OutputLock&&) = delete;
  OutputLock(const OutputLock&) = delete;
  ~OutputLock();  ///< removes the lock file and releases the lock

  /// This process as recorded in the lock file.
  const LockOwner& owner() const { return m_owner; }
  /// The owner recorded in a lock file this run took over (its process had ended), if any.
  const std::optional<LockOwner>& taken_over() const { return m_taken_over; }
  const std::string& path() const { return m_path; }

 private:
  OutputLock(std::string path, int fd, LockOwner owner, std::optional<LockOwner> taken_over);
  std::string m_path;
  int m_fd = -1;
  LockOwner m_owner;
  std::optional<LockOwner> m_taken_over;
};

}  // namespace dayphoton::study
