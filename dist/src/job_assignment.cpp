#include "dayphoton/dist/job_assignment.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>
#include <stdexcept>
#include <string>
#include <utility>

namespace dayphoton::dist {

double JobAssignment::makespan() const {
  return cost_of_rank.empty() ? 0.0 : *std::max_element(cost_of_rank.begin(), cost_of_rank.end());
}

JobAssignment assign_jobs(const std::vector<double>& cost_of_job, int rank_count) {
  if (rank_count < 1) throw std::invalid_argument("dist: " + std::to_string(rank_count) + " ranks");
  for (std::size_t i = 0; i < cost_of_job.size(); ++i)
    if (!std::isfinite(cost_of_job[i]) || cost_of_job[i] < 0.0)
      throw std::invalid_argument("dist: job " + std::to_string(i) + " has cost " +
                                  std::to_string(cost_of_job[i]) + ", not a finite number >= 0");

  std::vector<std::size_t> order(cost_of_job.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return cost_of_job[a] > cost_of_job[b]; });

  JobAssignment out;
  out.owner_of_job.assign(cost_of_job.size(), 0);
  out.cost_of_rank.assign(static_cast<std::size_t>(rank_count), 0.0);
  // Least-loaded rank first, then the lowest rank: (load, rank) pairs in a min-heap.
  using Load = std::pair<double, int>;
  std::priority_queue<Load, std::vector<Load>, std::greater<Load>> ranks;
  for (int r = 0; r < rank_count; ++r) ranks.push({0.0, r});
  for (std::size_t job : order) {
    auto [load, r] = ranks.top();
    ranks.pop();
    out.owner_of_job[job] = r;
    load += cost_of_job[job];
    out.cost_of_rank[static_cast<std::size_t>(r)] = load;
    ranks.push({load, r});
  }
  return out;
}

}  // namespace dayphoton::dist
