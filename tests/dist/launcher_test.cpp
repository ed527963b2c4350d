#include "dayphoton/dist/launcher.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace dayphoton::dist {
namespace {

EnvironmentLookup lookup_in(const std::map<std::string, std::string>& env) {
  return [env](const char* name) -> const char* {
    auto it = env.find(name);
    return it == env.end() ? nullptr : it->second.c_str();
  };
}

TEST(DetectLauncher, AnOrdinaryRunHasNone) {
  EXPECT_FALSE(detect_launcher(lookup_in({{"HOME", "/root"}, {"SLURM_JOB_ID", "7"}})));
}

TEST(DetectLauncher, OpenMpiMpirun) {
  const auto l = detect_launcher(lookup_in({{"OMPI_COMM_WORLD_SIZE", "3"}, {"OMPI_COMM_WORLD_RANK", "1"}}));
  ASSERT_TRUE(l);
  EXPECT_EQ(l->variable, "OMPI_COMM_WORLD_SIZE");
  EXPECT_EQ(l->process_count, 3);
}

TEST(DetectLauncher, PmixAndPmi) {
  EXPECT_EQ(detect_launcher(lookup_in({{"PMIX_RANK", "0"}}))->variable, "PMIX_RANK");
  const auto pmi = detect_launcher(lookup_in({{"PMI_SIZE", "64"}}));
  EXPECT_EQ(pmi->variable, "PMI_SIZE");
  EXPECT_EQ(pmi->process_count, 64);
}

TEST(DetectLauncher, SlurmOnlyInsideAJobStep) {
  // A batch script's own shell has job variables but no step started by srun.
  EXPECT_FALSE(detect_launcher(lookup_in({{"SLURM_STEP_NUM_TASKS", "4"}})));
  const auto l = detect_launcher(lookup_in({{"SLURM_STEP_NUM_TASKS", "4"}, {"SLURM_STEP_ID", "0"}}));
  ASSERT_TRUE(l);
  EXPECT_EQ(l->process_count, 4);
}

TEST(DetectLauncher, AnUnreadableCountIsZeroNotAGuess) {
  EXPECT_EQ(detect_launcher(lookup_in({{"OMPI_COMM_WORLD_SIZE", "three"}}))->process_count, 0);
  EXPECT_EQ(detect_launcher(lookup_in({{"OMPI_COMM_WORLD_SIZE", "-2"}}))->process_count, 0);
}

}  // namespace
}  // namespace dayphoton::dist
