#include "dayphoton/dist/distributed_job_error.h"

namespace dayphoton::dist {
namespace {

std::string describe(int rank, std::size_t job, const std::string& name, const std::string& message,
                     bool in_delivery) {
  std::string out = "rank " + std::to_string(rank) + ", " + (in_delivery ? "delivery of job " : "job ") +
                    std::to_string(job);
  if (!name.empty()) out += " (" + name + ")";
  return out + ": " + message;
}

}  // namespace

DistributedJobError::DistributedJobError(int failed_rank, std::size_t failed_job, const std::string& job_name,
                                         const std::string& message, bool in_delivery)
    : std::runtime_error(describe(failed_rank, failed_job, job_name, message, in_delivery)),
      m_rank(failed_rank),
      m_job(failed_job),
      m_message(message) {}

}  // namespace dayphoton::dist
