// Run folders: named after the server's process id, so a later server can tell a dead one's.
#include "serve/run_folders.hpp"

#include <signal.h>
#include <stdlib.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <regex>
#include <stdexcept>

namespace stepdance::cli::serve {
namespace {

namespace fs = std::filesystem;
constexpr const char* kPrefix = "stepdance-serve-";

// Gives the owner every right on `path` and, if it is a folder, on everything beneath it.
void open_up(const fs::path& path) {
  std::error_code ignored;
  if (fs::is_symlink(path, ignored)) return;
  fs::permissions(path, fs::perms::owner_all, fs::perm_options::add, ignored);
  if (!fs::is_directory(path, ignored)) return;
  for (const fs::directory_entry& entry : fs::directory_iterator(path, ignored)) open_up(entry.path());
}

bool process_alive(pid_t pid) { return kill(pid, 0) == 0 || errno == EPERM; }

}  // namespace

std::string make_run_folder() {
  std::string pattern = (fs::temp_directory_path() / (kPrefix + std::to_string(getpid()) + "-XXXXXX")).string();
  if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot make a folder for the run: " + pattern);
  return pattern;
}

bool remove_run_folder(const std::string& folder) {
  std::error_code error;
  fs::remove_all(folder, error);
  if (error) {
    open_up(folder);
    fs::remove_all(folder, error);
  }
  return !fs::exists(folder, error);
}

int remove_stale_run_folders() {
  static const std::regex kName(std::string(kPrefix) + "([0-9]+)-[A-Za-z0-9]{6}");
  std::error_code error;
  int removed = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(fs::temp_directory_path(), error)) {
    std::smatch match;
    const std::string name = entry.path().filename().string();
    if (!std::regex_match(name, match, kName) || !entry.is_directory(error)) continue;
    const pid_t pid = static_cast<pid_t>(std::stol(match[1].str()));
    if (pid == getpid() || process_alive(pid)) continue;
    if (remove_run_folder(entry.path().string())) ++removed;
  }
  return removed;
}

}  // namespace stepdance::cli::serve
