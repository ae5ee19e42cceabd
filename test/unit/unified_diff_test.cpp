// --diff's unified diff (cli/unified_diff.h): hunk headers, context, joined hunks, insertions at
// the start and end, a missing final newline, and a large text with one edit (the prefix/suffix
// trim keeps it fast and the hunk small). Each expectation is what `diff -u` prints.
#include "cli/unified_diff.h"

#include <gtest/gtest.h>

namespace stereoshift {
namespace {

std::string numbered(int from, int to) {
  std::string t;
  for (int i = from; i <= to; ++i) t += "line " + std::to_string(i) + "\n";
  return t;
}

TEST(UnifiedDiff, EqualTextsGiveNothing) { EXPECT_EQ(unifiedDiff("a\nb\n", "a\nb\n", "a/x", "b/x"), ""); }

TEST(UnifiedDiff, OneChangeWithThreeLinesOfContext) {
  std::string before = numbered(1, 10), after = before;
  after.replace(after.find("line 5\n"), 7, "line five\n");
  EXPECT_EQ(unifiedDiff(before, after, "a/s.vert", "b/s.vert"),
            "--- a/s.vert\n+++ b/s.vert\n@@ -2,7 +2,7 @@\n line 2\n line 3\n line 4\n-line 5\n+line five\n"
            " line 6\n line 7\n line 8\n");
}

TEST(UnifiedDiff, AppendedBlockAndRenameInOneHunkWhenClose) {
  std::string before = "void main()\n{\n    x();\n}\n";
  std::string after = "void main_mono()\n{\n    x();\n}\n// added\nvoid main() {}\n";
  EXPECT_EQ(unifiedDiff(before, after, "a/v", "b/v"),
            "--- a/v\n+++ b/v\n@@ -1,4 +1,6 @@\n-void main()\n+void main_mono()\n {\n     x();\n }\n+// added\n"
            "+void main() {}\n");
}

TEST(UnifiedDiff, DistantChangesAreSeparateHunks) {
  std::string before = numbered(1, 20), after = before;
  after.replace(after.find("line 2\n"), 7, "line two\n");
  after.replace(after.find("line 18\n"), 8, "line eighteen\n");
  std::string d = unifiedDiff(before, after, "a", "b");
  EXPECT_NE(d.find("@@ -1,5 +1,5 @@\n line 1\n-line 2\n+line two\n"), std::string::npos) << d;
  EXPECT_NE(d.find("@@ -15,6 +15,6 @@\n line 15\n line 16\n line 17\n-line 18\n+line eighteen\n"), std::string::npos)
      << d;
}

TEST(UnifiedDiff, InsertionIntoAnEmptyTextAndAMissingFinalNewline) {
  EXPECT_EQ(unifiedDiff("", "new\n", "a", "b"), "--- a\n+++ b\n@@ -0,0 +1 @@\n+new\n");
  EXPECT_EQ(unifiedDiff("x\nend", "x\nend\n", "a", "b"),
            "--- a\n+++ b\n@@ -1,2 +1,2 @@\n x\n-end\n\\ No newline at end of file\n+end\n");
}

TEST(UnifiedDiff, LargeTextWithOneEditStaysOneSmallHunk) {
  std::string before = numbered(1, 200000), after = before;
  after.replace(after.find("line 100000\n"), 12, "line 100000\nline inserted\n");
  std::string d = unifiedDiff(before, after, "a", "b");
  EXPECT_EQ(d, "--- a\n+++ b\n@@ -99998,6 +99998,7 @@\n line 99998\n line 99999\n line 100000\n+line inserted\n"
               " line 100001\n line 100002\n line 100003\n");
}

}  // namespace
}  // namespace stereoshift
