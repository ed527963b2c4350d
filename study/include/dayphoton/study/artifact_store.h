// ArtifactStore: the cache of a run's intermediate results, one file per artefact in the
// cache folder (cache_folder.h: beside the output folder, not in it), named
// <kind>-<key>.bin (key = ContentHash::hex() of its inputs).
// docs/cache.md describes the whole cache: keys, framing, atomicity, invalidation, resume.
//
// Every file is written atomically (temporary file "<name>.tmp.<pid>" + rename,
// core/atomic_file.h; not fsync'ed: a file torn by a power failure fails its checksum and is
// recomputed, and a sync per artefact made the office's photon pass 2.7 times slower) and framed, all integers little-endian:
//   "DPHA"                    magic (4 bytes)
//   u32 format version        FormatVersion
//   u32 length + bytes        the kind
//   u32 length + bytes        the key (so a file copied or renamed to another key is refused)
//   u64 payload size
//   u64 payload checksum      64-bit, four-lane multiply-rotate over the payload's words
//   payload
// A truncated, corrupted or foreign file is treated as absent (and reported by read()
// through `problem`), so an interrupted run (kill -9) simply recomputes what it had not
// finished: that is how `dayphoton run` resumes. Temporary files left by a killed write
// never match an artefact's name and are ignored.
//
// Thread safety: all methods may be called from several threads. Writes of different keys
// run in parallel; writes of the same path within one process are serialised (the
// temporary file name carries only the pid), and across processes the rename makes the
// last complete write win.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace dayphoton::study {

class ArtifactStore {
 public:
  static constexpr std::uint32_t FormatVersion = 1;

  /// Uses (and creates on first write) `directory`.
  explicit ArtifactStore(std::string directory);

  const std::string& directory() const { return m_directory; }
  /// <directory>/<kind>-<key>.bin. Kind and key must be non-empty, made of letters, digits,
  /// '_', '-' and '.', and not start with '.' (throws std::invalid_argument otherwise).
  std::string path_for(const std::string& kind, const std::string& key) const;

  /// True if a readable, intact artefact exists (reads and checks the whole file; when the
  /// payload is wanted anyway, call read() alone).
  bool contains(const std::string& kind, const std::string& key) const;
  /// Write atomically, creating the directory if needed (throws std::runtime_error naming
  /// the path on failure).
  void write(const std::string& kind, const std::string& key, const std::string& payload) const;
  /// The payload, or nothing if absent or damaged (`problem`, if given, says which:
  /// "missing", or what is wrong with the file).
  std::optional<std::string> read(const std::string& kind, const std::string& key,
                                  std::string* problem = nullptr) const;

  /// The file names (<kind>-<key>.bin) of every artefact this store read intact or wrote,
  /// sorted: what the run that used it can reuse (cache_folder.h, pruning).
  std::vector<std::string> used_files() const;

 private:
  struct Used;
  std::string m_directory;
  std::shared_ptr<Used> m_used;  ///< shared by copies: they are the same store
};

}  // namespace dayphoton::study
