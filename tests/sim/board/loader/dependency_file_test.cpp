// The compiler's -MD output read back: prerequisites only, continuations joined, GCC's escapes
// undone, each file once.
#include "board/loader/dependency_file.hpp"

#include <gtest/gtest.h>

namespace stepdance::sim {
namespace {

TEST(DependencyFileTest, PrerequisitesOfEveryRuleInOrderEachOnce) {
  const std::string text =
      "/c/x.tmp-1.0.o: /c/x.tmp-1.ino.cpp /s/core.hpp \\\n"
      " /home/me/Sketch/../shared/val.h \\\n"
      "  /home/me/Sketch/table.inc\n"
      "/c/x.tmp-1.1.o: /home/me/Sketch/extra.cpp /s/core.hpp\n";
  const std::vector<std::string> expected{"/c/x.tmp-1.ino.cpp", "/s/core.hpp", "/home/me/Sketch/../shared/val.h",
                                          "/home/me/Sketch/table.inc", "/home/me/Sketch/extra.cpp"};
  EXPECT_EQ(parse_dependency_text(text), expected);
}

TEST(DependencyFileTest, EscapedSpacesHashesAndDollarsAreUndone) {
  const std::string text = "out.o: /my\\ sketches/a\\#1.h /cost$$/b.h\n";
  const std::vector<std::string> expected{"/my sketches/a#1.h", "/cost$/b.h"};
  EXPECT_EQ(parse_dependency_text(text), expected);
}

TEST(DependencyFileTest, NothingBeforeAColonIsAFile) {
  EXPECT_TRUE(parse_dependency_text("").empty());
  EXPECT_TRUE(parse_dependency_text("lonely.o:\n").empty());
  const std::vector<std::string> expected{"b.h"};
  EXPECT_EQ(parse_dependency_text("a.o a.d: b.h"), expected);  // no final newline
}

}  // namespace
}  // namespace stepdance::sim
