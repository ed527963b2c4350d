#pragma once
// distribute_jobs: run N independent jobs over the ranks of a communicator, threads within
// each rank, and hand every result to rank 0 (or to every rank) in job index order.
//
//   1. Agreement: every rank passes the same job count; rank 0 evaluates cost_of(i) for all
//      jobs, computes assign_jobs (job_assignment.h) and broadcasts it.
//   2. Each rank computes its own jobs with tbb::parallel_for (in the caller's task arena, so
//      the caller's thread limit holds). After a job throws, the rank starts no further job.
//   3. Agreement on the outcome: every rank reports success or its lowest-index failure to
//      rank 0, which broadcasts the verdict. On any failure EVERY rank throws the same
//      DistributedJobError (rank, job, name, message) and nothing is delivered; no rank waits
//      forever on a rank that failed.
//   4. Delivery: rank 0 receives the results and calls deliver(i, bytes) for i = 0, 1, ...,
//      N - 1, one at a time on the calling thread; with Delivery::every_rank, rank 0 also
//      broadcasts each result and every rank calls deliver in the same order.
//   5. If deliver throws, the remaining results are drained, and every rank throws a
//      DistributedJobError naming the delivery.
//
// Results are independent of the rank and thread counts as long as compute(i) is a pure
// function of i: assignment only decides where a job runs, never what it yields or the order
// of delivery. compute may run concurrently with itself (other jobs) on several threads.
//
// With one rank (the serial communicator) no message is sent, and an exception of compute or
// deliver propagates unchanged (an InputError keeps its located diagnostics), so the
// single-process path behaves as a plain parallel loop.
//
// A rank that dies (killed, out of memory) cannot report: MPI then ends the whole job (Open
// MPI's mpirun aborts all processes when one exits abnormally), which distribute_jobs relies
// on rather than on time-outs.
#include <cstddef>
#include <functional>
#include <string>

#include "dayphoton/dist/byte_buffer.h"
#include "dayphoton/dist/communicator.h"

namespace dayphoton::dist {

enum class Delivery {
  root_only,   ///< deliver is called on rank 0 only
  every_rank,  ///< every rank receives every result (e.g. photon maps every rank gathers from)
};

struct JobSet {
  std::size_t count = 0;
  /// An estimate of job i's run time, in any unit (same for all jobs); finite, >= 0.
  /// Called on rank 0 only.
  std::function<double(std::size_t job)> cost_of;
  /// Job i's result. Called on the owning rank, possibly on several threads at once.
  std::function<ByteBuffer(std::size_t job)> compute;
  /// Receives job i's result, in index order, on rank 0 (or every rank, see Delivery).
  std::function<void(std::size_t job, ByteBuffer bytes)> deliver;
  /// Optional: a name for job i in error messages ("source 3"); the index alone if empty.
  std::function<std::string(std::size_t job)> name_of;
  Delivery delivery = Delivery::root_only;
};

void distribute_jobs(Communicator& comm, const JobSet& jobs);

/// The same, results to rank 0 only, jobs named by their index.
void distribute_jobs(Communicator& comm, std::size_t job_count,
                     const std::function<double(std::size_t job)>& cost_of,
                     const std::function<ByteBuffer(std::size_t job)>& compute,
                     const std::function<void(std::size_t job, ByteBuffer bytes)>& deliver);

}  // namespace dayphoton::dist
