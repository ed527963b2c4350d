// The bad project files of tests/data/bad/ (what each is: tests/data/bad/README.md): every
// one must fail to load with exactly the located errors its "# expect: line:col: message"
// comments give, in order. tests/cli/run_cli_tests.sh also runs `dayphoton check` on each.
// Also the YAML loader's cost on a large file (one map of many keys).
#include <gtest/gtest.h>

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "dayphoton/project/project.h"
#include "located_errors.h"

namespace dayphoton::project {
namespace {

namespace fs = std::filesystem;

const std::string BadDir = std::string(DAYPHOTON_SOURCE_DIR) + "/tests/data/bad";

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The "# expect: " comment lines at the top of a file, without the prefix.
std::vector<std::string> expected_errors(const std::string& text) {
  const std::string prefix = "# expect: ";
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line) && !line.empty() && line[0] == '#')
    if (line.compare(0, prefix.size(), prefix) == 0) out.push_back(line.substr(prefix.size()));
  return out;
}

TEST(BadInputs, EachFileFailsWithItsLocatedMessages) {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(BadDir))
    if (entry.path().extension() == ".yaml") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 20u);
  const std::string readme = read_file(BadDir + "/README.md");
  for (const std::string& path : files) {
    const std::string name = fs::path(path).filename().string();
    SCOPED_TRACE(name);
    EXPECT_NE(readme.find("`" + name + "`"), std::string::npos) << "not described in README.md";
    const std::vector<std::string> expected = expected_errors(read_file(path));
    ASSERT_FALSE(expected.empty()) << "no '# expect: line:col: message' line";
    EXPECT_EQ(test::located_errors([&] { load_project(path); }, path), expected);
  }
}

TEST(BadInputs, FilesOverTwoMebibytesAreRefusedBeforeParsing) {
  // yaml-cpp's node graph costs ~350 bytes a node: 4 MiB of "1,1,1,..." took 1.1 GB.
  std::string text = "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\nextra: [1";
  while (text.size() < (2u << 20)) text += ",1";
  text += "]\n";
  const std::vector<std::string> expected = {
      "1:1: the file is larger than 2097152 bytes (2 MiB), the limit of a project file: put large "
      "geometry in OBJ files and sensors in .pts files"};
  EXPECT_EQ(test::located_errors([&] { load_project_from_string(text, "big.yaml"); }), expected);
  // The same from a file, of which load_project reads no more than the limit and one byte.
  const std::string path = (fs::temp_directory_path() / "dayphoton_big_project.yaml").string();
  std::ofstream(path, std::ios::binary) << text << std::string(1u << 20, '#');
  EXPECT_EQ(test::located_errors([&] { load_project(path); }), expected);
  fs::remove(path);
}

/// CPU time of the calling thread (POSIX clock_gettime, CLOCK_THREAD_CPUTIME_ID).
double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

TEST(BadInputs, ManyKeysInOneMapLoadInLinearTime) {
  // A map of n keys used to cost O(n^2) key comparisons (each key searched among those before
  // it): 100 000 keys took 46 s in a release build. Hashed, they take well under a second
  // (about 4 s under AddressSanitizer). The bound is on this thread's CPU time, not the wall
  // clock, so that a loaded machine does not fail it, and leaves room for a slow one while the
  // quadratic search would need far more.
  std::string text =
      "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"
      "outputs: {annual_illuminance: false, metrics: false}\n"
      "materials: {}\n"
      "geometry: {}\n";
  const int keys = 100000;
  for (int i = 0; i < keys; ++i) text += "k" + std::to_string(i) + ": 1\n";
  text += "k7: 2\n";  // one duplicate, found at the end
  const double start_s = thread_cpu_seconds();
  const std::vector<std::string> errors =
      test::located_errors([&] { load_project_from_string(text, "many_keys.yaml"); });
  EXPECT_LT(thread_cpu_seconds() - start_s, 20.0);
  // The duplicate is found while the tree is built, before the unknown keys are reported
  // (up to the cap of 50 kept diagnostics).
  ASSERT_GE(errors.size(), 2u);
  EXPECT_EQ(errors[0], "100005:1: duplicate key 'k7' (first given at line 12)");
  EXPECT_EQ(errors[1], "5:1: unknown key 'k0' in project");
}

}  // namespace
}  // namespace dayphoton::project
