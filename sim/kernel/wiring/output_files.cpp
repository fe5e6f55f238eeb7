// Output files of a run: which ones, their folders made and checked writable before the run,
// and the lines a VCD records.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

#include "scenario/names.hpp"
#include "wiring/simulation.hpp"

namespace stepdance::sim {
namespace {

/// Creates `folder` (and its parents) and writes and removes a probe file in it; "" on success,
/// else why not.
std::string make_writable_folder(const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) return "cannot create the output folder " + folder.string() + ": " + error.message();
  const std::filesystem::path probe = folder / (".stepdance-write-test-" + std::to_string(::getpid()));
  bool written = false;
  {
    std::ofstream out(probe, std::ios::binary);
    written = out.is_open() && static_cast<bool>(out << "ok") && static_cast<bool>(out.flush());
  }
  std::filesystem::remove(probe, error);
  return written ? "" : "cannot write in the output folder " + folder.string();
}

}  // namespace

std::vector<std::string> Simulation::output_files() const {
  std::vector<std::string> files;
  const auto add = [&files](const std::string& path) {
    if (!path.empty()) files.push_back(path);
  };
  add(vcd_path_);
  add(csv_path_);
  if (scenario_.machine) {
    add(output_path(scenario_.output.svg));
    add(output_path(scenario_.output.png));
  }
  add(output_path(scenario_.output.summary));
  for (const scenario::HostClientConfig& host : scenario_.hosts) add(output_path(host.transcript));
  return files;
}

bool Simulation::prepare_outputs(SimulationError& error) const {
  std::set<std::filesystem::path> folders;
  for (const std::string& file : output_files()) {
    const std::filesystem::path path = std::filesystem::absolute(file).lexically_normal();
    std::error_code status;
    if (std::filesystem::is_directory(path, status)) {
      error = {SimulationError::kBadInput, "cannot write " + path.string() + ": it is a folder"};
      return false;
    }
    folders.insert(path.parent_path());
  }
  for (const std::filesystem::path& folder : folders) {
    const std::string problem = make_writable_folder(folder);
    if (!problem.empty()) {
      error = {SimulationError::kBadInput, problem};
      return false;
    }
  }
  return true;
}

std::vector<scenario::PortLineRef> Simulation::vcd_ports() const {
  if (!scenario_.output.vcd_ports.empty() || !options_.vcd_file) return scenario_.output.vcd_ports;
  std::vector<scenario::PortLineRef> ports;
  for (const scenario::BoardConfig& board : scenario_.boards) {
    for (char port = 'A'; port <= 'D'; ++port) {
      if (scenario::module_has_port(board.module, port)) ports.push_back({board.name, true, port});
    }
  }
  for (const scenario::CableConfig& cable : scenario_.cables) ports.push_back({cable.to.board, false, cable.to.port});
  return ports;
}

}  // namespace stepdance::sim
