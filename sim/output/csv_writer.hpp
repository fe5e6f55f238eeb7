// Streams sampled values over time to a CSV file with fixed-precision, deterministic formatting.
#pragma once

#include <fstream>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "common/sim_time.hpp"

namespace stepdance::sim {

/// One CSV column after time_s.
struct CsvColumn {
  std::string name;  ///< header text (quoted in the file if it holds ',', '"' or a line break)
  int decimals = 3;  ///< digits after the point, 0..17
};

/// Writes `time_s,<names…>` then one row per sample: the time in seconds with 6 decimals (exact,
/// from integer ns, rounded half up to the µs), then each value with its column's decimals
/// ("%.*f" in the C locale, never "-0", "nan"/"inf" for non-finite values). Lines end in "\n".
/// Errors throw: std::invalid_argument for a bad column or row, std::runtime_error("path: …")
/// for I/O failures.
class CsvWriter {
 public:
  /// Writes to the file at `path` (created or truncated); the header is written at once.
  CsvWriter(const std::string& path, std::vector<CsvColumn> columns);
  /// Writes to `out`, which must outlive the writer. `name` labels error messages.
  CsvWriter(std::ostream& out, std::string name, std::vector<CsvColumn> columns);

  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  /// Appends a row: `values` holds one number per column, in column order.
  void write_row(SimTime time, const std::vector<double>& values);

  /// Flushes and, for a file, closes it; throws if anything failed. Idempotent.
  void close();

 private:
  void write_header();

  std::unique_ptr<std::ofstream> file_;
  std::ostream* out_;
  std::string name_;
  std::vector<CsvColumn> columns_;
  std::string line_;
  bool closed_ = false;
};

}  // namespace stepdance::sim
