// Where a run's cache lives and how it is pruned (docs/cache.md "Where", "Pruning").
//
// The cache is kept OUT of the results a user ships: beside the output folder, as the hidden
// folder ".<output name>-cache" (results/ -> .results-cache/), so each output folder has its
// own cache (two runs into two folders never share one, and the output folder's lock guards
// both), and zipping or copying the results folder takes no cache with it. `run --cache DIR`
// puts it elsewhere (a shared cache of several output folders is safe: every artefact is
// written atomically and named by the hash of its inputs).
//
// Pruning: a complete run writes the list of the artefacts it read or wrote
// (UsedListName); everything else in the folder was made for inputs the project no longer
// has, so `dayphoton clean` removes it. Without a list (no run has completed) nothing is
// pruned.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dayphoton/study/artifact_store.h"

namespace dayphoton::study {

/// The cache folder of an output folder: "<parent>/.<name>-cache".
std::string default_cache_folder(const std::string& output_dir);

/// The cache folder of earlier versions, inside the output folder.
std::string legacy_cache_folder(const std::string& output_dir);

/// If the output folder still holds the cache of an earlier version and `cache_dir` does not
/// exist, move it there (a rename: nothing is recomputed). True if it moved.
bool adopt_legacy_cache(const std::string& output_dir, const std::string& cache_dir);

/// The list of a complete run's artefacts, in the cache folder.
constexpr const char* UsedListName = "used-by-last-run.txt";

/// Write the store's used_files() as the cache folder's UsedListName (atomic).
void write_used_list(const ArtifactStore& store);

struct CachePruning {
  std::size_t kept_files = 0, removed_files = 0;
  std::uint64_t kept_bytes = 0, removed_bytes = 0;
};

/// Remove every artefact (`*.bin`) of `cache_dir` that its UsedListName does not name, and
/// the temporaries of writers that no longer run. `dry_run`: count only. Throws
/// std::runtime_error when the folder has no list (no run completed there, so what is
/// reusable is unknown) or cannot be read.
CachePruning prune_cache(const std::string& cache_dir, bool dry_run);

}  // namespace dayphoton::study
