#pragma once
// Which rank computes which job: longest processing time first (R. L. Graham, "Bounds on
// multiprocessing timing anomalies", SIAM J. Appl. Math. 17(2), 1969: the greedy list
// schedule on jobs sorted by decreasing time, within 4/3 - 1/(3m) of the optimal makespan).
// Jobs sorted by decreasing cost (ties: lower index first), each given to the rank with the
// least assigned cost so far (ties: lower rank). A pure function of the costs and the rank
// count: every rank computes the same assignment, and a result never depends on it.
#include <cstddef>
#include <vector>

namespace dayphoton::dist {

struct JobAssignment {
  std::vector<int> owner_of_job;        ///< rank computing job i
  std::vector<double> cost_of_rank;     ///< sum of the costs assigned to each rank
  /// max over ranks of cost_of_rank: the predicted wall time in cost units.
  double makespan() const;
};

/// Throws std::invalid_argument for rank_count < 1 or a cost that is negative or not finite.
JobAssignment assign_jobs(const std::vector<double>& cost_of_job, int rank_count);

}  // namespace dayphoton::dist
