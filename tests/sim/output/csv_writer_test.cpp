// CSV writer: exact text with quoting, time formatting, fixed decimals, and misuse.
#include <gtest/gtest.h>

#include <limits>
#include <sstream>
#include <stdexcept>

#include "output/csv_writer.hpp"
#include "sim/output/test_files.hpp"

namespace stepdance::sim {
namespace {

const std::vector<CsvColumn> kColumns = {{"x_mm", 3}, {"motor \"A\", steps", 0}};

void write_rows(CsvWriter& csv) {
  csv.write_row(0, {0, 0});
  csv.write_row(10 * kMillisecond, {1.23456, -0.4});
  csv.write_row(1'234'567'891, {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()});
  csv.write_row(600 * kSecond, {-12.0625, 960000});
  csv.close();
}

constexpr char kExpected[] =
    "time_s,x_mm,\"motor \"\"A\"\", steps\"\n"
    "0.000000,0.000,0\n"
    "0.010000,1.235,0\n"
    "1.234568,nan,inf\n"
    "600.000000,-12.062,960000\n";

TEST(CsvWriter, ExactText) {
  std::ostringstream out;
  CsvWriter csv(out, "positions.csv", kColumns);
  write_rows(csv);
  EXPECT_EQ(out.str(), kExpected);
}

TEST(CsvWriter, FileMatchesTheStreamOutput) {
  const std::string path = test::temp_path("positions.csv");
  CsvWriter csv(path, kColumns);
  write_rows(csv);
  EXPECT_EQ(test::read_text(path), kExpected);
}

TEST(CsvWriter, HeaderOnlyWithoutColumns) {
  std::ostringstream out;
  CsvWriter csv(out, "time.csv", {});
  csv.write_row(1500, {});
  EXPECT_EQ(out.str(), "time_s\n0.000002\n");
}

TEST(CsvWriter, MisuseThrows) {
  std::ostringstream out;
  EXPECT_THROW(CsvWriter(out, "bad.csv", {{"x", -1}}), std::invalid_argument);
  EXPECT_THROW(CsvWriter(out, "bad.csv", {{"x", 18}}), std::invalid_argument);
  CsvWriter csv(out, "bad.csv", kColumns);
  try {
    csv.write_row(0, {1});
    FAIL() << "a short row was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "bad.csv: CSV row has 1 values for 2 columns");
  }
  csv.close();
  EXPECT_THROW(csv.write_row(0, {1, 2}), std::logic_error);
  EXPECT_THROW(CsvWriter("/nonexistent-dir/x.csv", kColumns), std::runtime_error);
}

}  // namespace
}  // namespace stepdance::sim
