// write_text_file: one binary write, checked when the file opens and again when it closes.
#include "output/text_file.hpp"

#include <fstream>
#include <stdexcept>

namespace stepdance::sim {

void write_text_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error(path + ": cannot open for writing");
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw std::runtime_error(path + ": write failed");
}

}  // namespace stepdance::sim
