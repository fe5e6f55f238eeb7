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
    result.error = sketch_path + ": no precompiled board for this sketch in the page (it has: " +
                   (known.empty() ? "none" : known) + "); a changed sketch needs a local `stepdance serve`";
    return result;
  }
  result.ok = true;
  result.from_cache = true;
  result.library_path = found->second;
  return result;
}

}  // namespace stepdance::web
