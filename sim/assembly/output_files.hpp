// The files a run writes: where each goes (the scenario's names, moved by --out or replaced by
// --vcd/--csv/--html), checked against each other and the run's inputs, their folders made and
// checked writable before any sketch is built, and the lines a VCD records.
#pragma once

#include <string>
#include <vector>

#include "assembly/output_plan.hpp"
#include "assembly/simulation_options.hpp"
#include "scenario/scenario.hpp"

namespace stepdance::sim {

/// The output paths of one run. Holds references to the scenario and options it was made from
/// (the Simulation owns both). Context: host, while a run is built and at its end.
class OutputFiles {
 public:
  OutputFiles(const scenario::Scenario& scenario, const SimulationOptions& options);

  /// The folder of the boards' SD cards (--out's, else the scenario's).
  const std::string& directory() const { return directory_; }
  const std::string& vcd_path() const { return vcd_path_; }    ///< "" = no VCD
  const std::string& csv_path() const { return csv_path_; }    ///< "" = no CSV
  const std::string& html_path() const { return html_path_; }  ///< "" = no replay page
  /// A configured output file's path, moved into --out's directory when that was given.
  std::string path_of(const std::string& configured) const;
  /// Every file and folder the run will write, and who asked for it (output_plan.hpp).
  std::vector<PlannedOutput> planned() const;
  /// Checks the outputs against each other and the scenario's inputs (output_plan.hpp) and the
  /// VCD's size for a run of `duration_ns`, then creates the folders of every output file and
  /// checks that each can be written; false with a kBadInput error naming the line, option or
  /// folder otherwise.
  bool prepare(SimTime duration_ns, SimulationError& error) const;
  /// The lines the VCD records: the scenario's vcd_ports, or everything (see vcd_file).
  std::vector<scenario::PortLineRef> vcd_ports() const;

 private:
  const scenario::Scenario& scenario_;
  const SimulationOptions& options_;
  std::string directory_;
  std::string vcd_path_;
  std::string csv_path_;
  std::string html_path_;
};

}  // namespace stepdance::sim
