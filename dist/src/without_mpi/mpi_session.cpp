// MpiSession of a build without MPI (CMake option DAYPHOTON_MPI=OFF): refuses to start.
#include "dayphoton/dist/mpi_session.h"

namespace dayphoton::dist {

bool mpi_compiled_in() { return false; }

MpiSession::MpiSession(int*, char***) {
  throw MpiUnavailable(
      "this dayphoton was built without MPI (CMake option DAYPHOTON_MPI=OFF) but was started by a parallel "
      "launcher; rebuild with Open MPI (libopenmpi-dev) or run it without mpirun/srun");
}

MpiSession::~MpiSession() = default;

std::unique_ptr<Communicator> MpiSession::world() const {
  throw MpiUnavailable("this dayphoton was built without MPI");
}

}  // namespace dayphoton::dist
