// ArtifactStore: the cache of a run's intermediate results, one file per artefact under
// <output folder>/.cache/, named <kind>-<key>.bin (key = ContentHash::hex() of its inputs).
//
// Every file is written atomically (temporary file + rename, core/atomic_file.h) and framed:
// magic "DPHA", format version, the kind, the payload size and a 64-bit checksum of the
// payload. A truncated, corrupted or foreign file is treated as absent (and reported by
// read() through `problem`), so an interrupted run (kill -9) simply recomputes what it had
// not finished: that is how `dayphoton run` resumes.
#pragma once

#include <optional>
#include <string>

namespace dayphoton::study {

class ArtifactStore {
 public:
  /// Uses (and creates on first write) `directory`.
  explicit ArtifactStore(std::string directory);

  const std::string& directory() const { return m_directory; }
  std::string path_for(const std::string& kind, const std::string& key) const;

  /// True if a readable, intact artefact exists.
  bool contains(const std::string& kind, const std::string& key) const;
  /// Write atomically (throws std::runtime_error naming the path on failure).
  void write(const std::string& kind, const std::string& key, const std::string& payload) const;
  /// The payload, or nothing if absent or damaged (`problem`, if given, says which).
  std::optional<std::string> read(const std::string& kind, const std::string& key,
                                  std::string* problem = nullptr) const;

 private:
  std::string m_directory;
};

}  // namespace dayphoton::study
