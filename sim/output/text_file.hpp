// Writing a whole output file from text held in memory, with the writers' error messages.
#pragma once

#include <string>

namespace stepdance::sim {

/// Writes `text` to `path` byte for byte, replacing the file. Throws std::runtime_error
/// ("<path>: cannot open for writing" or "<path>: write failed").
void write_text_file(const std::string& path, const std::string& text);

}  // namespace stepdance::sim
