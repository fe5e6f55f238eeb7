// Sketch compilation: cache lookup, the compiler command line, and atomic publication of the .so.
#include "board/loader/sketch_builder.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "board/abi/board_abi.h"
#include "board/loader/content_hash.hpp"
#include "board/loader/dependency_file.hpp"
#include "board/loader/process.hpp"
#include "board/loader/sketch_sources.hpp"
#include "board/loader/toolchain_config.hpp"

namespace stepdance::sim {
namespace {

namespace fs = std::filesystem;

std::string env_or_empty(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr ? value : "";
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

bool write_file(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  return static_cast<bool>(out.flush());
}

/// The hash of the files a build read: their paths and contents (a file gone counts as changed).
std::string inputs_key(const std::vector<std::string>& inputs) {
  ContentHash hash;
  for (const std::string& file : inputs) {
    hash.add(file);
    hash.add_file(file);
  }
  return hash.hex();
}

/// The lines of a manifest (one path each); false if it cannot be read.
bool read_lines(const fs::path& path, std::vector<std::string>& lines) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  lines.clear();
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) lines.push_back(line);
  }
  return true;
}

/// Every file the compiler read, from the dependency files of one build: absolute, normal,
/// sorted, each once, the generated translation unit (under `generated_prefix`) replaced by the
/// .ino files it was made of.
bool collect_inputs(const std::vector<std::string>& dependency_files, const std::string& generated_prefix,
                    const std::vector<std::string>& inos, std::vector<std::string>& inputs) {
  std::vector<std::string> all = inos;
  for (const std::string& file : dependency_files) {
    std::vector<std::string> read;
    if (!read_dependency_file(file, read)) return false;
    for (const std::string& path : read) {
      const std::string normal = fs::absolute(path).lexically_normal().string();
      if (normal.rfind(generated_prefix, 0) != 0) all.push_back(normal);
    }
  }
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  inputs = std::move(all);
  return true;
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

std::vector<std::string> SketchBuilder::toolchain_paths() {
  std::vector<std::string> paths(std::begin(toolchain::kIncludeDirs), std::end(toolchain::kIncludeDirs));
  paths.emplace_back(toolchain::kRuntimeLibrary);
  paths.emplace_back(toolchain::kExportMap);
  return paths;
}

std::string SketchBuilder::cache_key(const SketchSources& sources) const {
  ContentHash hash;
  hash.add(std::to_string(STEPDANCE_BOARD_ABI_VERSION));
  hash.add(toolchain::kCompiler);
  for (const char* flag : toolchain::kFlags) hash.add(flag);
  hash.add(toolchain::kCCompiler);
  for (const char* flag : toolchain::kCFlags) hash.add(flag);
  for (const char* dir : toolchain::kIncludeDirs) {
    hash.add(dir);
    for (const std::string& header : headers_under(dir)) hash.add_file(header);
  }
  hash.add(toolchain::kForcedInclude);
  hash.add_file(toolchain::kRuntimeLibrary);
  hash.add_file(toolchain::kExportMap);
  for (const auto* group : {&sources.inos, &sources.cpp_files, &sources.c_files, &sources.headers}) {
    hash.add(std::to_string(group->size()));
    for (const std::string& file : *group) {
      hash.add(file);
      hash.add_file(file);
    }
  }
  return hash.hex();
}

std::vector<std::string> SketchBuilder::c_command(const std::string& source, const std::string& object) const {
  std::vector<std::string> command{toolchain::kCCompiler};
  for (const char* flag : toolchain::kCFlags) command.emplace_back(flag);
  for (const char* dir : toolchain::kIncludeDirs) command.push_back(std::string("-I") + dir);
  command.insert(command.end(), {"-c", source, "-o", object, "-MD", "-MF", object + ".d"});
  return command;
}

std::vector<std::string> SketchBuilder::cxx_command(const SketchSources& sources, const std::string& source,
                                                    const std::string& object) const {
  std::vector<std::string> command{toolchain::kCompiler};
  for (const char* flag : toolchain::kFlags) command.emplace_back(flag);
  command.push_back("-iquote" + sources.folder);  // the generated file lives in the cache
  for (const char* dir : toolchain::kIncludeDirs) command.push_back(std::string("-I") + dir);
  if (toolchain::kForcedInclude[0] != '\0') {
    command.emplace_back("-include");
    command.emplace_back(toolchain::kForcedInclude);
  }
  command.insert(command.end(), {"-x", "c++", source, "-c", "-o", object, "-MD", "-MF", object + ".d"});
  return command;
}

std::vector<std::string> SketchBuilder::link_command(const std::vector<std::string>& objects,
                                                     const std::string& output) const {
  std::vector<std::string> command{toolchain::kCompiler};
  for (const char* flag : toolchain::kFlags) command.emplace_back(flag);
  command.insert(command.end(), objects.begin(), objects.end());
  command.push_back(toolchain::kRuntimeLibrary);
  command.push_back(std::string("-Wl,--version-script=") + toolchain::kExportMap);
  command.insert(command.end(), {"-Wl,-u,stepdance_board_attach", "-shared", "-o", output});
  return command;
}

bool SketchBuilder::find_cached(const std::string& sources_key, SketchBuild& result) const {
  std::vector<std::string> inputs;
  if (!read_lines(fs::path(cache_dir_) / (sources_key + ".deps"), inputs)) return false;
  const fs::path library = fs::path(cache_dir_) / (sources_key + "-" + inputs_key(inputs) + ".so");
  std::error_code error;
  if (!fs::is_regular_file(library, error)) return false;
  result.ok = result.from_cache = true;
  result.library_path = library.string();
  result.inputs = std::move(inputs);
  return true;
}

bool SketchBuilder::store(const std::string& sources_key, const std::string& stem, SketchBuild& result) const {
  std::string manifest;
  for (const std::string& file : result.inputs) manifest += file + "\n";
  const fs::path deps = fs::path(cache_dir_) / (sources_key + ".deps");
  const fs::path library = fs::path(cache_dir_) / (sources_key + "-" + inputs_key(result.inputs) + ".so");
  std::error_code error;
  if (!write_file(stem + ".deps", manifest)) {
    error = std::make_error_code(std::errc::io_error);
  } else {
    fs::rename(stem + ".deps", deps, error);
  }
  if (!error) fs::rename(stem + ".so", library, error);
  if (error) {
    result.error = library.string() + ": cannot store the compiled sketch (" + error.message() + ")";
    return false;
  }
  result.ok = true;
  result.library_path = library.string();
  return true;
}

SketchBuild SketchBuilder::build(const std::string& sketch) const {
  {
    const std::lock_guard<std::mutex> lock(built_mutex_);
    const auto found = built_.find(sketch);
    if (found != built_.end()) return found->second;
  }
  SketchBuild result = build_once(sketch);
  if (!result.ok) return result;
  SketchBuild again = result;
  again.from_cache = true;
  again.diagnostics.clear();  // its warnings were given with the first board
  const std::lock_guard<std::mutex> lock(built_mutex_);
  built_.emplace(sketch, std::move(again));
  return result;
}

SketchBuild SketchBuilder::build_once(const std::string& sketch) const {
  SketchBuild result;
  SketchSources sources;
  if (!find_sketch_sources(sketch, sources, result.error)) return result;
  const std::string key = cache_key(sources);
  if (find_cached(key, result)) return result;
  std::error_code error;
  fs::create_directories(cache_dir_, error);
  if (error) {
    result.error = cache_dir_ + ": cannot create the sketch cache (" + error.message() + ")";
    return result;
  }
  const std::string stem = (fs::path(cache_dir_) / (key + ".tmp-" + unique_suffix())).string();
  std::vector<std::string> scratch;  // removed whatever happens
  const bool compiled = compile(sources, stem, scratch, result);
  if (compiled) store(key, stem, result);
  scratch.insert(scratch.end(), {stem + ".so", stem + ".deps"});  // left behind only on failure
  for (const std::string& file : scratch) fs::remove(file, error);
  if (!compiled) result.error = sketch + ": the sketch did not compile:\n" + result.error;
  return result;
}

bool SketchBuilder::compile(const SketchSources& sources, const std::string& stem, std::vector<std::string>& scratch,
                            SketchBuild& result) const {
  std::string text;
  const std::string assembled = stem + ".ino.cpp";
  const std::string log = stem + ".log";
  scratch = {assembled, log};
  if (!assemble_sketch_files(sources, text, result.error)) return false;
  if (!write_file(assembled, text)) {
    result.error = assembled + ": cannot write the assembled sketch";
    return false;
  }
  std::vector<std::string> cxx_sources{assembled};
  cxx_sources.insert(cxx_sources.end(), sources.cpp_files.begin(), sources.cpp_files.end());
  std::vector<std::string> objects;
  const auto run = [&](const std::vector<std::string>& command) {
    const ProcessResult process = run_process(command, log);
    result.diagnostics += process.output;
    if (process.started && process.exit_code == 0) return true;
    result.error = result.diagnostics;
    return false;
  };
  const auto next_object = [&objects, &scratch, &stem] {
    objects.push_back(stem + "." + std::to_string(objects.size()) + ".o");
    scratch.insert(scratch.end(), {objects.back(), objects.back() + ".d"});
    return objects.back();
  };
  for (const std::string& source : cxx_sources) {
    if (!run(cxx_command(sources, source, next_object()))) return false;
  }
  for (const std::string& source : sources.c_files) {
    if (!run(c_command(source, next_object()))) return false;
  }
  if (!run(link_command(objects, stem + ".so"))) return false;
  std::vector<std::string> dependency_files;
  for (const std::string& object : objects) dependency_files.push_back(object + ".d");
  if (!collect_inputs(dependency_files, stem, sources.inos, result.inputs)) {
    result.error = stem + ": cannot read the compiler's dependency output";
    return false;
  }
  return true;
}

// "function at file:line" for each offset in the board library, from one run of addr2line; ""
// where it cannot say.
std::vector<std::string> SketchBuilder::symbols(const std::string& library_path,
                                                const std::vector<uintptr_t>& offsets) const {
  std::vector<std::string> symbols(offsets.size());
  if (offsets.empty()) return symbols;
  std::vector<std::string> command{"addr2line", "-f", "-C", "-e", library_path};
  for (const uintptr_t offset : offsets) {
    char hex[32];
    std::snprintf(hex, sizeof hex, "0x%lx", static_cast<unsigned long>(offset));
    command.push_back(hex);
  }
  const std::string log =
      (std::filesystem::temp_directory_path() / ("stepdance-addr2line-" + std::to_string(::getpid()))).string();
  const ProcessResult result = run_process(command, log);
  std::filesystem::remove(log);
  if (!result.started || result.exit_code != 0) return symbols;
  std::istringstream lines(result.output);
  for (std::string& symbol : symbols) {
    std::string function;
    std::string place;
    if (!std::getline(lines, function) || !std::getline(lines, place)) break;
    if (function.empty() || function == "??") continue;
    const bool unknown_place = place.empty() || place.rfind("??", 0) == 0 || place.find(":?") != std::string::npos;
    symbol = unknown_place ? function : function + " at " + place;
  }
  return symbols;
}

}  // namespace stepdance::sim
