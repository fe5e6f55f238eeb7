// output_conflicts: each path resolved once (symlinks, inode), then every pair compared.
#include "assembly/output_plan.hpp"

#include <sys/stat.h>

#include <filesystem>

namespace stepdance::sim {
namespace {

namespace fs = std::filesystem;

/// A path as the file system sees it: symlinks in its existing part resolved, and the file's
/// device and inode when it exists.
struct ResolvedPath {
  fs::path path;
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;
};

ResolvedPath resolve(const std::string& path) {
  ResolvedPath resolved;
  std::error_code error;
  resolved.path = fs::weakly_canonical(fs::absolute(path), error);
  if (error) resolved.path = fs::absolute(path).lexically_normal();
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

/// Whether `inner` lies below `outer` (not equal to it).
bool is_inside(const fs::path& inner, const fs::path& outer) {
  auto in = inner.begin();
  for (auto out = outer.begin(); out != outer.end(); ++out, ++in) {
    if (out->empty()) continue;  // a trailing separator
    if (in == inner.end() || *in != *out) return false;
  }
  return in != inner.end();
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
  const std::string start = would(later.origin) + "write " + later.path;
  if (same_file(later_path, earlier_path)) return start + ", which " + located(earlier.origin) + " also writes";
  if (is_inside(later_path.path, earlier_path.path)) {
    return start + " inside " + earlier.path + ", which " + located(earlier.origin) + " writes";
  }
  if (is_inside(earlier_path.path, later_path.path)) {
    return start + ", but " + located(earlier.origin) + " writes " + earlier.path + " inside it";
  }
  return {};
}

/// The conflict between an output and an input, or "".
std::string input_clash(const PlannedOutput& output, const ResolvedPath& output_path, const RunInput& input,
                        const ResolvedPath& input_path) {
  const std::string start = would(output.origin);
  if (same_file(output_path, input_path)) {
    return start + "overwrite " + input.what + " " + input.path + " (an output never replaces an input)";
  }
  if (output.folder && is_inside(input_path.path, output_path.path)) {
    return start + "write the folder " + output.path + ", which holds " + input.what + " " + input.path;
  }
  return {};
}

}  // namespace

std::vector<std::string> output_conflicts(const std::vector<PlannedOutput>& outputs,
                                          const std::vector<RunInput>& inputs) {
  std::vector<ResolvedPath> output_paths;
  for (const PlannedOutput& output : outputs) output_paths.push_back(resolve(output.path));
  std::vector<ResolvedPath> input_paths;
  for (const RunInput& input : inputs) input_paths.push_back(resolve(input.path));
  std::vector<std::string> conflicts;
  for (size_t i = 0; i < outputs.size(); ++i) {
    for (size_t k = 0; k < inputs.size(); ++k) {
      const std::string clash = input_clash(outputs[i], output_paths[i], inputs[k], input_paths[k]);
      if (!clash.empty()) {
        conflicts.push_back(clash);
        break;  // one input is enough to refuse an output
      }
    }
    for (size_t j = 0; j < i; ++j) {
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
