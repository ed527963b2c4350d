#include "dayphoton/dist/launcher.h"

#include <cerrno>
#include <cstdlib>

namespace dayphoton::dist {
namespace {

/// The number a variable holds, 0 when it is no positive whole number.
int process_count_of(const char* text) {
  if (text == nullptr) return 0;
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || errno == ERANGE || v < 1 || v > 1 << 24) return 0;
  return static_cast<int>(v);
}

}  // namespace

std::optional<LauncherInfo> detect_launcher(const EnvironmentLookup& getenv_lookup) {
  if (const char* v = getenv_lookup("OMPI_COMM_WORLD_SIZE"))
    return LauncherInfo{"OMPI_COMM_WORLD_SIZE", process_count_of(v)};
  if (getenv_lookup("PMIX_RANK") != nullptr) return LauncherInfo{"PMIX_RANK", 0};
  if (const char* v = getenv_lookup("PMI_SIZE")) return LauncherInfo{"PMI_SIZE", process_count_of(v)};
  if (const char* v = getenv_lookup("SLURM_STEP_NUM_TASKS"); v != nullptr && getenv_lookup("SLURM_STEP_ID") != nullptr)
    return LauncherInfo{"SLURM_STEP_NUM_TASKS", process_count_of(v)};
  return std::nullopt;
}

}  // namespace dayphoton::dist
