// libFuzzer target: arbitrary bytes as a VCD capture through the reader, STEP/DIR pairing and the
// pulse decoder in both modes (what `stepdance decode` does with a file).
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <sstream>
#include <string>

#include "decode/capture_decoder.hpp"
#include "decode/step_dir_pairs.hpp"
#include "decode/vcd_reader.hpp"

namespace {

using namespace stepdance::sim;

/// Every complete pulse is counted once: accepted or rejected for one reason.
void decode_and_check(const VcdWire& step, const VcdWire& dir, stepdance::InputMode mode) {
  DecodeOptions options;
  options.mode = mode;
  const DecodeResult result = decode_step_dir(step.edges, dir.edges, options, {step.initial, dir.initial});
  uint64_t counted = 0;
  for (const DirectionCounts& counts : result.counts.signals) counted += counts.forward + counts.reverse;
  if (counted != result.accepted) abort();
  uint64_t rises = step.initial ? 1 : 0;
  for (const Edge& edge : step.edges) rises += edge.level ? 1 : 0;
  if (result.accepted + result.counts.rejected() + result.incomplete != rises) abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  const VcdReadResult read = read_vcd(in, "fuzz.vcd");
  if (!read.ok) {
    if (read.error.empty()) abort();
    return 0;
  }
  if (read.truncated && read.warning.empty()) abort();
  const std::vector<VcdWire>& wires = read.capture.wires;
  for (const StepDirPair& pair : find_step_dir_pairs(read.capture)) {
    if (pair.step >= wires.size() || pair.dir >= wires.size()) abort();
    decode_and_check(wires[pair.step], wires[pair.dir], stepdance::INPUT_MODE_STEPDANCE);
    decode_and_check(wires[pair.step], wires[pair.dir], stepdance::INPUT_MODE_STEP_DIR);
  }
  return 0;
}
