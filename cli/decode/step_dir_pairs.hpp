// Chooses the STEP and DIR wires of a VCD capture: by name, or by pairing *_STEP with *_DIR.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "decode/vcd_reader.hpp"

namespace stepdance::sim {

/// A STEP wire and the DIR wire that goes with it.
struct StepDirPair {
  std::string label;  ///< the common prefix, e.g. "driver.OUT_A" for driver.OUT_A_STEP / driver.OUT_A_DIR
  size_t step = 0;    ///< index into VcdCapture::wires
  size_t dir = 0;     ///< index into VcdCapture::wires
};

/// Every 1-bit wire whose name ends in "STEP" (any case, e.g. "OUT_A_STEP", "step") paired with
/// the 1-bit wire of the same scope whose name is the same prefix followed by "DIR" (any case).
/// The label is the scope-qualified prefix without a trailing '_' or '.', or the scope (or
/// "STEP") when the prefix is empty. In declaration order of the STEP wires; unpaired STEP wires
/// are left out.
std::vector<StepDirPair> find_step_dir_pairs(const VcdCapture& capture);

/// The result of looking a wire up by name.
struct WireLookup {
  bool ok = false;
  size_t index = 0;   ///< into VcdCapture::wires, when ok
  std::string error;  ///< when !ok: "no wire named 'X' (wires: …)" or "'X' is ambiguous: …"
};

/// Finds the wire whose full name ("driver.OUT_A_STEP") is `name`, or else the only wire whose
/// bare name ("D0") is `name`.
WireLookup find_wire(const VcdCapture& capture, const std::string& name);

}  // namespace stepdance::sim
