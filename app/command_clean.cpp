// `dayphoton clean TARGET`: remove from the cache of an output folder what the last complete
// run did not use (study/cache_folder.h), or the whole cache with --all. The output folder's
// lock is held meanwhile, so no run reads an artefact while it goes. See docs/cache.md.
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <string>
#include <system_error>

#include "commands.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/cache_folder.h"
#include "dayphoton/study/output_lock.h"

namespace dayphoton::app {

namespace {

std::string megabytes(std::uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f MB", double(bytes) / 1e6);
  return text;
}

/// The output folder TARGET names: itself, or a project file's outputs.folder.
std::string output_folder_of(const std::string& target) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(target, ec)) return target;
  if (fs::is_regular_file(target, ec)) return project::load_project(target).outputs.folder;
  throw UsageError("'" + target + "' is neither an output folder nor a project file");
}

}  // namespace

int run_clean(const CleanOptions& options, std::ostream& out) {
  namespace fs = std::filesystem;
  const std::string output = output_folder_of(options.target);
  const std::string cache = options.cache_dir.empty() ? study::default_cache_folder(output) : options.cache_dir;
  std::error_code ec;
  if (!fs::is_directory(cache, ec)) {
    out << "no cache at " << cache << ": nothing to remove\n";
    require_written(out, "standard output");
    return ExitOk;
  }
  // A run writing this output folder (and its cache) holds the lock: wait for none, fail.
  const study::OutputLock lock = study::OutputLock::acquire(output, "dayphoton clean " + options.target);
  if (options.all) {
    std::uint64_t bytes = 0;
    std::size_t files = 0;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(cache, ec))
      if (e.is_regular_file(ec)) {
        bytes += e.file_size(ec);
        ++files;
      }
    if (!options.dry_run) {
      fs::remove_all(cache, ec);
      if (ec) throw std::runtime_error("cannot remove the cache " + cache + ": " + ec.message());
    }
    out << (options.dry_run ? "would remove " : "removed ") << cache << ": " << files << " files, "
        << megabytes(bytes) << '\n';
  } else {
    const study::CachePruning p = study::prune_cache(cache, options.dry_run);
    out << (options.dry_run ? "would remove " : "removed ") << p.removed_files << " artefacts ("
        << megabytes(p.removed_bytes) << ") that the last complete run did not use; kept " << p.kept_files
        << " (" << megabytes(p.kept_bytes) << ") in " << cache << '\n';
  }
  require_written(out, "standard output");
  return ExitOk;
}

}  // namespace dayphoton::app
