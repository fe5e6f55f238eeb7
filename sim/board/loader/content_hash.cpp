// FNV-1a over strings and files, for the sketch cache.
#include "board/loader/content_hash.hpp"

#include <cstdio>
#include <fstream>

namespace stepdance::sim {

void ContentHash::add(const std::string& bytes) {
  for (const char c : bytes) add_byte(static_cast<uint8_t>(c));
  add_byte(0xFF);
}

bool ContentHash::add_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    add("<unreadable>" + path);
    return false;
  }
  char buffer[1 << 16];
  while (in) {
    in.read(buffer, sizeof buffer);
    const std::streamsize got = in.gcount();
    for (std::streamsize i = 0; i < got; ++i) add_byte(static_cast<uint8_t>(buffer[i]));
  }
  add_byte(0xFF);
  return true;
}

std::string ContentHash::hex() const {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value_));
  return text;
}

}  // namespace stepdance::sim
