// output_conflicts: each path resolved once (symlinks, inode), then every pair compared.
#include "assembly/output_plan.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <utility>

namespace stepdance::sim {
namespace {

namespace fs = std::filesystem;

/// A path as the file system sees it: symlinks in its existing part resolved, and the file's
/// device and inode when it exists.
struct ResolvedPath {
  std::string path;  ///< generic form, no trailing separator (but "/")
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;
};

ResolvedPath resolve(const std::string& path) {
  ResolvedPath resolved;
  std::error_code error;
  fs::path canonical = fs::weakly_canonical(fs::absolute(path), error);
  if (error) canonical = fs::absolute(path).lexically_normal();
  resolved.path = canonical.generic_string();
  while (resolved.path.size() > 1 && resolved.path.back() == '/') resolved.path.pop_back();
  struct stat status {};
  if (::stat(path.c_str(), &status) == 0) {
    resolved.exists = true;
    resolved.device = status.st_dev;
    resolved.inode = status.st_ino;
  }
  return resolved;
}

bool same_file(const ResolvedPath& a, const ResolvedPath& b) {
  if (a.path == b.path) return true;
  return a.exists && b.exists && a.device == b.device && a.inode == b.inode;
}

/// Whether `inner` lies below `outer` (not equal to it): a string comparison, since every pair
/// of a thousand boards' outputs is compared (path iteration made that 40 s).
bool is_inside(const std::string& inner, const std::string& outer) {
  if (inner.size() <= outer.size() || inner.compare(0, outer.size(), outer) != 0) return false;
  return outer == "/" || inner[outer.size()] == '/';
}

/// "'svg' (file:line)", or just "--csv" for an option.
std::string located(const OutputOrigin& origin) {
  return origin.where == origin.what ? origin.what : origin.what + " (" + origin.where + ")";
}

/// "where: what would ", or "--csv: would " for an option.
std::string would(const OutputOrigin& origin) {
  return origin.where + ": " + (origin.where == origin.what ? "" : origin.what + " ") + "would ";
}

/// The conflict between output `later` and the earlier output `earlier`, or "".
std::string output_clash(const PlannedOutput& later, const ResolvedPath& later_path, const PlannedOutput& earlier,
                         const ResolvedPath& earlier_path) {
  const auto start = [&] { return would(later.origin) + "write " + later.path; };
  if (same_file(later_path, earlier_path)) return start() + ", which " + located(earlier.origin) + " also writes";
  if (is_inside(later_path.path, earlier_path.path)) {
    return start() + " inside " + earlier.path + ", which " + located(earlier.origin) + " writes";
  }
  if (is_inside(earlier_path.path, later_path.path)) {
    return start() + ", but " + located(earlier.origin) + " writes " + earlier.path + " inside it";
  }
  return {};
}

/// The conflict between an output and an input, or "".
std::string input_clash(const PlannedOutput& output, const ResolvedPath& output_path, const RunInput& input,
                        const ResolvedPath& input_path) {
  if (same_file(output_path, input_path)) {
    return would(output.origin) + "overwrite " + input.what + " " + input.path + " (an output never replaces an input)";
  }
  if (output.folder && is_inside(input_path.path, output_path.path)) {
    return would(output.origin) + "write the folder " + output.path + ", which holds " + input.what + " " + input.path;
  }
  return {};
}

/// Paths indexed for the lookups the comparisons need: by text, by inode, and sorted (for
/// everything below a folder). Only pairs these find can clash, so a thousand boards' outputs
/// are not compared pairwise (that took 40 s).
class PathIndex {
 public:
  explicit PathIndex(const std::vector<ResolvedPath>& paths) {
    for (size_t k = 0; k < paths.size(); ++k) {
      by_text_.emplace(paths[k].path, k);
      if (paths[k].exists) by_inode_.emplace(std::make_pair(paths[k].device, paths[k].inode), k);
    }
  }
  /// Indices whose path is `path`'s or one above it, or the same file.
  void above_or_same(const ResolvedPath& path, std::vector<size_t>& out) const {
    for (size_t end = path.path.size(); end > 0;) {
      const auto [from, to] = by_text_.equal_range(path.path.substr(0, end));
      for (auto found = from; found != to; ++found) out.push_back(found->second);
      if (end == 1) break;
      const size_t slash = path.path.rfind('/', end - 1);
      if (slash == std::string::npos) break;
      end = slash == 0 ? 1 : slash;
    }
    if (!path.exists) return;
    const auto [from, to] = by_inode_.equal_range(std::make_pair(path.device, path.inode));
    for (auto found = from; found != to; ++found) out.push_back(found->second);
  }
  /// Sorted indices that may clash with `path`: the same file, and below it when it is a folder.
  std::vector<size_t> candidates(const ResolvedPath& path, bool folder) const {
    std::vector<size_t> out;
    const auto [from, to] = by_text_.equal_range(path.path);
    for (auto found = from; found != to; ++found) out.push_back(found->second);
    if (path.exists) {
      const auto [first, last] = by_inode_.equal_range(std::make_pair(path.device, path.inode));
      for (auto found = first; found != last; ++found) out.push_back(found->second);
    }
    if (folder) {
      const std::string prefix = path.path == "/" ? "/" : path.path + "/";
      for (auto found = by_text_.lower_bound(prefix); found != by_text_.end() && found->first.rfind(prefix, 0) == 0;
           ++found)
        out.push_back(found->second);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

 private:
  std::multimap<std::string, size_t> by_text_;
  std::multimap<std::pair<dev_t, ino_t>, size_t> by_inode_;
};

/// For each path, the sorted indices of the others it may clash with: the same file, or one
/// inside the other.
std::vector<std::vector<size_t>> related_pairs(const std::vector<ResolvedPath>& paths) {
  const PathIndex index(paths);
  std::vector<std::vector<size_t>> partners(paths.size());
  std::vector<size_t> found;
  for (size_t j = 0; j < paths.size(); ++j) {
    found.clear();
    index.above_or_same(paths[j], found);
    for (const size_t k : found) {
      if (k == j) continue;
      partners[j].push_back(k);
      partners[k].push_back(j);
    }
  }
  for (std::vector<size_t>& list : partners) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return partners;
}

}  // namespace

std::vector<std::string> output_conflicts(const std::vector<PlannedOutput>& outputs,
                                          const std::vector<RunInput>& inputs) {
  std::vector<ResolvedPath> output_paths;
  for (const PlannedOutput& output : outputs) output_paths.push_back(resolve(output.path));
  // Every board lists the ~470 files its build read, mostly the same ones: each resolved once.
  std::map<std::string, ResolvedPath> resolved_inputs;
  std::vector<ResolvedPath> input_paths;
  for (const RunInput& input : inputs) {
    auto found = resolved_inputs.find(input.path);
    if (found == resolved_inputs.end()) found = resolved_inputs.emplace(input.path, resolve(input.path)).first;
    input_paths.push_back(found->second);
  }
  const std::vector<std::vector<size_t>> partners = related_pairs(output_paths);
  const PathIndex input_index(input_paths);
  std::vector<std::string> conflicts;
  for (size_t i = 0; i < outputs.size(); ++i) {
    for (const size_t k : input_index.candidates(output_paths[i], outputs[i].folder)) {
      const std::string clash = input_clash(outputs[i], output_paths[i], inputs[k], input_paths[k]);
      if (!clash.empty()) {
        conflicts.push_back(clash);
        break;  // one input is enough to refuse an output
      }
    }
    for (const size_t j : partners[i]) {
      if (j >= i) break;
      const bool swap = outputs[i].origin.defaulted && !outputs[j].origin.defaulted;
      const size_t later = swap ? j : i;
      const size_t earlier = swap ? i : j;
      const std::string clash =
          output_clash(outputs[later], output_paths[later], outputs[earlier], output_paths[earlier]);
      if (!clash.empty()) conflicts.push_back(clash);
    }
  }
  return conflicts;
}

std::string output_conflicts_text(const std::vector<PlannedOutput>& outputs, const std::vector<RunInput>& inputs) {
  std::string text;
  for (const std::string& conflict : output_conflicts(outputs, inputs)) text += (text.empty() ? "" : "\n") + conflict;
  return text;
}

}  // namespace stepdance::sim
