// Sketch folders as the IDE sees them, the assembled translation unit, and building one for real.
#include "board/loader/sketch_sources.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "board/host/sim_board.hpp"
#include "board/loader/board_library.hpp"
#include "board/loader/sketch_builder.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim {
namespace {

namespace fs = std::filesystem;

const std::string kFixture = STEPDANCE_SOURCE_DIR "/tests/sim/assembly/fixtures/IdeSketch";
const std::string kCache = STEPDANCE_BUILD_DIR "/sketch-cache";

std::string file_name(const std::string& path) { return fs::path(path).filename().string(); }

std::vector<std::string> names(const std::vector<std::string>& paths) {
  std::vector<std::string> out;
  for (const std::string& path : paths) out.push_back(file_name(path));
  return out;
}

// A scratch folder under the build tree, emptied first.
fs::path scratch_folder(const std::string& name) {
  const fs::path folder = fs::path(STEPDANCE_BUILD_DIR) / "sketch-sources-test" / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

TEST(SketchSources, AnIdeFolderHasTheMainInoFirstThenTheOthersAlphabetically) {
  const fs::path folder = scratch_folder("Plotter");
  for (const char* name : {"zeta.ino", "Plotter.ino", "alpha.ino", "pins.h", "usb.c", "motion.cpp", "notes.txt"}) {
    write(folder / name, "\n");
  }
  write(folder / "src" / "deep" / "filter.cpp", "\n");
  SketchSources sources;
  std::string error;
  ASSERT_TRUE(find_sketch_sources(folder.string(), sources, error)) << error;  // the folder names the sketch
  EXPECT_EQ(names(sources.inos), (std::vector<std::string>{"Plotter.ino", "alpha.ino", "zeta.ino"}));
  EXPECT_EQ(names(sources.cpp_files), (std::vector<std::string>{"motion.cpp", "filter.cpp"}));
  EXPECT_EQ(names(sources.c_files), std::vector<std::string>{"usb.c"});
  EXPECT_EQ(names(sources.headers), std::vector<std::string>{"pins.h"});
}

TEST(SketchSources, AnInoNotNamedAfterItsFolderStandsAlone) {
  const fs::path folder = scratch_folder("loose");
  write(folder / "one.ino", "\n");
  write(folder / "two.ino", "\n");
  write(folder / "other.cpp", "\n");
  SketchSources sources;
  std::string error;
  ASSERT_TRUE(find_sketch_sources((folder / "one.ino").string(), sources, error)) << error;
  EXPECT_EQ(names(sources.inos), std::vector<std::string>{"one.ino"});
  EXPECT_TRUE(sources.cpp_files.empty());
  EXPECT_FALSE(find_sketch_sources((folder / "missing.ino").string(), sources, error));
  EXPECT_NE(error.find("missing.ino: sketch not found"), std::string::npos) << error;
}

TEST(SketchAssembly, PrototypesGoBeforeTheFirstDefinitionUnderTheirConditionsWithLineDirectives) {
  const std::string main_ino =
      "#include \"pins.h\"\n"                      // 1
      "int counter = 0;\n"                         // 2
      "void setup() { later(); }\n"                // 3
      "#ifdef FAST\n"                              // 4
      "void later(int n = 2) { counter += n; }\n"  // 5
      "#endif\n";                                  // 6
  const std::string second = "void loop() {}";     // no final newline
  const std::string text = assemble_sketch({{"/s/Main.ino", main_ino}, {"/s/b \"q\".ino", second}});
  const std::string expected =
      "#include <Arduino.h>\n"
      "#line 1 \"/s/Main.ino\"\n"
      "#include \"pins.h\"\n"
      "int counter = 0;\n"
      "#line 3 \"/s/Main.ino\"\n"
      "void setup();\n"
      "#ifdef FAST\n"
      "#line 5 \"/s/Main.ino\"\n"
      "void later(int n = 2);\n"
      "#endif\n"
      "#line 1 \"/s/b \\\"q\\\".ino\"\n"
      "void loop();\n"
      "#line 3 \"/s/Main.ino\"\n"
      "void setup() { later(); }\n"
      "#ifdef FAST\n"
      "void later(int n    ) { counter += n; }\n"  // the default blanked, columns kept
      "#endif\n"
      "#line 1 \"/s/b \\\"q\\\".ino\"\n"
      "void loop() {}\n";
  EXPECT_EQ(text, expected);
}

TEST(SketchAssembly, ADefinitionAfterACommentOnItsLineGetsThePrototypesRightBeforeIt) {
  const std::string text = assemble_sketch({{"a.ino", "/* first\n   ends */ void f() { g(); }\nvoid g() {}\n"}});
  const std::string expected =
      "#include <Arduino.h>\n"
      "#line 1 \"a.ino\"\n"
      "/* first\n   ends */ \n"
      "#line 2 \"a.ino\"\n"
      "void f();\n"
      "#line 3 \"a.ino\"\n"
      "void g();\n"
      "#line 2 \"a.ino\"\n"
      "           void f() { g(); }\n"  // padded back to column 11
      "void g() {}\n";
  EXPECT_EQ(text, expected);
}

TEST(SketchAssembly, ASketchWithoutFunctionsIsOnlyConcatenated) {
  EXPECT_EQ(assemble_sketch({{"a.ino", "int x;\n"}, {"b.ino", "int y;\n"}}),
            "#include <Arduino.h>\n#line 1 \"a.ino\"\nint x;\n#line 1 \"b.ino\"\nint y;\n");
}

TEST(SketchBuilderIde, AFolderWithSeveralInosACppAndANameCBuildsAndRuns) {
  const SketchBuild build = SketchBuilder(kCache).build(kFixture);
  ASSERT_TRUE(build.ok) << build.error;
  std::string error;
  auto library = BoardLibrary::load(build.library_path, error);
  ASSERT_NE(library, nullptr) << error;
  Scheduler scheduler;
  BoardOptions options;
  options.name = "ide";
  SimBoard board(scheduler, options, std::move(library));
  ASSERT_TRUE(board.attach(error)) << error;
  std::vector<std::string> lines;
  board.console().on_line([&lines](const std::string& line) { lines.push_back(line); });
  board.power_on(0);
  scheduler.run_until(50 * kMillisecond);
  // label() = 40 + 9 letters of "StepDance", reported twice (default argument 2), then 2 × 21 once.
  EXPECT_EQ(lines, (std::vector<std::string>{"49", "49", "42"}));
}

TEST(SketchBuilderIde, ACompileErrorNamesTheInoAndLineItIsOn) {
  const fs::path folder = scratch_folder("Broken");
  write(folder / "Broken.ino", "void setup() { helper(); }\nvoid loop() {}\n");
  write(folder / "more.ino", "// helper\n\nvoid helper() { not_declared_anywhere(); }\n");
  const SketchBuild build = SketchBuilder(kCache).build(folder.string());
  EXPECT_FALSE(build.ok);
  EXPECT_NE(build.error.find("more.ino:3:17: error"), std::string::npos) << build.error;
  EXPECT_EQ(build.error.find(".ino.cpp:"), std::string::npos) << build.error;  // never the generated file
}

TEST(SketchBuilderIde, AnErrorInANameCIsReportedAndNothingIsCached) {
  const fs::path folder = scratch_folder("BadC");
  write(folder / "BadC.ino", "void setup() {}\nvoid loop() {}\n");
  write(folder / "name.c", "int broken(void) { return missing_value; }\n");
  const SketchBuild build = SketchBuilder(kCache).build(folder.string());
  EXPECT_FALSE(build.ok);
  EXPECT_NE(build.error.find("name.c:1:"), std::string::npos) << build.error;
}

}  // namespace
}  // namespace stepdance::sim
