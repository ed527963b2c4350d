#pragma once
// The error every rank throws when a job of distribute_jobs failed on some rank.
#include <cstddef>
#include <stdexcept>
#include <string>

namespace dayphoton::dist {

class DistributedJobError : public std::runtime_error {
 public:
  /// what(): "rank R, job J (NAME): MESSAGE", or "rank R, delivery of job J (NAME): MESSAGE"
  /// when rank 0's deliver failed.
  DistributedJobError(int failed_rank, std::size_t failed_job, const std::string& job_name,
                      const std::string& message, bool in_delivery);

  int failed_rank() const { return m_rank; }
  std::size_t failed_job() const { return m_job; }
  /// The failing job's own message (its exception's what()).
  const std::string& job_message() const { return m_message; }

 private:
  int m_rank;
  std::size_t m_job;
  std::string m_message;
};

}  // namespace dayphoton::dist
