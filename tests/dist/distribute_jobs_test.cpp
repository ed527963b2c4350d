#include "dayphoton/dist/distribute_jobs.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <mutex>
#include <stdexcept>
#include <string>

#include "dayphoton/dist/distributed_job_error.h"
#include "dayphoton/dist/serial_communicator.h"
#include "in_process_ranks.h"

namespace dayphoton::dist {
namespace {

/// Job i's result: i + 1 bytes, a function of i alone.
ByteBuffer result_of(std::size_t i) {
  ByteBuffer out(i + 1);
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = static_cast<std::byte>((i * 31 + k * 7) & 0xff);
  return out;
}

double cost_of(std::size_t i) { return static_cast<double>((i * 37) % 11); }

/// Everything a rank saw delivered, in delivery order.
struct Delivered {
  std::vector<std::size_t> order;
  std::vector<ByteBuffer> bytes;
};

JobSet jobs_into(Delivered& d, std::size_t count) {
  JobSet jobs;
  jobs.count = count;
  jobs.cost_of = cost_of;
  jobs.compute = result_of;
  jobs.deliver = [&d](std::size_t i, ByteBuffer b) {
    d.order.push_back(i);
    d.bytes.push_back(std::move(b));
  };
  jobs.name_of = [](std::size_t i) { return "source " + std::to_string(i); };
  return jobs;
}

void expect_all_in_order(const Delivered& d, std::size_t count) {
  ASSERT_EQ(d.order.size(), count);
  for (std::size_t i = 0; i < count; ++i) {
    EXPECT_EQ(d.order[i], i);
    EXPECT_EQ(d.bytes[i], result_of(i));
  }
}

TEST(DistributeJobs, OneProcessDeliversEveryResultInIndexOrder) {
  auto comm = make_serial_communicator();
  Delivered d;
  tbb::task_arena arena(4);
  arena.execute([&] { distribute_jobs(*comm, jobs_into(d, 50)); });
  expect_all_in_order(d, 50);
}

TEST(DistributeJobs, TheShortSignature) {
  auto comm = make_serial_communicator();
  Delivered d;
  distribute_jobs(
      *comm, 5, cost_of, result_of, [&](std::size_t i, ByteBuffer b) {
        d.order.push_back(i);
        d.bytes.push_back(std::move(b));
      });
  expect_all_in_order(d, 5);
}

struct LocatedProblem : std::runtime_error {
  using std::runtime_error::runtime_error;
};

TEST(DistributeJobs, OneProcessRethrowsTheJobsOwnExceptionAndDeliversNothing) {
  auto comm = make_serial_communicator();
  Delivered d;
  JobSet jobs = jobs_into(d, 20);
  jobs.compute = [](std::size_t i) -> ByteBuffer {
    if (i == 13) throw LocatedProblem("project.yaml:3:4: error: bad");
    return result_of(i);
  };
  EXPECT_THROW(distribute_jobs(*comm, jobs), LocatedProblem);
  EXPECT_TRUE(d.order.empty());
}

TEST(DistributeJobs, BadCostsAndMissingCallbacksAreRefused) {
  auto comm = make_serial_communicator();
  Delivered d;
  JobSet jobs = jobs_into(d, 3);
  jobs.cost_of = [](std::size_t i) { return i == 2 ? -1.0 : 1.0; };
  EXPECT_THROW(distribute_jobs(*comm, jobs), std::invalid_argument);
  jobs = jobs_into(d, 3);
  jobs.deliver = nullptr;
  EXPECT_THROW(distribute_jobs(*comm, jobs), std::invalid_argument);
}

TEST(DistributeJobs, NoJobsIsNothingToDo) {
  Delivered d;
  auto errors = test::run_ranks(3, [&](Communicator& comm) {
    Delivered mine;
    distribute_jobs(comm, jobs_into(mine, 0));
    EXPECT_TRUE(mine.order.empty());
  });
  for (auto& e : errors) EXPECT_FALSE(e);
}

class DistributeJobsOnRanks : public ::testing::TestWithParam<int> {};

TEST_P(DistributeJobsOnRanks, RankZeroGetsTheSameBytesAsOneProcess) {
  const int ranks = GetParam();
  std::vector<Delivered> seen(static_cast<std::size_t>(ranks));
  std::vector<std::atomic<int>> computed_on(37);
  const auto errors = test::run_ranks(ranks, [&](Communicator& comm) {
    JobSet jobs = jobs_into(seen[static_cast<std::size_t>(comm.rank())], 37);
    jobs.compute = [&, rank = comm.rank()](std::size_t i) {
      computed_on[i] = rank;
      return result_of(i);
    };
    distribute_jobs(comm, jobs);
  });
  for (auto& e : errors) EXPECT_FALSE(e);
  expect_all_in_order(seen[0], 37);
  for (int r = 1; r < ranks; ++r) EXPECT_TRUE(seen[static_cast<std::size_t>(r)].order.empty());
  // Every rank did some of the work (37 jobs, at most 4 ranks).
  std::vector<int> per_rank(static_cast<std::size_t>(ranks), 0);
  for (auto& r : computed_on) ++per_rank[static_cast<std::size_t>(r.load())];
  for (int n : per_rank) EXPECT_GT(n, 0);
}

TEST_P(DistributeJobsOnRanks, EveryRankDeliveryGivesEveryRankAllResults) {
  const int ranks = GetParam();
  std::vector<Delivered> seen(static_cast<std::size_t>(ranks));
  const auto errors = test::run_ranks(ranks, [&](Communicator& comm) {
    JobSet jobs = jobs_into(seen[static_cast<std::size_t>(comm.rank())], 23);
    jobs.delivery = Delivery::every_rank;
    distribute_jobs(comm, jobs);
  });
  for (auto& e : errors) EXPECT_FALSE(e);
  for (const Delivered& d : seen) expect_all_in_order(d, 23);
}

TEST_P(DistributeJobsOnRanks, AThrowingJobFailsEveryRankWithTheSameLocatedMessage) {
  const int ranks = GetParam();
  std::vector<Delivered> seen(static_cast<std::size_t>(ranks));
  int owner_of_failure = -1;
  const auto errors = test::run_ranks(ranks, [&](Communicator& comm) {
    JobSet jobs = jobs_into(seen[static_cast<std::size_t>(comm.rank())], 30);
    jobs.compute = [&, rank = comm.rank()](std::size_t i) -> ByteBuffer {
      if (i == 17) {
        owner_of_failure = rank;
        throw std::runtime_error("no photons left the sky");
      }
      return result_of(i);
    };
    distribute_jobs(comm, jobs);
  });
  ASSERT_GE(owner_of_failure, 0);
  const std::string expected =
      "rank " + std::to_string(owner_of_failure) + ", job 17 (source 17): no photons left the sky";
  for (int r = 0; r < ranks; ++r) {
    ASSERT_TRUE(errors[static_cast<std::size_t>(r)]) << "rank " << r;
    try {
      std::rethrow_exception(errors[static_cast<std::size_t>(r)]);
    } catch (const DistributedJobError& e) {
      EXPECT_EQ(e.what(), expected);
      EXPECT_EQ(e.failed_rank(), owner_of_failure);
      EXPECT_EQ(e.failed_job(), 17u);
      EXPECT_EQ(e.job_message(), "no photons left the sky");
    } catch (...) {
      ADD_FAILURE() << "rank " << r << ": not a DistributedJobError";
    }
    EXPECT_TRUE(seen[static_cast<std::size_t>(r)].order.empty());
  }
}

TEST_P(DistributeJobsOnRanks, AFailedDeliveryFailsEveryRankAfterDrainingTheResults) {
  const int ranks = GetParam();
  const auto errors = test::run_ranks(ranks, [&](Communicator& comm) {
    Delivered d;
    JobSet jobs = jobs_into(d, 12);
    jobs.deliver = [](std::size_t i, ByteBuffer) {
      if (i == 4) throw std::runtime_error("disk full");
    };
    distribute_jobs(comm, jobs);
  });
  for (int r = 0; r < ranks; ++r) {
    ASSERT_TRUE(errors[static_cast<std::size_t>(r)]);
    try {
      std::rethrow_exception(errors[static_cast<std::size_t>(r)]);
    } catch (const DistributedJobError& e) {
      EXPECT_STREQ(e.what(), "rank 0, delivery of job 4 (source 4): disk full");
    }
  }
}

TEST_P(DistributeJobsOnRanks, RanksThatDisagreeOnTheJobCountAllFail) {
  const int ranks = GetParam();
  const auto errors = test::run_ranks(ranks, [&](Communicator& comm) {
    Delivered d;
    distribute_jobs(comm, jobs_into(d, comm.rank() == ranks - 1 ? 9 : 8));
  });
  for (auto& e : errors) {
    ASSERT_TRUE(e);
    try {
      std::rethrow_exception(e);
    } catch (const std::runtime_error& x) {
      EXPECT_NE(std::string(x.what()).find("has 9 jobs, rank 0 has 8"), std::string::npos) << x.what();
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Ranks, DistributeJobsOnRanks, ::testing::Values(2, 3, 4));

}  // namespace
}  // namespace dayphoton::dist
