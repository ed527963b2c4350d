// The distributed step executor: a run's steps (plan_step.h) shared out over the ranks of an
// MPI job (dist/communicator.h), for `mpirun -np N dayphoton run` (docs/cluster.md).
//
// Every rank runs the same run_study on the same project (SPMD): every rank builds the same
// plan and meets the same steps in the same order; only this executor's methods talk. Rank 0
// alone reads and writes the cache: lookup() and run_batch() broadcast its verdict and the
// cached bytes, which every rank takes, so every rank follows the same branch and holds the
// same typed values. The misses of a batch are the jobs of one dist::distribute_jobs call
// (longest first over the ranks by the steps' cost estimates, Step::cost, themselves shared
// out first; TBB within a rank); every result is delivered to every rank in step order (each
// takes it, as if from the cache) and rank 0 stores it. A step's result is a pure function
// of its inputs and travels as the cache's own bytes, so the outputs are those of a
// one-process run whose artefacts came from the cache: byte-identical to it.
//
// Big photon sources (a step whose predicted cost exceeds 1/SplitSourceFactor of a rank's
// share of its batch, plan_policy.h) are not one job: their passes are traced in attempt
// ranges over the ranks, with the passes' counts summed on every rank
// (split_photon_steps.h); their artefacts are the same bytes.
//
// A single step that estimates a grid (a grid's sky or sun coefficients, its direct sun) goes
// by sensor blocks (plan_step.h SensorBlocks) when it has more than `block_size` sensors: the
// blocks are the jobs of one distribute_jobs, rank 0 joins them in sensor order into the
// whole grid's artefact (the same bytes, cache key and file as one process makes) and every
// rank takes it. The accuracy rounds are a collective step (Step::collective): every rank runs
// them, sharing their attempt ranges and sensor blocks through round_work()
// (distributed_round_work.h), and rank 0 stores the result.
//
// With at least as many cases (the base project and its variants) as ranks, case_units()
// hands out whole cases (case_units.h): each rank computes its own cases' steps alone, rank 0
// stores them, and the cases then run through this executor from the cache.
//
// writes_results() is true on rank 0 alone: run_study's writer flag (study_runner.h), so the
// other ranks write nothing at all (no output folder, no run.log, no cache).
#pragma once

#include <cstddef>
#include <memory>

#include "dayphoton/dist/communicator.h"
#include "dayphoton/study/artifact_store.h"
#include "dayphoton/study/plan_policy.h"
#include "dayphoton/study/step_executor.h"

namespace dayphoton::study {

/// An executor over `comm`'s ranks; `comm` must outlive it. With one rank it behaves as the
/// local executor (same cache use, same results). `block_size`: sensors per block of a grid
/// step (plan_policy.h; tests use smaller ones).
std::unique_ptr<StepExecutor> make_distributed_executor(dist::Communicator& comm, const ArtifactStore& store,
                                                        bool force, std::size_t block_size = SensorBlockSize);

}  // namespace dayphoton::study
