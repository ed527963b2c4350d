// Tests for core/atomic_file.h: contents land complete, an exception in the writer leaves
// neither the target nor a temporary file, an unwritable folder gives a runtime_error
// naming the path, and an existing target is replaced only on success.
#include "dayphoton/core/atomic_file.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <sys/wait.h>
#include <unistd.h>

#include "../temp_folder.h"

namespace dayphoton {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

using test::empty_dir;

std::size_t file_count(const fs::path& dir) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir)) (void)e, ++n;
  return n;
}

TEST(AtomicFile, WritesStringAndReplacesExisting) {
  const fs::path dir = empty_dir("atomic_file_test_a");
  const fs::path target = dir / "out.csv";
  write_file_atomically(target.string(), "index,x\n0,1\n");
  EXPECT_EQ(slurp(target), "index,x\n0,1\n");
  write_file_atomically(target.string(), "replaced\n");
  EXPECT_EQ(slurp(target), "replaced\n");
  EXPECT_EQ(file_count(dir), 1u);  // no temporary left behind
  fs::remove_all(dir);
}

TEST(AtomicFile, BinaryStream) {
  const fs::path dir = empty_dir("atomic_file_test_b");
  const fs::path target = dir / "data.bin";
  const std::string bytes("\x00\x01\xff\n\r", 5);
  write_file_atomically(target.string(), [&](std::ostream& out) { out.write(bytes.data(), 5); }, true);
  EXPECT_EQ(slurp(target), bytes);
  fs::remove_all(dir);
}

TEST(AtomicFile, WriterExceptionKeepsOldFileAndRemovesTemporary) {
  const fs::path dir = empty_dir("atomic_file_test_c");
  const fs::path target = dir / "out.txt";
  write_file_atomically(target.string(), "old\n");
  EXPECT_THROW(write_file_atomically(target.string(),
                                     [](std::ostream& out) {
                                       out << "half";
                                       throw std::logic_error("writer failed");
                                     }),
               std::logic_error);
  EXPECT_EQ(slurp(target), "old\n");
  EXPECT_EQ(file_count(dir), 1u);
  fs::remove_all(dir);
}

TEST(AtomicFile, MissingFolderGivesErrorNamingPath) {
  const fs::path dir = empty_dir("atomic_file_test_d");
  const fs::path target = dir / "no_such_folder" / "out.txt";
  try {
    write_file_atomically(target.string(), "x");
    FAIL() << "expected runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_folder"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(target));
  fs::remove_all(dir);
}

/// The id of a process that has exited (forked, reaped): no process has it, until reused.
pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

TEST(AtomicFile, TemporaryFileOwnerParsesOnlyTheTemporaryPattern) {
  EXPECT_EQ(temporary_file_owner("summary.json.tmp.1234"), 1234);
  EXPECT_EQ(temporary_file_owner("photons-ab.bin.tmp.7"), 7);
  EXPECT_EQ(temporary_file_owner("summary.json"), 0);
  EXPECT_EQ(temporary_file_owner("a.tmp."), 0);
  EXPECT_EQ(temporary_file_owner("a.tmp.12x"), 0);
  EXPECT_EQ(temporary_file_owner(".tmp.12"), 0);
  EXPECT_EQ(temporary_file_owner("a.tmp.12345678901"), 0);  // not a pid
}

TEST(AtomicFile, RemovesTemporariesOfDeadProcessesOnly) {
  const fs::path dir = empty_dir("atomic_file_test_dead");
  fs::create_directories(dir / ".cache");
  const pid_t dead = dead_pid();
  const std::string own = std::to_string(::getpid());
  std::ofstream(dir / ("summary.json.tmp." + std::to_string(dead))) << "partial";
  std::ofstream(dir / ".cache" / ("photons-0.bin.tmp." + std::to_string(dead))) << "partial";
  std::ofstream(dir / ("daylight_factor.csv.tmp." + own)) << "being written";
  std::ofstream(dir / "summary.json") << "{}";
  EXPECT_EQ(remove_dead_temporaries(dir.string()), 2u);
  EXPECT_FALSE(fs::exists(dir / ("summary.json.tmp." + std::to_string(dead))));
  EXPECT_FALSE(fs::exists(dir / ".cache" / ("photons-0.bin.tmp." + std::to_string(dead))));
  EXPECT_TRUE(fs::exists(dir / ("daylight_factor.csv.tmp." + own)));
  EXPECT_TRUE(fs::exists(dir / "summary.json"));
  EXPECT_EQ(remove_dead_temporaries((dir / "absent").string()), 0u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace dayphoton
