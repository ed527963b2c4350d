// Whole cases as units over the ranks of an MPI run (docs/cluster.md, "Variants as units").
//
// A project with variants has several cases (the base project and each variant), whose
// steps are independent. When there are at least as many cases as ranks, the distributed
// executor (distributed_executor.h) hands each rank whole cases instead of sharing every
// step of every case over all ranks: run_study first runs the cases each rank owns with
// that rank's own executor (this machine's cores, TBB; no message), then join() brings what
// the other ranks computed to rank 0, which stores it in the cache; then every case runs as
// before through the distributed executor, every step of it now from the cache. So the
// outputs are those of a one-process run whose artefacts came from the cache, byte for byte,
// and the cache holds the artefacts one process stores.
//
// A unit executor reads the cache folder itself (rank 0's writes it; the other ranks' only
// read it, so on a cache folder every node sees, a re-run takes their cases' steps from it,
// and elsewhere they compute them again: the same bytes). It writes nothing: the other ranks
// keep their artefacts in memory until join(), and their results are not written (their
// writes_results() is false), nor is their annual multiply made.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "dayphoton/dist/communicator.h"
#include "dayphoton/study/artifact_store.h"
#include "dayphoton/study/step_executor.h"

namespace dayphoton::study {

class CaseUnits {
 public:
  virtual ~CaseUnits() = default;
  /// Whether this process computes case `c`'s steps (0: the base project, 1...: the variants).
  virtual bool mine(std::size_t c) const = 0;
  /// The executor of this process's own cases.
  virtual StepExecutor& executor() = 0;
  /// Collective: the artefacts the other ranks computed reach rank 0, which stores them, in
  /// rank order. Returns the run log's line about the assignment (the same on every rank).
  virtual std::string join() = 0;
};

/// Cases as units over `comm`'s ranks when there are at least as many `cases` as ranks (and
/// more than one rank, and no `force`); null otherwise. Case c goes to rank ranks - 1 - (c mod ranks), so
/// rank 0, which writes every case's files afterwards, gets the fewest. Collective only in
/// join().
std::unique_ptr<CaseUnits> make_case_units(dist::Communicator& comm, const ArtifactStore& store, bool force,
                                           std::size_t cases);

}  // namespace dayphoton::study
