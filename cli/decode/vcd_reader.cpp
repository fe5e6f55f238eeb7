// VCD reader: the declaration section, then value changes streamed to a listener (or kept as
// edge lists by read_vcd).
#include "decode/vcd_reader.hpp"

#include <charconv>
#include <cstdint>
#include <fstream>
#include <istream>
#include <limits>
#include <unordered_map>
#include <utility>

#include "decode/vcd_tokenizer.hpp"

namespace stepdance::sim {
namespace {

constexpr SimTime kFemtosecondsPerNs = 1'000'000;
/// Passed instead of 0/1 for a value that has no logic level (a real).
constexpr int kNoLevel = -1;

/// A token quoted for an error message: non-printable bytes escaped, long tokens shortened.
std::string quoted(const std::string& text) {
  static const char kHex[] = "0123456789abcdef";
  std::string out = "'";
  for (size_t i = 0; i < text.size() && i < 40; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= ' ' && c <= '~') {
      out += static_cast<char>(c);
    } else {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  if (text.size() > 40) out += "...";
  return out + "'";
}

bool parse_unsigned(const std::string& text, size_t offset, uint64_t& value) {
  if (offset >= text.size()) return false;
  const char* first = text.data() + offset;
  const char* last = text.data() + text.size();
  const auto result = std::from_chars(first, last, value);
  return result.ec == std::errc() && result.ptr == last;
}

/// Parses "1ns", "10 us" (joined), … into femtoseconds; false if not a valid timescale.
bool parse_timescale(const std::string& text, SimTime& femtoseconds) {
  size_t digits = 0;
  while (digits < text.size() && text[digits] >= '0' && text[digits] <= '9') ++digits;
  const std::string number = text.substr(0, digits);
  const std::string unit = text.substr(digits);
  SimTime multiplier = 0;
  if (number == "1")
    multiplier = 1;
  else if (number == "10")
    multiplier = 10;
  else if (number == "100")
    multiplier = 100;
  else
    return false;
  static const std::pair<const char*, SimTime> kUnits[] = {{"s", 1'000'000'000'000'000},
                                                           {"ms", 1'000'000'000'000},
                                                           {"us", 1'000'000'000},
                                                           {"ns", 1'000'000},
                                                           {"ps", 1'000},
                                                           {"fs", 1}};
  for (const auto& [name, fs] : kUnits) {
    if (unit == name) {
      femtoseconds = multiplier * fs;
      return true;
    }
  }
  return false;
}

}  // namespace

class VcdStreamReader::Parser {
 public:
  Parser(std::istream& in, std::string name) : in_(in), tokens_(in), name_(std::move(name)) {}

  bool declarations_done() { return ok_ = read_declarations(); }
  const VcdCapture& capture() const { return capture_; }
  bool values_done(VcdValueListener& listener) {
    listener_ = &listener;
    ok_ = read_values();
    if (ok_ && !initial_reported_) report_initial_levels();
    return ok_;
  }

  VcdReadResult take_result() {
    VcdReadResult result;
    if (ok_ && in_.bad()) {
      ok_ = false;
      error_ = name_ + ":0: read error";
    }
    if (!ok_) {
      result.error = std::move(error_);
      return result;
    }
    result.ok = true;
    result.capture = std::move(capture_);
    if (tokens_.cut() || dump_block_open_) {
      result.truncated = true;
      result.warning = name_ + ":" + std::to_string(tokens_.line()) + ": the capture is truncated (" +
                       (tokens_.cut() ? "it ends in the middle of line " + std::to_string(tokens_.cut_line())
                                      : std::string("a dump block has no $end")) +
                       "); decoded up to there";
    }
    return result;
  }

 private:
  bool fail(size_t line, const std::string& message) {
    error_ = name_ + ":" + std::to_string(line) + ": " + message;
    return false;
  }

  /// The end of the tokens: a token too long is an error of its own, else `message` at the end.
  bool fail_at_end(const std::string& message) {
    if (tokens_.too_long()) {
      return fail(tokens_.line(), "a token longer than " + std::to_string(VcdTokenizer::kMaxTokenBytes) +
                                      " bytes (this is not a VCD file)");
    }
    return fail(tokens_.line(), message);
  }

  /// Reads the tokens of a command up to its `$end` into `args`.
  bool read_until_end(const std::string& command, size_t line, std::vector<VcdToken>& args) {
    args.clear();
    VcdToken token;
    while (tokens_.next(token)) {
      if (token.text == "$end") return true;
      if (token.text.size() > 1 && token.text[0] == '$') {
        return fail(token.line, "missing $end of " + command + " (from line " + std::to_string(line) + "), found " +
                                    quoted(token.text));
      }
      if (args.size() >= kMaxCommandWords) {
        return fail(token.line, command + " (from line " + std::to_string(line) + ") has more than " +
                                    std::to_string(kMaxCommandWords) + " words before its $end");
      }
      args.push_back(token);
    }
    return fail_at_end("unexpected end of file: missing $end of " + command + " (from line " + std::to_string(line) +
                       ")");
  }

  /// Skips a free-text command (comment, date, version) up to `$end`, which may not be nested.
  bool skip_text(const std::string& command, size_t line) {
    VcdToken token;
    while (tokens_.next(token)) {
      if (token.text == "$end") return true;
    }
    return fail_at_end("unexpected end of file: missing $end of " + command + " (from line " + std::to_string(line) +
                       ")");
  }

  static bool is_text_command(const std::string& command) {
    return command == "$comment" || command == "$date" || command == "$version";
  }

  bool read_declarations() {
    VcdToken token;
    std::vector<VcdToken> args;
    while (tokens_.next(token)) {
      const std::string& command = token.text;
      if (command == "META" && capture_.wires.empty()) {
        tokens_.skip_line();  // sigrok-cli puts "META samplerate: N" lines into converted files
        continue;
      }
      if (command.empty() || command[0] != '$' || command == "$end") {
        return fail(token.line, "expected a declaration command, found " + quoted(command));
      }
      const size_t line = token.line;
      if (is_text_command(command)) {
        if (!skip_text(command, line)) return false;
        continue;
      }
      if (!read_until_end(command, line, args)) return false;
      if (command == "$enddefinitions") return true;
      if (command == "$timescale") {
        std::string joined;
        for (const VcdToken& arg : args) joined += arg.text;
        if (!parse_timescale(joined, capture_.timescale_fs)) {
          return fail(line,
                      "bad $timescale " + quoted(joined) + " (expected 1, 10 or 100 and s, ms, us, ns, ps or fs)");
        }
      } else if (command == "$scope") {
        if (args.size() != 2) return fail(line, "$scope needs a type and a name");
        if (!spend(line, args[1].text.size() + kScopeOverheadBytes)) return false;
        scopes_.push_back(args[1].text);
      } else if (command == "$upscope") {
        if (!args.empty()) return fail(line, "$upscope takes no arguments");
        if (scopes_.empty()) return fail(line, "$upscope without an open $scope");
        declaration_bytes_ -= scopes_.back().size() + kScopeOverheadBytes;
        scopes_.pop_back();
      } else if (command == "$var") {
        if (!declare_var(line, args)) return false;
      }
      // Other declaration commands ($attrbegin, $timezero, …) carry nothing we need.
    }
    return fail_at_end("unexpected end of file: missing $enddefinitions");
  }

  /// Counts `bytes` more of declarations; false (an error) beyond kMaxDeclarationBytes.
  bool spend(size_t line, size_t bytes) {
    declaration_bytes_ += bytes;
    if (declaration_bytes_ <= kMaxDeclarationBytes) return true;
    return fail(line, "the declarations hold more than " + std::to_string(kMaxDeclarationBytes / (1024 * 1024)) +
                          " MiB of scope, wire and identifier names (too large a capture to decode)");
  }

  bool declare_var(size_t line, const std::vector<VcdToken>& args) {
    if (args.size() != 4 && args.size() != 5) {
      return fail(line, "$var needs a type, a width, an identifier and a name");
    }
    uint64_t width = 0;
    if (!parse_unsigned(args[1].text, 0, width) || width == 0 || width > 1'000'000) {
      return fail(line, "bad $var width " + quoted(args[1].text));
    }
    if (capture_.wires.size() >= kMaxWires) {
      return fail(line, "more than " + std::to_string(kMaxWires) + " wires (too wide a capture to decode)");
    }
    VcdWire wire;
    for (const std::string& scope : scopes_) wire.scope += (wire.scope.empty() ? "" : ".") + scope;
    wire.width = static_cast<int>(width);
    wire.id = args[2].text;
    wire.name = args[3].text;
    if (args.size() == 5) wire.name += args[4].text;
    if (!spend(line, wire.scope.size() + wire.id.size() + wire.name.size())) return false;
    if (capture_.wires.size() == kWiresBeforeReserving) {
      // A wide capture: room for the most wires allowed, so the tables never grow by copying
      // (which holds the old and the new table at once); untouched, the room costs no memory.
      capture_.wires.reserve(kMaxWires);
      next_with_id_.reserve(kMaxWires);
      levels_.reserve(kMaxWires);
    }
    const uint32_t index = static_cast<uint32_t>(capture_.wires.size());
    const auto [first, inserted] = first_of_id_.try_emplace(wire.id, index);
    next_with_id_.push_back(kNoWire);
    if (!inserted) {  // several vars share this identifier: chain them
      uint32_t last = first->second;
      while (next_with_id_[last] != kNoWire) last = next_with_id_[last];
      next_with_id_[last] = index;
    }
    capture_.wires.push_back(std::move(wire));
    levels_.push_back(0);
    return true;
  }

  /// Tells the listener every 1-bit wire's level at the end of the first timestamp.
  void report_initial_levels() {
    initial_reported_ = true;
    for (size_t index = 0; index < capture_.wires.size(); ++index) {
      if (capture_.wires[index].width == 1) listener_->on_initial_level(index, levels_[index] != 0);
    }
  }

  /// Applies a new level of identifier `id` at the current time (kNoLevel: a real value, only
  /// the identifier is checked).
  bool apply(size_t line, const std::string& id, int level) {
    const auto found = first_of_id_.find(id);
    if (found == first_of_id_.end()) return fail(line, "value change for undeclared identifier " + quoted(id));
    const bool initial = !have_time_ || current_ns_ == capture_.start_time;
    for (uint32_t index = found->second; index != kNoWire; index = next_with_id_[index]) {
      if (capture_.wires[index].width != 1 || level == kNoLevel) continue;  // vectors and reals are not recorded
      const uint8_t high = level == 1 ? 1 : 0;
      if (!initial && high != levels_[index]) listener_->on_edge(index, current_ns_, high != 0);
      levels_[index] = high;
    }
    return true;
  }

  bool set_time(const VcdToken& token) {
    uint64_t units = 0;
    if (!parse_unsigned(token.text, 1, units)) return fail(token.line, "bad timestamp " + quoted(token.text));
    SimTime ns = 0;
    const SimTime fs = capture_.timescale_fs;
    if (fs >= kFemtosecondsPerNs) {
      const uint64_t multiplier = static_cast<uint64_t>(fs / kFemtosecondsPerNs);
      if (units > static_cast<uint64_t>(std::numeric_limits<SimTime>::max()) / multiplier) {
        return fail(token.line, "timestamp " + quoted(token.text) + " overflows 64-bit nanoseconds");
      }
      ns = static_cast<SimTime>(units * multiplier);
    } else {
      const uint64_t divisor = static_cast<uint64_t>(kFemtosecondsPerNs / fs);
      const uint64_t rounded = units / divisor + (units % divisor * 2 >= divisor ? 1 : 0);
      if (rounded > static_cast<uint64_t>(std::numeric_limits<SimTime>::max())) {
        return fail(token.line, "timestamp " + quoted(token.text) + " overflows 64-bit nanoseconds");
      }
      ns = static_cast<SimTime>(rounded);
    }
    if (!have_time_) {
      have_time_ = true;
      capture_.start_time = ns;
    } else if (ns < current_ns_) {
      return fail(token.line, "time goes backwards (" + token.text + " after #" + std::to_string(last_units_) + ")");
    } else if (ns > capture_.start_time && !initial_reported_) {
      report_initial_levels();  // the first timestamp is over: its values are the initial levels
    }
    current_ns_ = ns;
    last_units_ = units;
    capture_.end_time = ns;
    return true;
  }

  static bool is_scalar_value(char c) { return c == '0' || c == '1' || c == 'x' || c == 'X' || c == 'z' || c == 'Z'; }

  bool read_values() {
    VcdToken token;
    bool in_dump_block = false;
    for (;;) {
      if (!tokens_.next(token)) {
        if (tokens_.too_long()) return fail_at_end("");
        break;
      }
      if (token.cut) break;  // a possibly cut value change is not applied
      const std::string& text = token.text;
      const char first = text[0];
      if (first == '#') {
        if (!set_time(token)) return false;
      } else if (is_scalar_value(first)) {
        if (text.size() < 2) return fail(token.line, "value " + quoted(text) + " has no identifier");
        if (!apply(token.line, text.substr(1), first == '1' ? 1 : 0)) return false;
      } else if (first == 'b' || first == 'B' || first == 'r' || first == 'R') {
        if (!read_vector(token)) return false;
      } else if (text == "$dumpvars" || text == "$dumpall" || text == "$dumpon" || text == "$dumpoff") {
        if (in_dump_block) return fail(token.line, text + " inside another dump block");
        in_dump_block = true;
      } else if (text == "$end") {
        if (!in_dump_block) return fail(token.line, "$end without an open command");
        in_dump_block = false;
      } else if (text == "$comment") {
        if (!skip_text(text, token.line)) return false;
      } else {
        return fail(token.line, "unexpected " + quoted(text) + " in value changes");
      }
    }
    dump_block_open_ = in_dump_block;  // a file cut inside $dumpvars: truncated, not wrong
    return true;
  }

  bool read_vector(const VcdToken& value) {
    const std::string& text = value.text;
    const bool real = text[0] == 'r' || text[0] == 'R';
    if (text.size() < 2) return fail(value.line, "empty vector value " + quoted(text));
    if (!real) {
      for (size_t i = 1; i < text.size(); ++i) {
        if (!is_scalar_value(text[i])) return fail(value.line, "bad binary value " + quoted(text));
      }
    }
    VcdToken id;
    if (!tokens_.next(id)) return fail_at_end("unexpected end of file: value " + quoted(text) + " has no identifier");
    if (id.cut) return true;  // the identifier may be cut: the value is not applied
    if (real) return apply(id.line, id.text, kNoLevel);
    return apply(id.line, id.text, text.back() == '1' ? 1 : 0);
  }

  static constexpr uint32_t kNoWire = UINT32_MAX;
  /// The most words a declaration command holds before its $end ($var has at most five; a
  /// $timescale three), so the words of one command are never an unbounded list.
  static constexpr size_t kMaxCommandWords = 16;
  /// Captures up to this many wires grow their tables as usual (a few KiB).
  static constexpr size_t kWiresBeforeReserving = 4096;
  /// What an open scope costs beyond its name (its string in scopes_).
  static constexpr size_t kScopeOverheadBytes = sizeof(std::string);

  std::istream& in_;
  VcdTokenizer tokens_;
  std::string name_;
  std::string error_;
  bool ok_ = false;
  VcdCapture capture_;
  std::vector<std::string> scopes_;
  size_t declaration_bytes_ = 0;
  /// Identifier → its first wire; further wires of the same identifier follow next_with_id_.
  std::unordered_map<std::string, uint32_t> first_of_id_;
  std::vector<uint32_t> next_with_id_;
  std::vector<uint8_t> levels_;  ///< each 1-bit wire's level now
  VcdValueListener* listener_ = nullptr;
  bool initial_reported_ = false;
  bool have_time_ = false;
  bool dump_block_open_ = false;
  SimTime current_ns_ = 0;
  uint64_t last_units_ = 0;
};

VcdStreamReader::VcdStreamReader(std::istream& in, std::string name)
    : parser_(std::make_unique<Parser>(in, std::move(name))) {}

VcdStreamReader::~VcdStreamReader() = default;

bool VcdStreamReader::read_declarations() { return parser_->declarations_done(); }

const VcdCapture& VcdStreamReader::declarations() const { return parser_->capture(); }

bool VcdStreamReader::read_values(VcdValueListener& listener) { return parser_->values_done(listener); }

VcdReadResult VcdStreamReader::take_result() { return parser_->take_result(); }

namespace {

/// Keeps every edge, as read_vcd promises.
class EdgeKeeper final : public VcdValueListener {
 public:
  explicit EdgeKeeper(std::vector<VcdWire> wires) : wires_(std::move(wires)) {}
  void on_initial_level(size_t wire, bool high) override { wires_[wire].initial = high; }
  void on_edge(size_t wire, SimTime time_ns, bool high) override { wires_[wire].edges.push_back(Edge{time_ns, high}); }
  std::vector<VcdWire>& wires() { return wires_; }

 private:
  std::vector<VcdWire> wires_;
};

}  // namespace

VcdReadResult read_vcd(std::istream& in, const std::string& name) {
  VcdStreamReader reader(in, name);
  if (!reader.read_declarations()) return reader.take_result();
  EdgeKeeper keeper(reader.declarations().wires);
  reader.read_values(keeper);
  VcdReadResult result = reader.take_result();
  if (result.ok) result.capture.wires = std::move(keeper.wires());
  return result;
}

VcdReadResult read_vcd_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    VcdReadResult result;
    result.error = path + ":0: cannot open";
    return result;
  }
  return read_vcd(in, path);
}

}  // namespace stepdance::sim
