// File storage of a simulated board, backed by a host folder.
#include "board/host/board_storage.hpp"

#include <cstring>
#include <filesystem>

namespace stepdance::sim {

bool BoardStorage::valid_name(const char* name) {
  if (name == nullptr) return false;
  const size_t length = std::strlen(name);
  if (length == 0 || length > 63) return false;
  if (std::strchr(name, '/') != nullptr || std::strchr(name, '\\') != nullptr) return false;
  return std::strcmp(name, ".") != 0 && std::strcmp(name, "..") != 0;
}

Status BoardStorage::open(const char* name, int mode, int& handle) {
  if (directory_.empty()) return Status::kUnsupported;
  if (!valid_name(name) || mode < 0 || mode > 2) return Status::kBadArgument;
  if (open_files_.size() >= static_cast<size_t>(kMaxOpenFiles)) {
    ++refused_opens_;
    return Status::kFull;
  }
  std::error_code error;
  if (mode != 0) std::filesystem::create_directories(directory_, error);
  std::ios::openmode flags = std::ios::binary;
  if (mode == 0) flags |= std::ios::in;
  if (mode == 1) flags |= std::ios::out | std::ios::trunc;
  if (mode == 2) flags |= std::ios::out | std::ios::app;
  auto file = std::make_unique<std::fstream>(directory_ + "/" + name, flags);
  if (!file->is_open()) return Status::kIoError;
  handle = next_handle_++;
  open_files_[handle] = std::move(file);
  return Status::kOk;
}

Status BoardStorage::read(int handle, uint8_t* data, size_t length, size_t& read) {
  read = 0;
  const auto found = open_files_.find(handle);
  if (found == open_files_.end()) return Status::kBadArgument;
  found->second->read(reinterpret_cast<char*>(data), static_cast<std::streamsize>(length));
  read = static_cast<size_t>(found->second->gcount());
  if (found->second->eof()) found->second->clear();
  return Status::kOk;
}

Status BoardStorage::write(int handle, const uint8_t* data, size_t length) {
  const auto found = open_files_.find(handle);
  if (found == open_files_.end()) return Status::kBadArgument;
  if (length > kWriteLimitBytes - written_bytes_) {
    ++refused_writes_;
    refused_write_bytes_ += length;
    return Status::kFull;
  }
  written_bytes_ += length;
  found->second->write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(length));
  return found->second->good() ? Status::kOk : Status::kIoError;
}

Status BoardStorage::close(int handle) {
  const auto found = open_files_.find(handle);
  if (found == open_files_.end()) return Status::kBadArgument;
  open_files_.erase(found);
  return Status::kOk;
}

}  // namespace stepdance::sim
