// `stepdance decode`: reads a VCD, pairs or picks STEP/DIR wires, decodes like an input port.
#include "decode_command.hpp"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <memory>
#include <vector>

#include <nlohmann/json.hpp>

#include "command_help.hpp"
#include "decode/capture_decoder.hpp"
#include "decode/decode_report.hpp"
#include "decode/pair_decoders.hpp"
#include "decode/step_dir_pairs.hpp"
#include "decode/vcd_reader.hpp"
#include "exit_codes.hpp"
#include "option_kinds.hpp"
#include "scenario/decimal_text.hpp"
#include "stepdance/core/frame_period.hpp"

namespace stepdance::cli {
namespace {

using sim::StepDirPair;
using sim::VcdCapture;

int bad_input(const std::string& message) {
  std::cerr << message << "\n";
  return kExitBadInput;
}

// The STEP/DIR pairs to decode: the two named wires, or every pair the file has.
bool choose_pairs(const DecodeCommandOptions& options, const VcdCapture& capture, std::vector<StepDirPair>& pairs,
                  std::string& error) {
  if (options.step_wire.empty() != options.dir_wire.empty()) {
    error = "--step and --dir go together";
    return false;
  }
  if (options.step_wire.empty()) {
    pairs = sim::find_step_dir_pairs(capture);
    if (pairs.empty()) error = "no STEP/DIR wire pairs (*STEP with *DIR); name them with --step and --dir";
    return !pairs.empty();
  }
  const sim::WireLookup step = sim::find_wire(capture, options.step_wire);
  const sim::WireLookup dir = sim::find_wire(capture, options.dir_wire);
  if (!step.ok || !dir.ok) {
    error = !step.ok ? step.error : dir.error;
    return false;
  }
  if (step.index == dir.index) {
    error = "--step and --dir name the same wire, '" + capture.wires[step.index].full_name() +
            "': a STEP/DIR pair is two wires";
    return false;
  }
  pairs.push_back({capture.wires[step.index].full_name(), step.index, dir.index});
  return true;
}

bool decode_options(const DecodeCommandOptions& options, sim::DecodeOptions& decode, std::string& error) {
  decode.mode = options.mode == "step_dir" ? INPUT_MODE_STEP_DIR : INPUT_MODE_STEPDANCE;
  const std::optional<int64_t> period_us = sim::scenario::parse_decimal_integer(options.frame_period_us);
  if (!period_us || *period_us < 0 || *period_us > UINT32_MAX ||
      !frame_period_supported(static_cast<uint32_t>(*period_us))) {
    error = "--frame-us must be 10, 20, 25 or 40 (the sending board's frame period), got " + options.frame_period_us;
    return false;
  }
  decode.frame_period_us = static_cast<uint32_t>(*period_us);
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
    if (options.axis == sim::signal_name(signal)) {
      decode.step_dir_signal = signal;
      return true;
    }
  }
  error = "--axis must be one of X, Y, R, T, Z, E";
  return false;
}

/// `text` indented by `spaces` more after every line break (a nested JSON value).
std::string indented(const std::string& text, const std::string& spaces) {
  std::string out;
  for (const char c : text) {
    out += c;
    if (c == '\n') out += spaces;
  }
  return out;
}

/// The JSON report, written a port at a time (one JSON document of every port would be held
/// whole): {"capture", "ports": {label: report, …} in key order, a label's last pair winning,
/// "truncated" when cut}, as nlohmann's dump(2) of the whole document would print it.
void print_json(const std::string& capture, sim::PairDecoders& decoders, const std::string& truncated) {
  const std::vector<StepDirPair>& pairs = decoders.pairs();
  std::vector<size_t> order(pairs.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&pairs](size_t a, size_t b) { return pairs[a].label < pairs[b].label; });
  std::cout << "{\n  \"capture\": " << nlohmann::json(capture).dump() << ",\n  \"ports\": {";
  bool first = true;
  for (size_t at = 0; at < order.size(); ++at) {
    const size_t index = order[at];
    if (at + 1 < order.size() && pairs[order[at + 1]].label == pairs[index].label) continue;  // the last one wins
    std::cout << (first ? "\n    " : ",\n    ") << nlohmann::json(pairs[index].label).dump() << ": "
              << indented(sim::decode_report_json(decoders.finish(index)).dump(2), "    ");
    first = false;
  }
  std::cout << (first ? "}" : "\n  }");
  if (!truncated.empty()) std::cout << ",\n  \"truncated\": " << nlohmann::json(truncated).dump();
  std::cout << "\n}\n";
}

