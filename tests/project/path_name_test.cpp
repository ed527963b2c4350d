// The path-name rule (project/src/path_name.cpp): what each kind of bad name is told, the
// case fold, and names shown safely in messages. The loader's use of the rule is tested on
// the files of tests/data/bad/ (bad_inputs_test.cpp).
#include "dayphoton/project/path_name.h"

#include <gtest/gtest.h>

#include <string>

namespace dayphoton::project {
namespace {

TEST(PathName, EachProblemIsNamed) {
  EXPECT_EQ(path_name_problem("workplane"), "");
  EXPECT_EQ(path_name_problem(""), "it is empty");
  EXPECT_EQ(path_name_problem("../x"), "'/' is not allowed");
  EXPECT_EQ(path_name_problem("a\\b"), "'\\x5C' is not allowed");
  EXPECT_EQ(path_name_problem(std::string("a\0b", 3)), "'\\x00' is not allowed");
  EXPECT_EQ(path_name_problem("a\nb"), "'\\x0A' is not allowed");
  EXPECT_EQ(path_name_problem("caf\xC3\xA9"), "'\\xC3' is not allowed");
  EXPECT_EQ(path_name_problem(".."), "it starts with '.'");
  EXPECT_EQ(path_name_problem("-rf"), "it starts with '-'");
  EXPECT_EQ(path_name_problem("x."), "it ends with '.'");
  EXPECT_EQ(path_name_problem("Lpt3.csv"), "'Lpt3' is a device name");
  EXPECT_EQ(path_name_problem(std::string(MaxPathNameLength, 'x')), "");
  EXPECT_EQ(path_name_problem(std::string(300, 'x')), "it has 300 characters (at most 64)");
}

TEST(PathName, CaseFoldMatchesWhatCaseInsensitiveFileSystemsCompare) {
  EXPECT_EQ(path_name_fold("Office_2.b"), path_name_fold("office_2.B"));
  EXPECT_NE(path_name_fold("office1"), path_name_fold("office2"));
}

TEST(PathName, PrintableNameEscapesEveryByteATerminalWouldInterpret) {
  EXPECT_EQ(printable_name("desk 1"), "desk 1");
  EXPECT_EQ(printable_name("\x1B[31mred"), "\\x1B[31mred");
  EXPECT_EQ(printable_name(std::string("a\0b\n\x7F", 5)), "a\\x00b\\x0A\\x7F");
  EXPECT_EQ(printable_name("\xC2\x9B"), "\\xC2\\x9B");  // U+009B, the 8-bit CSI
}

}  // namespace
}  // namespace dayphoton::project
