// file_name_problem, inside_path_problem: byte rules, then one pass over a path's parts.
#include "scenario/file_names.hpp"

namespace stepdance::sim::scenario {
namespace {

bool has_control_byte(std::string_view text) {
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7F) return true;
  }
  return false;
}

}  // namespace

std::string file_name_problem(std::string_view name) {
  if (name.empty()) return "must not be empty";
  if (name.size() > kMaxFileNameBytes) return "must be at most " + std::to_string(kMaxFileNameBytes) + " bytes";
  if (name.find('/') != std::string_view::npos) return "must not contain '/'";
  if (name == "." || name == "..") return "must not be '.' or '..'";
  if (has_control_byte(name)) return "must not contain control characters";
  return {};
}

std::string inside_path_problem(std::string_view name) {
  if (name.empty()) return "must not be empty";
  if (name.front() == '/') return "must be a name inside the output folder, not an absolute path";
  if (has_control_byte(name)) return "must not contain control characters";
  std::size_t start = 0;
  while (start <= name.size()) {
    std::size_t end = name.find('/', start);
    if (end == std::string_view::npos) end = name.size();
    const std::string_view part = name.substr(start, end - start);
    if (part == "..") return "must stay inside the output folder (no '..')";
    start = end + 1;
  }
  return {};
}

}  // namespace stepdance::sim::scenario
