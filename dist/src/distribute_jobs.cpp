#include "dayphoton/dist/distribute_jobs.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <exception>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

#include "dayphoton/dist/distributed_job_error.h"
#include "dayphoton/dist/job_assignment.h"
#include "dayphoton/dist/message_limits.h"
#include "wire_format.h"

namespace dayphoton::dist {
namespace {

/// Results travel from their owner to rank 0 with this tag (dist/'s own range).
constexpr int ResultTag = LastCallerTag + 1;

constexpr std::uint64_t NoFailure = std::numeric_limits<std::uint64_t>::max();

/// A failed job as a rank saw it.
struct Failure {
  std::uint64_t job = NoFailure;
  int rank = 0;
  std::string name;
  std::string message;
  std::exception_ptr exception;  // kept for the one-process path only

  bool failed() const { return job != NoFailure; }
};

std::string message_of(const std::exception_ptr& e) {
  try {
    std::rethrow_exception(e);
  } catch (const std::exception& x) {
    return x.what();
  } catch (...) {
    return "an exception that is no std::exception";
  }
}

std::string name_of(const JobSet& jobs, std::size_t job) {
  if (!jobs.name_of) return {};
  try {
    return jobs.name_of(job);
  } catch (...) {
    return {};
  }
}

/// The lowest-index failure of the jobs `mine` (indices into the job set), computed with TBB
/// into `results`. After a failure no further job starts.
Failure compute_jobs(const JobSet& jobs, const std::vector<std::size_t>& mine, std::vector<ByteBuffer>& results,
                     int rank) {
  results.assign(mine.size(), ByteBuffer{});
  Failure first;
  std::mutex first_mutex;
  std::atomic<bool> stop{false};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mine.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t k = r.begin(); k != r.end(); ++k) {
      if (stop.load(std::memory_order_relaxed)) return;
      const std::size_t job = mine[k];
      try {
        results[k] = jobs.compute(job);
        if (results[k].size() > MaxBufferBytes)
          throw std::length_error("a result of " + std::to_string(results[k].size()) + " bytes, above the limit of " +
                                  std::to_string(MaxBufferBytes) + " bytes");
      } catch (...) {
        std::lock_guard<std::mutex> lock(first_mutex);
        stop = true;
        if (job < first.job) {
          first.job = job;
          first.rank = rank;
          first.exception = std::current_exception();
        }
      }
    }
  });
  if (first.failed()) {
    first.message = message_of(first.exception);
    first.name = name_of(jobs, first.job);
  }
  return first;
}

ByteBuffer encode(const Failure& f) {
  ByteBuffer out;
  wire::put_u64(out, f.job);
  wire::put_u64(out, static_cast<std::uint64_t>(f.rank));
  wire::put_string(out, f.name);
  wire::put_string(out, f.message);
  return out;
}

Failure decode_failure(const ByteBuffer& in) {
  wire::Reader r(in);
  Failure f;
  f.job = r.u64();
  f.rank = static_cast<int>(r.u64());
  f.name = r.string();
  f.message = r.string();
  return f;
}

/// Collective: every rank passes its own failure (or none); every rank returns the failure of
/// the lowest job index over all ranks (ties: lowest rank), or none.
Failure agree_on_failure(Communicator& comm, const Failure& mine) {
  const std::vector<ByteBuffer> all = comm.gather_to_root(encode(mine));
  ByteBuffer verdict;
  if (comm.rank() == RootRank) {
    Failure first;
    for (const ByteBuffer& b : all) {
      Failure f = decode_failure(b);
      if (f.job < first.job || (f.failed() && f.job == first.job && f.rank < first.rank)) first = std::move(f);
    }
    verdict = encode(first);
  }
  comm.broadcast_from_root(verdict);
  return decode_failure(verdict);
}

void check_callbacks(const JobSet& jobs) {
  if (!jobs.compute || !jobs.deliver || !jobs.cost_of)
    throw std::invalid_argument("distribute_jobs: compute, deliver and cost_of are required");
}

std::vector<double> costs_of(const JobSet& jobs) {
  std::vector<double> costs(jobs.count);
  for (std::size_t i = 0; i < jobs.count; ++i) costs[i] = jobs.cost_of(i);
  return costs;
}

/// One process: a parallel loop; the first (lowest-index) exception propagates unchanged.
void run_in_one_process(const JobSet& jobs) {
  assign_jobs(costs_of(jobs), 1);  // the costs are checked alike for every rank count
  std::vector<std::size_t> all(jobs.count);
  for (std::size_t i = 0; i < jobs.count; ++i) all[i] = i;
  std::vector<ByteBuffer> results;
  const Failure failure = compute_jobs(jobs, all, results, RootRank);
  if (failure.failed()) std::rethrow_exception(failure.exception);
  for (std::size_t i = 0; i < jobs.count; ++i) jobs.deliver(i, std::move(results[i]));
}

