// Samples motor, pen and knob positions at a fixed interval into the scenario's CSV file.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "common/sim_time.hpp"
#include "kernel/scheduler/periodic_timer.hpp"
#include "output/csv_writer.hpp"

namespace stepdance::sim {

/// A CSV column and how to read its value at a sample time.
struct CsvProbe {
  CsvColumn column;
  std::function<double(SimTime)> read;
};

/// Writes one row every interval from time 0 (a row at 0, interval, 2 × interval, …). Values
/// are read from the models when the row is due; motor positions include the steps of a frame
/// being played at that moment (up to 32 µs ahead of the row's time).
class CsvSampler {
 public:
  CsvSampler(Scheduler& scheduler, const std::string& path, std::vector<CsvProbe> probes, SimTime interval_ns);
  /// Flushes and closes the file; throws std::runtime_error("path: …") on failure.
  void close();

 private:
  static void sample(void* context, SimTime time);

  std::vector<CsvProbe> probes_;
  CsvWriter writer_;
  PeriodicTimer timer_;
  std::vector<double> row_;
};

}  // namespace stepdance::sim
