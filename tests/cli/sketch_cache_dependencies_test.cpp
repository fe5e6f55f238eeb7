// The sketch cache follows every file the compiler read (issue 27): a header included from
// outside the sketch folder ("../shared/val.h") and a file included by another extension
// ("table.inc") were not in the cache key, so after editing them the old library ran. The
// fixture prints a value from each; the test edits both in a copy and expects the new values.
#include <algorithm>
#include <filesystem>
#include <fstream>

#include "board/loader/sketch_builder.hpp"
#include "cli_runner.hpp"

namespace stepdance::sim::test {
namespace {

namespace fs = std::filesystem;

struct Copy {
  std::string folder;  ///< the fixture's copy
  std::string cache;   ///< a sketch cache of its own, empty at first
};

Copy copy_fixture(const std::string& name) {
  const std::string scratch = test_output_dir("sketch_cache_" + name);
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  fs::copy(source_path("tests/sim/assembly/fixtures/OutputSafety"), scratch + "/copy", fs::copy_options::recursive);
  return {scratch + "/copy", scratch + "/cache"};
}

/// The run's console: "shared value N" and "table value M" lines.
std::string run_console(const Copy& copy) {
  const CommandResult result = stepdance("sim --cache " + copy.cache + " --out " + copy.folder + "/out " + copy.folder,
                                         fs::path(copy.folder).parent_path().string());
  EXPECT_EQ(result.exit_code, 0) << result.err;
  return result.out;
}

void rewrite(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::trunc) << text; }

TEST(SketchCacheDependenciesTest, EditingAHeaderOutsideTheSketchFolderRebuildsTheSketch) {
  const Copy copy = copy_fixture("outside_header");
  EXPECT_NE(run_console(copy).find("[driver] shared value 1\n"), std::string::npos);
  rewrite(copy.folder + "/shared/val.h", "#define SHARED_VALUE 2\n");
  EXPECT_NE(run_console(copy).find("[driver] shared value 2\n"), std::string::npos);
}

TEST(SketchCacheDependenciesTest, EditingAFileIncludedByAnotherExtensionRebuildsTheSketch) {
  const Copy copy = copy_fixture("table_inc");
  EXPECT_NE(run_console(copy).find("[driver] table value 10\n"), std::string::npos);
  rewrite(copy.folder + "/Sketch/table.inc", "20\n");
  EXPECT_NE(run_console(copy).find("[driver] table value 20\n"), std::string::npos);
  rewrite(copy.folder + "/Sketch/table.inc", "10\n");  // back to a version the cache holds
  EXPECT_NE(run_console(copy).find("[driver] table value 10\n"), std::string::npos);
}

TEST(SketchCacheDependenciesTest, TheBuildListsEveryFileTheCompilerRead) {
  const Copy copy = copy_fixture("inputs");
  const SketchBuild fresh = SketchBuilder(copy.cache).build(copy.folder + "/Sketch");
  ASSERT_TRUE(fresh.ok) << fresh.error;
  EXPECT_FALSE(fresh.from_cache);
  const SketchBuild cached = SketchBuilder(copy.cache).build(copy.folder + "/Sketch");
  ASSERT_TRUE(cached.ok) << cached.error;
  EXPECT_TRUE(cached.from_cache);
  EXPECT_EQ(cached.inputs, fresh.inputs);
  const auto has = [&fresh](const std::string& path) {
    return std::find(fresh.inputs.begin(), fresh.inputs.end(), path) != fresh.inputs.end();
  };
  EXPECT_TRUE(has(copy.folder + "/Sketch/Sketch.ino"));
  EXPECT_TRUE(has(copy.folder + "/shared/val.h"));
  EXPECT_TRUE(has(copy.folder + "/Sketch/table.inc"));
  EXPECT_TRUE(has(source_path("src/stepdance.hpp")));
  EXPECT_TRUE(std::is_sorted(fresh.inputs.begin(), fresh.inputs.end()));
}

// An output may not replace any file the compiler read, which only the build can tell.
TEST(SketchCacheDependenciesTest, AnOutputOverAnIncludedFileIsRefusedBeforeTheBoardLoads) {
  const Copy copy = copy_fixture("csv_over_header");
  const std::string header = copy.folder + "/shared/val.h";
  const std::string before = read_file(header);
  const CommandResult result = stepdance("sim --quiet --cache " + copy.cache + " --csv " + header + " " + copy.folder,
                                         fs::path(copy.folder).parent_path().string());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, "--csv: would overwrite a file the sketch of board 'driver' includes " + header +
                            " (an output never replaces an input)\n");
  EXPECT_EQ(read_file(header), before);
  EXPECT_FALSE(fs::exists(copy.folder + "/out/summary.json"));  // the folder is made, nothing ran
}

}  // namespace
}  // namespace stepdance::sim::test