/// Collective: every rank's job count checked against rank 0's, rank 0's assignment of the
/// jobs to ranks. A disagreement or a bad cost is a std::runtime_error on every rank.
std::vector<int> agree_on_assignment(Communicator& comm, const JobSet& jobs) {
  ByteBuffer count;
  wire::put_u64(count, jobs.count);
  const std::vector<ByteBuffer> counts = comm.gather_to_root(count);
  ByteBuffer decision;
  if (comm.rank() == RootRank) {
    std::string problem;
    for (std::size_t r = 0; r < counts.size() && problem.empty(); ++r) {
      const std::uint64_t n = wire::Reader(counts[r]).u64();
      if (n != jobs.count)
        problem = "rank " + std::to_string(r) + " has " + std::to_string(n) + " jobs, rank 0 has " +
                  std::to_string(jobs.count);
    }
    JobAssignment assignment;
    if (problem.empty()) {
      try {
        assignment = assign_jobs(costs_of(jobs), comm.size());
      } catch (const std::exception& e) {
        problem = e.what();
      }
    }
    wire::put_string(decision, problem);
    if (problem.empty())
      for (int owner : assignment.owner_of_job) wire::put_u64(decision, static_cast<std::uint64_t>(owner));
  }
  comm.broadcast_from_root(decision);
  wire::Reader r(decision);
  const std::string problem = r.string();
  if (!problem.empty()) throw std::runtime_error("distribute_jobs: " + problem);
  std::vector<int> owner(jobs.count);
  for (int& o : owner) o = static_cast<int>(r.u64());
  return owner;
}

}  // namespace

void distribute_jobs(Communicator& comm, const JobSet& jobs) {
  check_callbacks(jobs);
  if (comm.size() == 1) {
    run_in_one_process(jobs);
    return;
  }
  const int me = comm.rank();
  const std::vector<int> owner = agree_on_assignment(comm, jobs);

  std::vector<std::size_t> mine;
  std::vector<std::size_t> slot_of_job(jobs.count, 0);  // index into `results` of my own jobs
  for (std::size_t i = 0; i < jobs.count; ++i)
    if (owner[i] == me) {
      slot_of_job[i] = mine.size();
      mine.push_back(i);
    }
  std::vector<ByteBuffer> results;
  const Failure failed = agree_on_failure(comm, compute_jobs(jobs, mine, results, me));
  if (failed.failed()) throw DistributedJobError(failed.rank, failed.job, failed.name, failed.message, false);

  // Delivery in index order. Senders send their jobs in increasing index, which is the order
  // rank 0 receives them in (MPI's non-overtaking rule, MPI 3.1 section 3.5).
  Failure delivery_failure;
  const bool everyone = jobs.delivery == Delivery::every_rank;
  for (std::size_t i = 0; i < jobs.count; ++i) {
    ByteBuffer bytes;
    if (owner[i] == me) {
      bytes = std::move(results[slot_of_job[i]]);
      if (me != RootRank) {
        comm.send(RootRank, ResultTag, bytes);
        bytes = ByteBuffer{};
      }
    } else if (me == RootRank) {
      bytes = comm.receive(owner[i], ResultTag);
    }
    if (everyone) comm.broadcast_from_root(bytes);
    if ((me == RootRank || everyone) && !delivery_failure.failed()) {
      try {
        jobs.deliver(i, std::move(bytes));
      } catch (...) {
        delivery_failure.job = i;
        delivery_failure.rank = me;
        delivery_failure.message = message_of(std::current_exception());
        delivery_failure.name = name_of(jobs, i);
      }
    }
  }
  const Failure delivered = agree_on_failure(comm, delivery_failure);
  if (delivered.failed())
    throw DistributedJobError(delivered.rank, delivered.job, delivered.name, delivered.message, true);
}

void distribute_jobs(Communicator& comm, std::size_t job_count, const std::function<double(std::size_t job)>& cost_of,
                     const std::function<ByteBuffer(std::size_t job)>& compute,
                     const std::function<void(std::size_t job, ByteBuffer bytes)>& deliver) {
  JobSet jobs;
  jobs.count = job_count;
  jobs.cost_of = cost_of;
  jobs.compute = compute;
  jobs.deliver = deliver;
  distribute_jobs(comm, jobs);
}

}  // namespace dayphoton::dist
