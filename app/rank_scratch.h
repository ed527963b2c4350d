// The scratch folder of an MPI rank other than 0 (docs/cluster.md): every rank runs the whole
// study, but only rank 0 writes the results folder and the cache; the others write theirs into
// a folder of their own, `<temp>/dayphoton-rank-<rank>-<pid>`, removed when the run ends.
//
// A rank that is killed (SIGKILL, out of memory, or ended by the launcher after another rank
// failed) cannot remove its folder. So each rank holds an flock(2) on `<folder>/.scratch.lock`
// for its whole run: the kernel releases it however the process ends. Before making its own
// folder, a rank removes every `dayphoton-rank-*` folder of the temp folder whose lock is free,
// i.e. whose rank no longer runs. A killed run's scratch therefore lasts until the next
// distributed run on that node, never longer.
#pragma once

#include <string>

namespace dayphoton::app {

class RankScratch {
 public:
  /// Removes the stale scratch folders of `temp_folder`, then makes and locks this rank's.
  /// Throws std::runtime_error (naming the folder) if it cannot be made or locked.
  RankScratch(const std::string& temp_folder, int rank);
  RankScratch(const RankScratch&) = delete;
  RankScratch& operator=(const RankScratch&) = delete;
  ~RankScratch();  ///< removes the folder and releases the lock

  const std::string& folder() const { return m_folder; }

  static constexpr const char* NamePrefix = "dayphoton-rank-";
  static constexpr const char* LockName = ".scratch.lock";

  /// Removes the `dayphoton-rank-*` folders of `temp_folder` whose lock is free; returns how
  /// many. A folder without a lock file (being made, or of an older version) is left alone.
  static int remove_stale(const std::string& temp_folder);

 private:
  std::string m_folder;
  int m_lock_fd = -1;
};

}  // namespace dayphoton::app
