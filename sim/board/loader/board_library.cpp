// dlopen of board libraries, copying the file for every board after the first that uses it and
// running every copy from the original's code pages.
#include "board/loader/board_library.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <filesystem>
#include <map>

#include "board/loader/board_code_ranges.hpp"
#include "board/loader/shared_code_pages.hpp"

namespace stepdance::sim {
namespace {

namespace fs = std::filesystem;

// How many boards currently use each library path in this process.
std::map<std::string, int>& users_by_path() {
  static std::map<std::string, int> users;
  return users;
}

void* open_library(const std::string& path, std::string& error) {
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* reason = dlerror();
    error = path + ": cannot load the board library: " + (reason != nullptr ? reason : "unknown error");
  }
  return handle;
}

// Loads a private copy so this board's globals are not the first board's, then maps its code
// and constants from `path` again, so that a thousand boards do not run a thousand copies of the
// same code (they did not fit the processor's caches: docs/simulator.md, "Many boards").
void* open_private_copy(const std::string& path, int copy_index, std::string& error) {
  const std::string copy = path + ".copy-" + std::to_string(copy_index) + "-" + std::to_string(::getpid()) + ".so";
  std::error_code fs_error;
  fs::copy_file(path, copy, fs::copy_options::overwrite_existing, fs_error);
  if (fs_error) {
    error = copy + ": cannot copy the board library (" + fs_error.message() + ")";
    return nullptr;
  }
  void* handle = open_library(copy, error);
  fs::remove(copy, fs_error);
  if (handle != nullptr) share_read_only_pages(handle, path);
  return handle;
}

}  // namespace

BoardLibrary::BoardLibrary(void* handle, StepdanceBoardAttachFn attach_fn, std::string key)
    : handle_(handle), attach_(attach_fn), key_(std::move(key)) {
  find_board_code(handle_, load_base_, code_);
}

std::unique_ptr<BoardLibrary> BoardLibrary::load(const std::string& library_path, std::string& error) {
  const std::string key = fs::absolute(library_path).lexically_normal().string();
  const int users = users_by_path()[key];
  void* handle = users == 0 ? open_library(key, error) : open_private_copy(key, users, error);
  if (handle == nullptr) return nullptr;
  auto attach_fn = reinterpret_cast<StepdanceBoardAttachFn>(dlsym(handle, STEPDANCE_BOARD_ATTACH_SYMBOL));
  if (attach_fn == nullptr) {
    error = library_path + ": not a Stepdance board library (no " STEPDANCE_BOARD_ATTACH_SYMBOL ")";
    dlclose(handle);
    return nullptr;
  }
  ++users_by_path()[key];
  return std::unique_ptr<BoardLibrary>(new BoardLibrary(handle, attach_fn, key));
}

BoardLibrary::~BoardLibrary() {
  dlclose(handle_);
  if (--users_by_path()[key_] == 0) users_by_path().erase(key_);
}

}  // namespace stepdance::sim
