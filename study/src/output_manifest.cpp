// OutputManifest: see output_manifest.h.
#include "dayphoton/study/output_manifest.h"

#include <cerrno>
#include <cstring>
#include <exception>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <tbb/parallel_for.h>

#include "dayphoton/core/atomic_file.h"
#include "dayphoton/core/error_text.h"
#include "dayphoton/core/sha256.h"

namespace dayphoton::study {

namespace {

namespace fs = std::filesystem;

/// The line after which the marker lists files, one per line.
constexpr const char* FilesHeading = "files written so far:";

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The files an interrupted run listed in its marker.
std::vector<std::string> marker_paths(const std::string& text) {
  std::vector<std::string> paths;
  std::istringstream in(text);
  std::string line;
  bool listing = false;
  while (std::getline(in, line)) {
    if (listing && !line.empty()) paths.push_back(line);
    if (line == FilesHeading) listing = true;
  }
  return paths;
}

std::string relative_to(const fs::path& dir, const std::string& path) {
  return fs::path(path).lexically_normal().lexically_relative(dir.lexically_normal()).generic_string();
}

}  // namespace

bool stays_inside(const std::string& relative) {
  if (relative.empty() || relative.find('\0') != std::string::npos) return false;
  const fs::path p(relative);
  if (p.is_absolute() || p.has_root_name() || p.has_root_directory()) return false;
  for (const fs::path& part : p)
    if (part == ".." || part == "." || part.empty()) return false;
  return true;
}

std::vector<std::string> manifest_paths(const std::string& summary_json) {
  std::vector<std::string> paths;
  const nlohmann::json summary = nlohmann::json::parse(summary_json, nullptr, false);
  if (summary.is_discarded() || !summary.is_object()) return paths;
  const auto files = summary.find("files");
  if (files == summary.end() || !files->is_array()) return paths;
  for (const nlohmann::json& f : *files)
    if (f.is_object() && f.contains("path") && f["path"].is_string()) paths.push_back(f["path"].get<std::string>());
  return paths;
}

OutputManifest::OutputManifest(std::string dir, std::size_t stale_removed)
    : m_dir(std::move(dir)), m_stale_removed(stale_removed) {}

OutputManifest OutputManifest::begin(const std::string& dir, const std::string& run) {
  const fs::path folder(dir);
  const fs::path marker = folder / MarkerName, summary = folder / SummaryName;
  // Files of the previous run: a complete one's manifest, an interrupted one's marker.
  std::set<std::string> stale;
  for (const std::string& p : manifest_paths(read_text(summary)))
    if (stays_inside(p)) stale.insert(p);
  for (const std::string& p : marker_paths(read_text(marker)))
    if (stays_inside(p)) stale.insert(p);
  stale.erase(MarkerName);

  // The marker first, listing the stale files until they are gone (a kill while removing
  // them leaves them listed for the next run), then no summary.json: the folder is marked
  // incomplete before anything in it changes.
  std::ostringstream text;
  text << "This folder is being written by `dayphoton run` (" << run << "), or that run was interrupted.\n"
       << "Its files are incomplete until the run writes summary.json and removes this file; run the\n"
       << "project again to complete it (finished steps come from the cache in .cache/).\n"
       << FilesHeading << "\n";
  for (const std::string& p : stale) text << p << "\n";
  write_file_atomically(marker.string(), text.str());
  std::error_code ec;
  fs::remove(summary, ec);
  if (ec) throw std::runtime_error("cannot remove " + summary.string() + ": " + ec.message());

  std::size_t removed = 0;
  for (const std::string& p : stale) {
    const fs::path file = folder / p;
    if (fs::is_directory(fs::symlink_status(file, ec))) continue;  // never a folder's content
    if (fs::remove(file, ec)) ++removed;
    // Folders the previous run created and that are now empty go too (never the folder itself).
    for (fs::path parent = fs::path(p).parent_path(); !parent.empty(); parent = parent.parent_path())
      if (!fs::remove(folder / parent, ec)) break;  // fails unless empty
  }

  OutputManifest manifest(dir, removed);
  manifest.m_marker.open(marker, std::ios::app | std::ios::binary);
  if (!manifest.m_marker) throw std::runtime_error("cannot append to " + marker.string() + ": " + error_text(errno));
  return manifest;
}

OutputManifest OutputManifest::none(const std::string& dir) {
  OutputManifest manifest(dir, 0);
  manifest.m_writes = false;
  return manifest;
}

void OutputManifest::record(const std::string& path) {
  if (!m_writes) throw std::logic_error("output " + path + " written by a process that writes nothing");
  const std::string relative = relative_to(fs::path(m_dir), path);
  if (!stays_inside(relative)) throw std::logic_error("output " + path + " is not inside " + m_dir);
  if (!m_recorded.insert(relative).second) return;
  m_marker << relative << "\n";
  m_marker.flush();
  if (!m_marker) throw std::runtime_error("cannot append to " + (fs::path(m_dir) / MarkerName).string());
}

void OutputManifest::record(const std::vector<std::string>& paths) {
  for (const std::string& p : paths) record(p);
}

std::vector<ManifestEntry> OutputManifest::entries() const {
  std::vector<ManifestEntry> out;
  for (const std::string& relative : m_recorded) {  // std::set: sorted
    ManifestEntry e;
    e.path = relative;
    out.push_back(std::move(e));
  }
  // The files are independent: hashed in parallel, each into its own entry (grain 1: one
  // large file, illuminance.bin, is most of the bytes); a failure is reported for the first
  // such file in path order, whatever the threads.
  std::vector<std::exception_ptr> failures(out.size());
  tbb::parallel_for(std::size_t(0), out.size(), [&](std::size_t i) {
    try {
      out[i].sha256 = sha256_file_hex((fs::path(m_dir) / out[i].path).string(), &out[i].bytes);
    } catch (...) {
      failures[i] = std::current_exception();
    }
  });
  for (const std::exception_ptr& f : failures)
    if (f) std::rethrow_exception(f);
  return out;
}

void OutputManifest::finish() {
  if (!m_writes) return;
  m_marker.close();
  std::error_code ec;
  fs::remove(fs::path(m_dir) / MarkerName, ec);
  if (ec) throw std::runtime_error("cannot remove " + (fs::path(m_dir) / MarkerName).string() + ": " + ec.message());
}

}  // namespace dayphoton::study
