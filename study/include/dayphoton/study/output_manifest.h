// What a run wrote into its output folder, and the marker that says the folder is incomplete
// (docs/outputs.md, "Complete or marked incomplete").
//
// A run into a folder:
//   1. begin(): writes the marker file INCOMPLETE, then removes summary.json and every output
//      file of the previous run into the folder: those listed in its summary.json `files`, or,
//      if that run was interrupted, in its INCOMPLETE marker;
//   2. record(): each output file, once written, is appended to the marker at once, so an
//      interrupted run leaves the list of what it wrote;
//   3. entries(): size and SHA-256 of every recorded file, for summary.json `files`;
//   4. finish(): after summary.json, the last output, is written: removes the marker.
// So a folder is complete exactly when it holds summary.json and no INCOMPLETE; a killed run
// leaves INCOMPLETE and only files it wrote itself, never a mix with an earlier run's.
// Paths are relative to the folder; a listed path that is absolute or climbs out of the folder
// ("..") is never removed.
#pragma once

#include <cstdint>
#include <fstream>
#include <set>
#include <string>
#include <vector>

namespace dayphoton::study {

struct ManifestEntry {
  std::string path;  ///< relative to the output folder, '/'-separated
  std::uint64_t bytes = 0;
  std::string sha256;  ///< 64 lowercase hex digits
};

class OutputManifest {
 public:
  static constexpr const char* MarkerName = "INCOMPLETE";
  static constexpr const char* SummaryName = "summary.json";

  /// Start a run into the existing folder `dir` (steps 1 above). `run` describes the run in
  /// the marker's text (e.g. "pid 12, started ..."). Throws std::runtime_error naming the
  /// file when the marker cannot be written.
  static OutputManifest begin(const std::string& dir, const std::string& run);

  /// The manifest of a process that writes nothing into `dir` (the ranks other than 0 of an
  /// MPI run): no marker, nothing removed, no entries; record() throws std::logic_error, since
  /// such a process must not have written an output.
  static OutputManifest none(const std::string& dir);

  /// How many files of the previous run begin() removed.
  std::size_t stale_removed() const { return m_stale_removed; }

  /// Record output files just written (paths inside the folder, as the run built them).
  void record(const std::string& path);
  void record(const std::vector<std::string>& paths);

  /// Size and SHA-256 of every recorded file, sorted by path.
  std::vector<ManifestEntry> entries() const;

  /// The run is complete (summary.json written): remove the marker.
  void finish();

  const std::string& dir() const { return m_dir; }

 private:
  OutputManifest(std::string dir, std::size_t stale_removed);
  std::string m_dir;
  std::size_t m_stale_removed = 0;
  bool m_writes = true;  ///< false: none()
  std::set<std::string> m_recorded;
  std::ofstream m_marker;
};

/// The relative paths listed in a summary.json text's `files` (empty if it has none or is not
/// JSON); used by begin() and by the tests.
std::vector<std::string> manifest_paths(const std::string& summary_json);

/// Whether `relative` names a file inside the folder: not empty, not absolute, no ".." part.
bool stays_inside(const std::string& relative);

}  // namespace dayphoton::study
