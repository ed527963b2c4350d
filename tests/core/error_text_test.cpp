// error_text (core/error_text.h): the system's text of an error number, the same as
// std::strerror's in one thread, from parallel threads each its own; and the messages of
// sha256_file_hex, which the manifest calls from parallel threads, carry it.
#include "dayphoton/core/error_text.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "dayphoton/core/sha256.h"

namespace dayphoton {
namespace {

TEST(ErrorText, TheSystemsTextOfAnErrorNumber) {
  for (int code : {ENOENT, EACCES, ENOSPC, EISDIR, EINVAL}) EXPECT_EQ(error_text(code), std::strerror(code)) << code;
  // A number the system has no name for still gets a text that names it.
  const std::string unknown = error_text(123456);
  EXPECT_NE(unknown.find("123456"), std::string::npos) << unknown;
}

TEST(ErrorText, ParallelThreadsGetTheirOwnTexts) {
  const std::vector<int> codes = {ENOENT, EACCES, ENOSPC, EISDIR, 123456, 654321};
  std::vector<std::string> expected;
  for (int code : codes) expected.push_back(error_text(code));
  std::vector<int> wrong(codes.size(), 0);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < codes.size(); ++t)
    threads.emplace_back([&, t] {
      for (int i = 0; i < 2000; ++i) wrong[t] += error_text(codes[t]) != expected[t];
    });
  for (std::thread& t : threads) t.join();
  for (std::size_t t = 0; t < codes.size(); ++t) EXPECT_EQ(wrong[t], 0) << codes[t];
}

TEST(ErrorText, AFileTheManifestCannotReadSaysWhy) {
  const std::string path = (std::filesystem::path(::testing::TempDir()) / "error_text_test_missing.bin").string();
  std::filesystem::remove(path);
  try {
    sha256_file_hex(path);
    ADD_FAILURE() << "no error for a missing file";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot read " + path + ": " + error_text(ENOENT));
  }
}

}  // namespace
}  // namespace dayphoton
