// The cache folder beside the output folder, and its pruning (cache_folder.h).
#include "dayphoton/study/cache_folder.h"

#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>
#include <system_error>

#include "dayphoton/core/atomic_file.h"

namespace dayphoton::study {

namespace fs = std::filesystem;

std::string default_cache_folder(const std::string& output_dir) {
  fs::path out = fs::path(output_dir).lexically_normal();
  if (out.filename().empty()) out = out.parent_path();  // "results/"
  const std::string name = out.filename().string();
  if (name.empty() || name == "." || name == "..") {
    out = fs::absolute(out).lexically_normal();
    if (out.filename().empty()) out = out.parent_path();  // "<dir>/." -> "<dir>/" -> "<dir>"
  }
  if (out.filename().empty() || out == out.root_path())  // the root: no parent to put it in
    return (fs::path(output_dir) / ".cache").string();
  return (out.parent_path() / ("." + out.filename().string() + "-cache")).string();
}

std::string legacy_cache_folder(const std::string& output_dir) {
  return (fs::path(output_dir) / ".cache").string();
}

bool adopt_legacy_cache(const std::string& output_dir, const std::string& cache_dir) {
  const fs::path legacy = legacy_cache_folder(output_dir);
  std::error_code ec;
  if (fs::path(cache_dir).lexically_normal() == legacy.lexically_normal()) return false;
  if (!fs::is_directory(legacy, ec) || fs::exists(cache_dir, ec)) return false;
  fs::rename(legacy, cache_dir, ec);
  return !ec;
}

void write_used_list(const ArtifactStore& store) {
  std::error_code ec;
  fs::create_directories(store.directory(), ec);
  std::string text;
  for (const std::string& name : store.used_files()) text += name + "\n";
  write_file_atomically((fs::path(store.directory()) / UsedListName).string(), text);
}

CachePruning prune_cache(const std::string& cache_dir, bool dry_run) {
  const fs::path list_path = fs::path(cache_dir) / UsedListName;
  std::ifstream list(list_path);
  if (!list)
    throw std::runtime_error("the cache " + cache_dir + " has no " + UsedListName +
                             ": no run has completed with it, so what it can reuse is unknown (run the project "
                             "first, or delete the folder)");
  std::set<std::string> keep;
  for (std::string line; std::getline(list, line);)
    if (!line.empty()) keep.insert(line);
  if (!dry_run) remove_dead_temporaries(cache_dir);
  CachePruning result;
  std::error_code listing;
  fs::directory_iterator entries(cache_dir, listing);
  if (listing) throw std::runtime_error("cannot read the cache " + cache_dir + ": " + listing.message());
  for (const fs::directory_entry& e : entries) {
    std::error_code ec;
    if (!e.is_regular_file(ec) || e.path().extension() != ".bin") continue;
    const std::uint64_t bytes = e.file_size(ec);
    if (keep.count(e.path().filename().string())) {
      ++result.kept_files;
      result.kept_bytes += bytes;
      continue;
    }
    if (!dry_run && !fs::remove(e.path(), ec))
      throw std::runtime_error("cannot remove " + e.path().string() + ": " + ec.message());
    ++result.removed_files;
    result.removed_bytes += bytes;
  }
  return result;
}

}  // namespace dayphoton::study
