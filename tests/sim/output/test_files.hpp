// Temporary files for the output-writer tests: unique paths and whole-file reads.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace stepdance::sim::test {

/// A path in the test temporary directory, unique per test: <tmp>/<suite>.<test>.<suffix>.
inline std::string temp_path(const std::string& suffix) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return ::testing::TempDir() + "stepdance_sim_output." + info->test_suite_name() + "." + info->name() + "." + suffix;
}

/// The whole content of a file ("" if it cannot be read).
inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

/// Writes `text` to `path`.
inline void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

}  // namespace stepdance::sim::test
