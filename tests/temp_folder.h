// Test support: a temporary folder of this test process's own. CTest runs every GoogleTest case
// as a process of its own, several at once (-j), and two checkouts may run the same tests on one
// machine: a fixed folder name (below /tmp, or below the build tree's TMPDIR, tests/CMakeLists.txt)
// would let two of them read and remove each other's files. Below it, a test names its folders
// as it likes.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace dayphoton::test {

/// This process's own folder, "dayphoton_test_<pid>" below the temporary folder
/// (std::filesystem::temp_directory_path: TMPDIR, which CTest sets to the build tree's
/// test-tmp/), made empty on first use. It is removed with everything in it when the process
/// ends, unless a test failed (its files are then kept for a look). A test that forks must end
/// its child with _exit, not exit: the child's exit would remove the folder.
inline const std::filesystem::path& process_temp_dir() {
  struct Folder {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("dayphoton_test_" + std::to_string(::getpid()));
    Folder() {
      std::filesystem::remove_all(path);  // of an earlier process with the same id
      std::filesystem::create_directories(path);
    }
    ~Folder() {
      const ::testing::UnitTest* tests = ::testing::UnitTest::GetInstance();
      if (tests->Failed()) return;
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Folder folder;
  return folder.path;
}

/// `name` below this process's own folder, removed first (nothing of an earlier test is read);
/// not made again: the code under test makes it.
inline std::filesystem::path fresh_dir(const std::string& name) {
  const std::filesystem::path dir = process_temp_dir() / name;
  std::filesystem::remove_all(dir);
  return dir;
}

/// `name` below this process's own folder, made empty (fresh_dir, then created).
inline std::filesystem::path empty_dir(const std::string& name) {
  const std::filesystem::path dir = fresh_dir(name);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace dayphoton::test
