// PrecompiledBoards: sketch folder name → side module path, with a clear refusal for the rest.
#include "precompiled_boards.hpp"

#include <filesystem>

namespace stepdance::web {

std::string sketch_folder_name(const std::string& sketch_path) {
  std::filesystem::path path = std::filesystem::path(sketch_path).lexically_normal();
  if (!path.has_filename()) path = path.parent_path();  // "…/StepASketch/"
  if (path.extension() == ".ino") path = path.parent_path();
  return path.filename().string();
}

void PrecompiledBoards::add(const std::string& folder_name, const std::string& library_path) {
  libraries_[folder_name] = library_path;
}

sim::SketchBuild PrecompiledBoards::build(const std::string& sketch_path) const {
  sim::SketchBuild result;
  const auto found = libraries_.find(sketch_folder_name(sketch_path));
  if (found == libraries_.end()) {
    std::string known;
    for (const auto& [name, path] : libraries_) known += (known.empty() ? "" : ", ") + name;
    result.error = sketch_path +
                   ": no precompiled board for this sketch in the page (it has: " + (known.empty() ? "none" : known) +
                   "); a changed sketch needs a local `stepdance serve`";
    return result;
  }
  // A fresh copy for every board of every run: emscripten's dlopen keeps a module once loaded
  // (dlclose does not unload it), so opening the same path again would give the previous run's
  // board with its globals as that run left them.
  const std::string copy = found->second + ".run-" + std::to_string(++copies_) + ".wasm";
  std::error_code error;
  std::filesystem::copy_file(found->second, copy, std::filesystem::copy_options::overwrite_existing, error);
  if (error) {
    result.error = copy + ": cannot copy the board (" + error.message() + ")";
    return result;
  }
  result.ok = true;
  result.from_cache = true;
  result.library_path = copy;
  return result;
}

}  // namespace stepdance::web
