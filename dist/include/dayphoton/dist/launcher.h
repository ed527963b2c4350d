#pragma once
// Was this process started by a parallel launcher (Open MPI's mpirun/mpiexec, Slurm's srun,
// a PMI or PMIx process manager)? Decided from the environment alone, before MPI is touched,
// so an ordinary run never initialises MPI.
//
// Variables read, first found wins:
//   OMPI_COMM_WORLD_SIZE  Open MPI's mpirun (Open MPI documentation, "Environment variables
//                         set for MPI applications", docs.open-mpi.org, section 11.1)
//   PMIX_RANK             a PMIx server: srun --mpi=pmix, prterun
//   PMI_SIZE              a PMI-1/PMI-2 server: srun --mpi=pmi2, MPICH's hydra
//   SLURM_STEP_NUM_TASKS  a Slurm job step started by srun (sbatch(1) and srun(1) "OUTPUT
//                         ENVIRONMENT VARIABLES"); only with SLURM_STEP_ID set, since a batch
//                         script's own shell is no step of several tasks
#include <functional>
#include <optional>
#include <string>

namespace dayphoton::dist {

struct LauncherInfo {
  std::string variable;    ///< the environment variable that told (for messages)
  int process_count = 0;   ///< the number of processes it announces, 0 when it does not say
};

/// Looks up an environment variable (std::getenv in production, a map in tests).
using EnvironmentLookup = std::function<const char*(const char* name)>;

/// The launcher this process was started by, or nothing for an ordinary run.
std::optional<LauncherInfo> detect_launcher(const EnvironmentLookup& getenv_lookup);

}  // namespace dayphoton::dist
