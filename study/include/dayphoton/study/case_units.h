// Whole cases as units over the ranks of an MPI run (docs/cluster.md, "Variants as units").
//
// A project with variants has several cases (the base project and each variant), whose
// steps are independent. When there are at least as many cases as ranks, the distributed
// executor (distributed_executor.h) hands each rank whole cases, dealt out by their
// estimated cost (case_cost.h, assign_case_units), instead of sharing every step of every
// case over all ranks: run_study first runs the cases each rank owns with
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
//
// Several projects of one command (`dayphoton run a.yaml b.yaml`) are units the same way:
// every case of every project is a unit, each project's units use its own cache folder, and
// rank 0 stores each artefact it receives in the cache of the project it belongs to; then
// each project runs as usual, its steps from its cache (docs/cluster.md "Projects as units").
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dayphoton/dist/communicator.h"
#include "dayphoton/study/artifact_store.h"
#include "dayphoton/study/step_executor.h"

namespace dayphoton::study {

/// One unit: case `case_index` (0: the base project, 1...: its variants in order) of project
/// `project` (the command's projects in order; 0 for a run of one project), and its estimated
/// cost (case_cost.h).
struct CaseUnit {
  std::size_t project = 0;
  std::size_t case_index = 0;
  double cost_seconds = 0;
};

/// The rank of each unit, from the units' costs: longest processing time first
/// (dist::assign_jobs: units by decreasing cost, ties by the lower index, each to the least
/// loaded rank, ties by the lower rank), with the ranks counted from the last (the greedy's
/// rank r is rank ranks - 1 - r), so rank 0, which writes every case afterwards, is the last
/// of equally loaded ranks to be given a unit. With equal costs unit c goes to rank
/// ranks - 1 - (c mod ranks). Within 4/3 - 1/(3 ranks) of the best makespan (R. L. Graham,
/// "Bounds on multiprocessing timing anomalies", SIAM J. Appl. Math. 17(2), 1969). A pure
/// function of the costs; under MPI rank 0 alone computes it, from its own estimates, and
/// sends it to the other ranks (make_case_units), so that the ranks cannot disagree.
std::vector<int> assign_case_units(const std::vector<double>& costs, int ranks);

class CaseUnits {
 public:
  virtual ~CaseUnits() = default;
  /// Whether this process computes unit `unit`'s steps (an index into the units given).
  virtual bool mine(std::size_t unit) const = 0;
  /// The executor of this process's own units of project `project` (its cache).
  virtual StepExecutor& executor(std::size_t project) = 0;
  /// Collective: the artefacts the other ranks computed reach rank 0, which stores each in its
  /// project's cache, in rank order. Returns the run log's line about the assignment (the
  /// same on every rank).
  virtual std::string join() = 0;
};

/// The `cases` cases of one project as units over `comm`'s ranks when there are at least as
/// many cases as ranks (and more than one rank, and no `force`); null otherwise.
/// `case_costs`: each case's estimate (case_costs_seconds), called only then (on every rank,
/// which fail alike on a bad case), assigned by assign_case_units on rank 0. Collective when it
/// returns units: rank 0 sends every rank the assignment and its estimates (they replace the
/// rank's own, in the run log's line too); and in join().
std::unique_ptr<CaseUnits> make_case_units(dist::Communicator& comm, const ArtifactStore& store, bool force,
                                           std::size_t cases, const std::function<std::vector<double>()>& case_costs);

/// The cases of several projects (one command's) as units: `stores[p]` is project p's cache
/// (each must outlive the units), `units` every case of every project (the costs of the
/// ranks other than 0 are not used). Null under the same conditions (fewer units than ranks,
/// one rank, `force`); collective as the other.
std::unique_ptr<CaseUnits> make_case_units(dist::Communicator& comm, const std::vector<const ArtifactStore*>& stores,
                                           bool force, const std::vector<CaseUnit>& units);

}  // namespace dayphoton::study
