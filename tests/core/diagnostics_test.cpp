// Tests for core/diagnostics.h: Levenshtein distance against hand-counted cases, the
// "did you mean" threshold, the compiler-style format with its caret, the error cap, and
// InputError carrying the located list.
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/terminal_text.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

namespace dayphoton {
namespace {

TEST(Diagnostics, EditDistanceKnownCases) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("abc", ""), 3u);
  EXPECT_EQ(edit_distance("", "abcd"), 4u);
  EXPECT_EQ(edit_distance("sill", "sill"), 0u);
  EXPECT_EQ(edit_distance("sil", "sill"), 1u);        // insertion
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);  // 2 substitutions + 1 insertion
  EXPECT_EQ(edit_distance("flaw", "lawn"), 2u);
  EXPECT_EQ(edit_distance("lawn", "flaw"), 2u);  // symmetric
}

TEST(Diagnostics, ClosestMatchOnlyForPlausibleTypos) {
  const std::vector<std::string> keys{"sill", "width", "height", "offset", "material"};
  EXPECT_EQ(closest_match("sil", keys), "sill");
  EXPECT_EQ(closest_match("heigth", keys), "height");  // 2 edits in 6 letters
  EXPECT_EQ(closest_match("materail", keys), "material");
  EXPECT_EQ(closest_match("colour", keys), "");  // nothing close
  EXPECT_EQ(closest_match("x", {}), "");
}

TEST(Diagnostics, FormatPrintsLocationLineAndCaret) {
  Diagnostic d;
  d.location.file = "project.yaml";
  d.location.line = 12;
  d.location.column = 7;
  d.message = "unknown key 'sil' in window";
  d.source_line = "      sil: 0.9";
  EXPECT_EQ(d.format(),
            "project.yaml:12:7: error: unknown key 'sil' in window\n"
            "          sil: 0.9\n"
            "          ^\n");
  // Tabs are kept so the caret lines up.
  Diagnostic t{Severity::Warning, {"a.obj", 3, 3}, "odd", "\tf 1 2"};
  EXPECT_EQ(t.format(), "a.obj:3:3: warning: odd\n    \tf 1 2\n    \t ^\n");
  // Without a column there is no caret; without a line, just the file.
  Diagnostic n{Severity::Error, {"w.epw", 9, 0}, "bad field", "1,2,3"};
  EXPECT_EQ(n.format(), "w.epw:9: error: bad field\n    1,2,3\n");
  Diagnostic f{Severity::Error, {"w.epw", 0, 0}, "cannot open", ""};
  EXPECT_EQ(f.format(), "w.epw: error: cannot open\n");
}

TEST(Diagnostics, InputTextCannotDriveTheTerminal) {
  // An escape sequence in a file name and in the echoed line, a bell and a C1 CSI in the
  // message: printed as escapes, the caret still under the offending column.
  Diagnostic d;
  d.location = {"\x1b]0;pwned\x07.pts", 2, 8};
  d.message = "expected a number, found '\x1b[2J\xc2\x9b'";
  d.source_line = "1 2 \x1b[31m x";
  EXPECT_EQ(d.format(),
            "\\e]0;pwned\\x07.pts:2:8: error: expected a number, found '\\e[2J\\xc2\\x9b'\n"
            "    1 2 \\e[31m x\n"
            "            ^\n");
  // Valid UTF-8 is kept; a stray byte is escaped.
  EXPECT_EQ(printable_text("Zürich \xff"), "Zürich \\xff");
  EXPECT_EQ(printable_text("tab\tkept\nnewline"), "tab\tkept\\nnewline");
  // A very long line is cut; the caret is left out when its column is cut off.
  Diagnostic longline;
  longline.location = {"a.pts", 1, 300};
  longline.message = "bad";
  longline.source_line = std::string(1000, 'x');
  EXPECT_EQ(longline.format(), "a.pts:1:300: error: bad\n    " + std::string(200, 'x') + "...\n");
}

TEST(Diagnostics, CollectsUpToCapAndThrowsInputError) {
  Diagnostics diag(2);
  EXPECT_FALSE(diag.has_errors());
  EXPECT_NO_THROW(diag.throw_if_errors());
  diag.warning({"f", 1, 1}, "just a warning");
  EXPECT_FALSE(diag.has_errors());
  diag.error({"f", 1, 2}, "first");
  diag.error({"f", 2, 1}, "second");
  EXPECT_TRUE(diag.at_cap());
  diag.error({"f", 3, 1}, "third");
  EXPECT_EQ(diag.error_count(), 3u);
  EXPECT_EQ(diag.entries().size(), 3u);  // warning + 2 kept errors
  const std::string text = diag.format();
  EXPECT_NE(text.find("f:1:2: error: first"), std::string::npos);
  EXPECT_EQ(text.find("third"), std::string::npos);
  EXPECT_NE(text.find("1 more error(s) not shown"), std::string::npos);
  EXPECT_NE(text.find("3 errors generated."), std::string::npos);
  try {
    diag.throw_if_errors();
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.diagnostics().size(), 3u);
    EXPECT_EQ(std::string(e.what()), text);
  }
}

TEST(Diagnostics, SingleLocatedInputError) {
  InputError e({"p.yaml", 4, 5}, "bad value", "  x: y");
  ASSERT_EQ(e.diagnostics().size(), 1u);
  EXPECT_EQ(e.diagnostics()[0].location.line, 4);
  EXPECT_EQ(std::string(e.what()), "p.yaml:4:5: error: bad value\n      x: y\n        ^\n");
}

TEST(Diagnostics, ReadSourceLine) {
  const std::string path = ::testing::TempDir() + "diagnostics_test_lines.txt";
  {
    std::ofstream out(path);
    out << "first\r\nsecond\nthird";
  }
  EXPECT_EQ(read_source_line(path, 1), "first");
  EXPECT_EQ(read_source_line(path, 2), "second");
  EXPECT_EQ(read_source_line(path, 3), "third");
  EXPECT_EQ(read_source_line(path, 4), "");
  EXPECT_EQ(read_source_line(path + ".missing", 1), "");
  std::remove(path.c_str());
}

}  // namespace
}  // namespace dayphoton
