// A program run by run_mpi_test.sh under mpirun with 1, 2 and 3 ranks (and without mpirun):
//   distribute_jobs_check results      rank 0 prints a digest of everything delivered to it;
//                                      every rank prints the digest of its every-rank delivery
//   distribute_jobs_check throw        rank 1's first job throws; every rank prints its error
//   distribute_jobs_check kill         rank 1's first job kills its own process (SIGKILL)
// Job 7's result is larger than one message (MaxChunkBytes), so chunking is exercised.
#include <tbb/task_arena.h>

#include <algorithm>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "dayphoton/dist/distribute_jobs.h"
#include "dayphoton/dist/distributed_job_error.h"
#include "dayphoton/dist/job_assignment.h"
#include "dayphoton/dist/launcher.h"
#include "dayphoton/dist/message_limits.h"
#include "dayphoton/dist/mpi_session.h"
#include "dayphoton/dist/serial_communicator.h"

namespace {

using namespace dayphoton::dist;

constexpr std::size_t JobCount = 40;
constexpr std::size_t BigJob = 7;

double cost_of(std::size_t i) { return 1.0 + static_cast<double>((i * 13) % 9); }

/// Job i's result, a function of i alone: xorshift64 words (G. Marsaglia, "Xorshift RNGs",
/// J. Stat. Softw. 8(14), 2003), then a few bytes more so that sizes are no multiple of 8.
ByteBuffer result_of(std::size_t i) {
  const std::size_t n = i == BigJob ? MaxChunkBytes + 3 : 100 + 17 * i;
  ByteBuffer out(n);
  std::uint64_t x = 0x9e3779b97f4a7c15ull * (i + 1);
  for (std::size_t k = 0; k < n; k += 8) {
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    std::memcpy(out.data() + k, &x, std::min<std::size_t>(8, n - k));
  }
  return out;
}

/// FNV-1a, 64 bit, over (index, size, 8-byte words of the bytes) of each delivery in order.
struct Digest {
  std::uint64_t h = 0xcbf29ce484222325ull;
  void add(std::uint64_t v) {
    h ^= v;
    h *= 0x100000001b3ull;
  }
  void add(const ByteBuffer& b) {
    for (std::size_t k = 0; k < b.size(); k += 8) {
      std::uint64_t w = 0;
      std::memcpy(&w, b.data() + k, std::min<std::size_t>(8, b.size() - k));
      add(w);
    }
  }
};

int first_job_of_rank_one(int size) {
  const std::vector<int> owner = [&] {
    std::vector<double> costs(JobCount);
    for (std::size_t i = 0; i < JobCount; ++i) costs[i] = cost_of(i);
    return assign_jobs(costs, size).owner_of_job;
  }();
  for (std::size_t i = 0; i < JobCount; ++i)
    if (owner[i] == 1) return static_cast<int>(i);
  return -1;
}

int run(Communicator& comm, const std::string& mode) {
  const int fail_job = comm.size() > 1 ? first_job_of_rank_one(comm.size()) : -1;
  JobSet jobs;
  jobs.count = JobCount;
  jobs.cost_of = cost_of;
  jobs.name_of = [](std::size_t i) { return "job " + std::to_string(i); };
  jobs.compute = [&](std::size_t i) {
    if (static_cast<int>(i) == fail_job && mode == "throw") throw std::runtime_error("deliberate failure on rank 1");
    if (static_cast<int>(i) == fail_job && mode == "kill") std::raise(SIGKILL);
    return result_of(i);
  };
  Digest digest;
  std::size_t next = 0;
  bool in_order = true;
  jobs.deliver = [&](std::size_t i, ByteBuffer b) {
    in_order = in_order && i == next++;
    digest.add(i);
    digest.add(b.size());
    digest.add(b);
  };
  try {
    tbb::task_arena arena(2);
    arena.execute([&] { distribute_jobs(comm, jobs); });
    if (comm.rank() == RootRank)
      std::printf("root digest %016llx in_order %d\n", (unsigned long long)digest.h, in_order);
    digest = Digest{};
    next = 0;
    jobs.delivery = Delivery::every_rank;
    arena.execute([&] { distribute_jobs(comm, jobs); });
    std::printf("every-rank digest %016llx in_order %d\n", (unsigned long long)digest.h, in_order);
    std::fflush(stdout);
  } catch (const DistributedJobError& e) {
    // One write per line: mpirun forwards the ranks' streams as they come, so a line written in
    // pieces could interleave with another rank's.
    const std::string line = std::string("error: ") + e.what() + "\n";
    std::fwrite(line.data(), 1, line.size(), stderr);
    std::fflush(stderr);
    return 3;
  }
  comm.barrier();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "results";
  if (mode != "results" && mode != "throw" && mode != "kill") {
    std::cerr << "usage: distribute_jobs_check results|throw|kill\n";
    return 2;
  }
  if (!detect_launcher([](const char* name) { return std::getenv(name); })) {
    auto comm = make_serial_communicator();
    return run(*comm, mode);
  }
  MpiSession session(&argc, &argv);
  int code = 0;
  {
    auto comm = session.world();
    code = run(*comm, mode);
  }
  return code;
}
