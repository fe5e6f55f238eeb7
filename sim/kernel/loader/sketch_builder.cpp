// Sketch compilation: cache lookup, the compiler command line, and atomic publication of the .so.
#include "loader/sketch_builder.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "abi/board_abi.h"
#include "loader/content_hash.hpp"
#include "loader/process.hpp"
#include "loader/toolchain_config.hpp"

namespace stepdance::sim {
namespace {

namespace fs = std::filesystem;

std::string env_or_empty(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr ? value : "";
}

bool is_sketch_source(const fs::path& path) {
  const std::string ext = path.extension().string();
  return ext == ".h" || ext == ".hpp" || ext == ".ino" || ext == ".cpp";
}

// Every header under an include directory, sorted: a changed core header changes the cache key
// even when the runtime library's bytes happen not to change.
std::vector<std::string> headers_under(const std::string& directory) {
  std::vector<std::string> paths;
  std::error_code error;
  for (const auto& entry : fs::recursive_directory_iterator(directory, error)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file(error) && (ext == ".h" || ext == ".hpp")) paths.push_back(entry.path().string());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

// The other sources next to the sketch, sorted so the hash does not depend on directory order.
std::vector<std::string> neighbour_sources(const fs::path& sketch) {
  std::vector<std::string> paths;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(sketch.parent_path(), error)) {
    if (entry.is_regular_file(error) && is_sketch_source(entry.path()) && entry.path() != sketch) {
      paths.push_back(entry.path().string());
    }
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

// Distinct per process and per call, so concurrent builders never share a temporary file.
std::string unique_suffix() {
  static unsigned counter = 0;
  return std::to_string(::getpid()) + "-" + std::to_string(++counter);
}

}  // namespace

SketchBuilder::SketchBuilder(std::string cache_dir)
    : cache_dir_(cache_dir.empty() ? default_cache_dir() : std::move(cache_dir)) {}

std::string SketchBuilder::default_cache_dir() {
  const std::string explicit_dir = env_or_empty("STEPDANCE_SKETCH_CACHE");
  if (!explicit_dir.empty()) return explicit_dir;
  const std::string xdg = env_or_empty("XDG_CACHE_HOME");
  if (!xdg.empty()) return xdg + "/stepdance/sketches";
  const std::string home = env_or_empty("HOME");
  if (!home.empty()) return home + "/.cache/stepdance/sketches";
  return toolchain::kFallbackCacheDir;
}

std::string SketchBuilder::cache_key(const std::string& sketch_path) const {
  ContentHash hash;
  hash.add(std::to_string(STEPDANCE_BOARD_ABI_VERSION));
  hash.add(toolchain::kCompiler);
  for (const char* flag : toolchain::kFlags) hash.add(flag);
  for (const char* dir : toolchain::kIncludeDirs) {
    hash.add(dir);
    for (const std::string& header : headers_under(dir)) hash.add_file(header);
  }
  hash.add(toolchain::kForcedInclude);
  hash.add_file(toolchain::kRuntimeLibrary);
  hash.add_file(toolchain::kExportMap);
  hash.add(sketch_path);
  hash.add_file(sketch_path);
  for (const std::string& source : neighbour_sources(sketch_path)) {
    hash.add(source);
    hash.add_file(source);
  }
  return hash.hex();
}

std::vector<std::string> SketchBuilder::compile_command(const std::string& sketch_path,
                                                        const std::string& output) const {
  std::vector<std::string> command{toolchain::kCompiler};
  for (const char* flag : toolchain::kFlags) command.emplace_back(flag);
  for (const char* dir : toolchain::kIncludeDirs) command.push_back(std::string("-I") + dir);
  if (toolchain::kForcedInclude[0] != '\0') {
    command.emplace_back("-include");
    command.emplace_back(toolchain::kForcedInclude);
  }
  command.insert(command.end(), {"-x", "c++", sketch_path, "-x", "none", toolchain::kRuntimeLibrary});
  command.push_back(std::string("-Wl,--version-script=") + toolchain::kExportMap);
  command.insert(command.end(), {"-Wl,-u,stepdance_board_attach", "-shared", "-o", output});
  return command;
}

SketchBuild SketchBuilder::build(const std::string& sketch) const {
  SketchBuild result;
  std::error_code error;
  const fs::path sketch_path = fs::absolute(sketch, error);
  if (!fs::is_regular_file(sketch_path, error)) {
    result.error = sketch + ": sketch not found";
    return result;
  }
  const std::string key = cache_key(sketch_path.string());
  const fs::path library = fs::path(cache_dir_) / (key + ".so");
  if (fs::is_regular_file(library, error)) {
    result.ok = result.from_cache = true;
    result.library_path = library.string();
    return result;
  }
  fs::create_directories(cache_dir_, error);
  if (error) {
    result.error = cache_dir_ + ": cannot create the sketch cache (" + error.message() + ")";
    return result;
  }
  const std::string suffix = unique_suffix();
  const fs::path temporary = fs::path(cache_dir_) / (key + ".tmp-" + suffix + ".so");
  const fs::path log = fs::path(cache_dir_) / (key + ".log-" + suffix);
  const ProcessResult compiled = run_process(compile_command(sketch_path.string(), temporary.string()), log.string());
  fs::remove(log, error);
  if (!compiled.started || compiled.exit_code != 0) {
    fs::remove(temporary, error);
    result.error = sketch + ": the sketch did not compile:\n" + compiled.output;
    return result;
  }
  fs::rename(temporary, library, error);
  if (error) {
    result.error = library.string() + ": cannot store the compiled sketch (" + error.message() + ")";
    return result;
  }
  result.ok = true;
  result.library_path = library.string();
  result.diagnostics = compiled.output;
  return result;
}

}  // namespace stepdance::sim