/// Reads the capture into `decoders` (made once the pairs are known): declarations first, then
/// the value changes straight into them, so the capture itself is never held (a chunk and one
/// token at a time) and memory does not grow with its length. The reader and its declarations
/// are gone when this returns. Returns kExitOk (with `truncated` set to the warning if the
/// capture is cut) or kExitBadInput after printing why.
int read_capture(const DecodeCommandOptions& options, const sim::DecodeOptions& decode,
                 std::unique_ptr<sim::PairDecoders>& decoders, std::string& truncated) {
  std::ifstream in(options.capture_path, std::ios::binary);
  if (!in) return bad_input(options.capture_path + ":0: cannot open");
  sim::VcdStreamReader reader(in, options.capture_path);
  if (!reader.read_declarations()) return bad_input(reader.take_result().error);
  std::vector<StepDirPair> pairs;
  std::string error;
  if (!choose_pairs(options, reader.declarations(), pairs, error))
    return bad_input(options.capture_path + ": " + error);
  decoders = std::make_unique<sim::PairDecoders>(reader.declarations().wires.size(), std::move(pairs), decode);
  if (!reader.read_values(*decoders)) return bad_input(reader.take_result().error);
  const sim::VcdReadResult read = reader.take_result();
  if (read.truncated) truncated = read.warning;
  return kExitOk;
}

}  // namespace

CLI::App& add_decode_command(CLI::App& app, DecodeCommandOptions& options) {
  CLI::App& decode = add_command(
      app, "decode",
      "Decode a VCD capture of a Stepdance cable (from the simulator, or exported by PulseView/sigrok "
      "from a logic analyzer): step counts per axis and direction, rejected pulses with reasons, "
      "frame statistics.",
      {{kExitOk, "ok"},
       {kExitBadInput, "bad capture or options"},
       {kExitTruncatedCapture,
        "the capture is truncated (it ends mid-stream: what it holds is decoded and reported, with a warning)"}});
  add_path_option(decode, "capture", options.capture_path, "the .vcd file")->required();
  decode.add_option("--step", options.step_wire, "STEP wire (full name like driver.OUT_A_STEP, or a bare name)");
  decode.add_option("--dir", options.dir_wire, "DIR wire that goes with --step");
  decode
      .add_option("--mode", options.mode,
                  "stepdance: axis by pulse width, DIR at the falling edge; "
                  "step_dir: every pulse is one step, DIR at the rising edge")
      ->check(CLI::IsMember({"stepdance", "step_dir"}))
      ->capture_default_str();
  decode.add_option("--axis", options.axis, "the axis step_dir pulses count as (X, Y, R, T, Z, E)")
      ->capture_default_str();
  add_number_option(decode, "--frame-us", options.frame_period_us,
                    "the sending board's frame period in us (10, 20, 25 or 40): how pulses group into "
                    "frames for the frame statistics; the counts do not depend on it")
      ->capture_default_str();
  decode.add_flag("--json", options.json, "print JSON instead of text");
  return decode;
}

int run_decode_command(const DecodeCommandOptions& options) {
  sim::DecodeOptions decode;
  std::string error;
  if (!decode_options(options, decode, error)) return bad_input(error);
  std::unique_ptr<sim::PairDecoders> decoders;
  std::string truncated;
  if (const int status = read_capture(options, decode, decoders, truncated); status != kExitOk) return status;
  if (!truncated.empty()) std::cerr << "warning: " << truncated << "\n";
  if (options.json) {
    print_json(options.capture_path, *decoders, truncated);
  } else {
    for (size_t i = 0; i < decoders->pairs().size(); ++i) {
      std::cout << sim::format_decode_report(decoders->finish(i), decoders->pairs()[i].label) << "\n";
    }
  }
  return truncated.empty() ? kExitOk : kExitTruncatedCapture;
}

}  // namespace stepdance::cli
