#include "dayphoton/dist/job_assignment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>

namespace dayphoton::dist {
namespace {

TEST(AssignJobs, LongestFirstToTheLeastLoadedRank) {
  // Sorted: j0 (5), j1 (4), j2 (3), j3 (3), j4 (3). j0 -> r0 (5), j1 -> r1 (4), j2 -> r1 (7),
  // j3 -> r0 (8), j4 -> r1 (10).
  const JobAssignment a = assign_jobs({5, 4, 3, 3, 3}, 2);
  EXPECT_EQ(a.owner_of_job, (std::vector<int>{0, 1, 1, 0, 1}));
  EXPECT_EQ(a.cost_of_rank, (std::vector<double>{8, 10}));
  EXPECT_EQ(a.makespan(), 10);
}

TEST(AssignJobs, TiesGoToTheLowerIndexAndTheLowerRank) {
  const JobAssignment a = assign_jobs({1, 1, 1, 1}, 3);
  EXPECT_EQ(a.owner_of_job, (std::vector<int>{0, 1, 2, 0}));
}

TEST(AssignJobs, MoreRanksThanJobsLeavesRanksIdle) {
  const JobAssignment a = assign_jobs({2, 1}, 4);
  EXPECT_EQ(a.owner_of_job, (std::vector<int>{0, 1}));
  EXPECT_EQ(a.cost_of_rank, (std::vector<double>{2, 1, 0, 0}));
}

TEST(AssignJobs, NoJobs) {
  const JobAssignment a = assign_jobs({}, 3);
  EXPECT_TRUE(a.owner_of_job.empty());
  EXPECT_EQ(a.makespan(), 0);
}

TEST(AssignJobs, WithinGrahamsBoundOfTheLowerBound) {
  // Graham (1969): LPT <= (4/3 - 1/(3m)) OPT, and OPT <= LPT; with OPT >= max(sum/m, max job)
  // and LPT <= sum/m + max job for any list schedule, check both closed-form bounds on 2000
  // random instances (fixed seed).
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> cost(0.0, 10.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const int m = 1 + trial % 7;
    std::vector<double> costs(1 + trial % 23);
    for (double& c : costs) c = cost(rng);
    const JobAssignment a = assign_jobs(costs, m);
    const double sum = std::accumulate(costs.begin(), costs.end(), 0.0);
    const double longest = *std::max_element(costs.begin(), costs.end());
    const double lower = std::max(sum / m, longest);
    EXPECT_GE(a.makespan(), lower - 1e-9);
    EXPECT_LE(a.makespan(), sum / m + longest + 1e-9);
    EXPECT_NEAR(std::accumulate(a.cost_of_rank.begin(), a.cost_of_rank.end(), 0.0), sum, 1e-9);
  }
}

TEST(AssignJobs, RefusesBadCostsAndRankCounts) {
  EXPECT_THROW(assign_jobs({1}, 0), std::invalid_argument);
  EXPECT_THROW(assign_jobs({1, -1}, 2), std::invalid_argument);
  EXPECT_THROW(assign_jobs({std::nan("")}, 2), std::invalid_argument);
  EXPECT_THROW(assign_jobs({std::numeric_limits<double>::infinity()}, 2), std::invalid_argument);
}

}  // namespace
}  // namespace dayphoton::dist
