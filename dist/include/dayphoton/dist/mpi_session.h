#pragma once
// MPI for the lifetime of one process: MPI_Init_thread (MPI_THREAD_FUNNELED: only the main
// thread calls MPI, TBB's workers never do) in the constructor, MPI_Finalize in the destructor.
// Create one only when detect_launcher() says the process was started by mpirun or srun.
//
// Built without MPI (CMake option DAYPHOTON_MPI=OFF), mpi_compiled_in() is false and the
// constructor throws MpiUnavailable: several copies of one serial run writing one output
// folder would be wrong, so a launch by mpirun of such a build is refused.
#include <memory>
#include <stdexcept>

#include "dayphoton/dist/communicator.h"

namespace dayphoton::dist {

/// True when this build links Open MPI (CMake option DAYPHOTON_MPI).
bool mpi_compiled_in();

class MpiUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class MpiSession {
 public:
  /// Initialises MPI (throws MpiUnavailable when not compiled in, std::runtime_error when
  /// MPI_Init_thread fails or cannot give MPI_THREAD_FUNNELED).
  MpiSession(int* argc, char*** argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  /// The ranks of MPI_COMM_WORLD (a duplicate of it, so our messages meet no one else's).
  /// Destroy every communicator before the session.
  std::unique_ptr<Communicator> world() const;
};

}  // namespace dayphoton::dist
