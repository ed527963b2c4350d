// Tests for study/output_lock.h: the lock file records the holder; a second taker (even in
// the same process, through another open file) is refused with the holder named; a lock file
// whose flock is free (its process died) is taken over and its owner reported; releasing
// removes the file.
#include "dayphoton/study/output_lock.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include "../temp_folder.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

using test::empty_dir;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(OutputLock, RecordsTheHolderAndRemovesTheFileOnRelease) {
  const fs::path dir = empty_dir("output_lock_a");
  {
    const OutputLock lock = OutputLock::acquire(dir.string(), "dayphoton run p.yaml");
    EXPECT_FALSE(lock.taken_over());
    EXPECT_EQ(lock.owner().pid, ::getpid());
    EXPECT_EQ(lock.owner().command, "dayphoton run p.yaml");
    const std::string text = slurp(dir / OutputLock::FileName);
    EXPECT_NE(text.find("pid " + std::to_string(::getpid()) + "\n"), std::string::npos) << text;
    EXPECT_NE(text.find("started 20"), std::string::npos) << text;
    EXPECT_NE(text.find("command dayphoton run p.yaml\n"), std::string::npos) << text;
  }
  EXPECT_FALSE(fs::exists(dir / OutputLock::FileName));
  fs::remove_all(dir);
}

TEST(OutputLock, SecondTakerIsRefusedNamingTheHolder) {
  const fs::path dir = empty_dir("output_lock_b");
  const OutputLock first = OutputLock::acquire(dir.string(), "dayphoton run a.yaml");
  try {
    OutputLock::acquire(dir.string(), "dayphoton run b.yaml");
    FAIL() << "a held lock was taken twice";
  } catch (const OutputFolderBusy& e) {
    EXPECT_EQ(e.owner().pid, ::getpid());
    const std::string what = e.what();
    EXPECT_NE(what.find("in use by another dayphoton run: pid " + std::to_string(::getpid())), std::string::npos) << what;
    EXPECT_NE(what.find("started 20"), std::string::npos) << what;
    EXPECT_NE(what.find("dayphoton run a.yaml"), std::string::npos) << what;
  }
  EXPECT_TRUE(fs::exists(dir / OutputLock::FileName));  // the refused taker leaves it alone
  fs::remove_all(dir);
}

TEST(OutputLock, LockFileOfADeadProcessIsTakenOver) {
  const fs::path dir = empty_dir("output_lock_c");
  // What a killed run leaves: the file with its details, no flock held on it.
  std::ofstream(dir / OutputLock::FileName) << "pid 4194301\nhost elsewhere\nstarted 2026-01-02T03:04:05Z\ncommand dayphoton run old.yaml\n";
  const OutputLock lock = OutputLock::acquire(dir.string(), "dayphoton run new.yaml");
  ASSERT_TRUE(lock.taken_over());
  EXPECT_EQ(lock.taken_over()->pid, 4194301);
  EXPECT_EQ(lock.taken_over()->describe(),
            "pid 4194301 on host elsewhere, started 2026-01-02T03:04:05Z (dayphoton run old.yaml)");
  EXPECT_NE(slurp(dir / OutputLock::FileName).find("pid " + std::to_string(::getpid())), std::string::npos);
  fs::remove_all(dir);
}

TEST(OutputLock, MissingFolderGivesAnErrorNamingTheLockFile) {
  const fs::path dir = test::process_temp_dir() / "output_lock_missing" / "nested";
  fs::remove_all(dir.parent_path());
  try {
    OutputLock::acquire(dir.string(), "x");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find((dir / OutputLock::FileName).string()), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dayphoton::study
