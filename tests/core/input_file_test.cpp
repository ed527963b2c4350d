// Input files must be regular files: a FIFO, a device or a folder is refused by its type,
// without opening it (opening a FIFO blocks until a writer appears).
#include "dayphoton/core/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "dayphoton/core/diagnostics.h"

using namespace dayphoton;

namespace {

std::string open_error(const std::string& path, const SourceLocation& from = {}) {
  try {
    open_input_file(path, "weather file", from);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(InputFile, RegularFileIsAccepted) {
  const std::string path = testing::TempDir() + "input_file_test.txt";
  std::ofstream(path) << "hello";
  EXPECT_EQ(input_file_problem(path), "");
  std::uint64_t size = 0;
  ASSERT_TRUE(input_file_size(path, size));
  EXPECT_EQ(size, 5u);
  std::ifstream in = open_input_file(path, "weather file");
  std::string text;
  in >> text;
  EXPECT_EQ(text, "hello");
}

TEST(InputFile, FifoIsRefusedWithoutBlocking) {
  const std::string path = testing::TempDir() + "input_file_test.fifo";
  ::unlink(path.c_str());
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  // Opening it for reading would block this test forever: the check must not open it.
  EXPECT_EQ(input_file_problem(path), "is a named pipe (FIFO), not a regular file");
  EXPECT_EQ(open_error(path), path + ": error: weather file is a named pipe (FIFO), not a regular file\n");
  std::uint64_t size = 0;
  EXPECT_FALSE(input_file_size(path, size));
  ::unlink(path.c_str());
}

TEST(InputFile, DevicesFoldersAndMissingFilesAreRefused) {
  EXPECT_EQ(input_file_problem("/dev/zero"), "is a character device, not a regular file");
  EXPECT_EQ(input_file_problem(testing::TempDir()), "is a folder, not a file");
  EXPECT_EQ(input_file_problem(testing::TempDir() + "no_such_file.epw"), "not found");
  EXPECT_EQ(input_file_problem(""), "is an empty file name");
  // Named in a project file: located at the entry that names it.
  EXPECT_EQ(open_error("/dev/zero", {"p.yaml", 3, 12}),
            "p.yaml:3:12: error: weather file '/dev/zero' is a character device, not a regular file\n");
}
