// VCD reader: a whitespace tokenizer, the declaration section, then value changes into edge lists.
#include "decode/vcd_reader.hpp"

#include <charconv>
#include <cstdint>
#include <fstream>
#include <istream>
#include <limits>
#include <unordered_map>
#include <utility>

namespace stepdance::sim {
namespace {

constexpr SimTime kFemtosecondsPerNs = 1'000'000;
/// Passed instead of 0/1 for a value that has no logic level (a real).
constexpr int kNoLevel = -1;

struct Token {
  std::string text;
  size_t line = 0;
  bool cut = false;  ///< the last token of a file that ends without a newline: maybe a fragment
};

/// Splits a stream into whitespace-separated tokens, remembering each token's line (1-based).
/// A last line without its newline is where a cut file ends: its last token may be a fragment
/// ("#12" of "#1234"), so it is marked `cut` and the file counts as truncated.
class Tokenizer {
 public:
  explicit Tokenizer(std::istream& in) : in_(in) {}

  bool next(Token& token) {
    for (;;) {
      while (pos_ < line_.size() && is_space(line_[pos_])) ++pos_;
      if (pos_ < line_.size()) {
        const size_t start = pos_;
        while (pos_ < line_.size() && !is_space(line_[pos_])) ++pos_;
        token.text.assign(line_, start, pos_ - start);
        token.line = line_number_;
        token.cut = cut_ && pos_ == line_.size();
        return true;
      }
      if (!std::getline(in_, line_)) return false;
      ++line_number_;
      pos_ = 0;
      if (in_.eof() && !line_.empty()) {
        cut_ = true;
        cut_line_ = line_number_;
      }
    }
  }

  /// Whether the file ended in the middle of a line.
  bool cut() const { return cut_; }
  /// The line the file was cut in (valid when cut()).
  size_t cut_line() const { return cut_line_; }

  /// Drops the rest of the current line.
  void skip_line() { pos_ = line_.size(); }

  /// The number of the last line read (the line an end-of-file error points at).
  size_t line() const { return line_number_ == 0 ? 1 : line_number_; }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

  std::istream& in_;
  std::string line_;
  size_t pos_ = 0;
  size_t line_number_ = 0;
  bool cut_ = false;
  size_t cut_line_ = 0;
};

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
  if (number == "1") multiplier = 1;
  else if (number == "10") multiplier = 10;
  else if (number == "100") multiplier = 100;
  else return false;
  static const std::pair<const char*, SimTime> kUnits[] = {
      {"s", 1'000'000'000'000'000}, {"ms", 1'000'000'000'000}, {"us", 1'000'000'000},
      {"ns", 1'000'000},            {"ps", 1'000},             {"fs", 1}};
  for (const auto& [name, fs] : kUnits) {
    if (unit == name) {
      femtoseconds = multiplier * fs;
      return true;
    }
  }
  return false;
}

class Parser {
 public:
  Parser(std::istream& in, std::string name) : tokens_(in), name_(std::move(name)) {}

  VcdReadResult run() {
    VcdReadResult result;
    if (read_declarations() && read_values()) {
      result.ok = true;
      result.capture = std::move(capture_);
      if (tokens_.cut() || dump_block_open_) {
        result.truncated = true;
        result.warning = name_ + ":" + std::to_string(tokens_.line()) + ": the capture is truncated (" +
                         (tokens_.cut() ? "it ends in the middle of line " + std::to_string(tokens_.cut_line())
                                        : std::string("a dump block has no $end")) +
                         "); decoded up to there";
      }
    } else {
      result.error = std::move(error_);
    }
    return result;
  }

 private:
  struct WireState {
    bool level = false;
  };

  bool fail(size_t line, const std::string& message) {
    error_ = name_ + ":" + std::to_string(line) + ": " + message;
    return false;
  }

  /// Reads the tokens of a command up to its `$end` into `args`.
  bool read_until_end(const std::string& command, size_t line, std::vector<Token>& args) {
    args.clear();
    Token token;
    while (tokens_.next(token)) {
      if (token.text == "$end") return true;
      if (token.text.size() > 1 && token.text[0] == '$') {
        return fail(token.line, "missing $end of " + command + " (from line " + std::to_string(line) +
                                    "), found " + quoted(token.text));
      }
      args.push_back(token);
    }
    return fail(tokens_.line(), "unexpected end of file: missing $end of " + command + " (from line " +
                                    std::to_string(line) + ")");
  }

  /// Skips a free-text command (comment, date, version) up to `$end`, which may not be nested.
  bool skip_text(const std::string& command, size_t line) {
    Token token;
    while (tokens_.next(token)) {
      if (token.text == "$end") return true;
    }
    return fail(tokens_.line(), "unexpected end of file: missing $end of " + command + " (from line " +
                                    std::to_string(line) + ")");
  }

  static bool is_text_command(const std::string& command) {
    return command == "$comment" || command == "$date" || command == "$version";
  }

  bool read_declarations() {
    Token token;
    std::vector<Token> args;
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
        for (const Token& arg : args) joined += arg.text;
        if (!parse_timescale(joined, capture_.timescale_fs)) {
          return fail(line, "bad $timescale " + quoted(joined) + " (expected 1, 10 or 100 and s, ms, us, ns, ps or fs)");
        }
      } else if (command == "$scope") {
        if (args.size() != 2) return fail(line, "$scope needs a type and a name");
        scopes_.push_back(args[1].text);
      } else if (command == "$upscope") {
        if (!args.empty()) return fail(line, "$upscope takes no arguments");
        if (scopes_.empty()) return fail(line, "$upscope without an open $scope");
        scopes_.pop_back();
      } else if (command == "$var") {
        if (!declare_var(line, args)) return false;
      }
      // Other declaration commands ($attrbegin, $timezero, …) carry nothing we need.
    }
    return fail(tokens_.line(), "unexpected end of file: missing $enddefinitions");
  }

  bool declare_var(size_t line, const std::vector<Token>& args) {
    if (args.size() != 4 && args.size() != 5) {
      return fail(line, "$var needs a type, a width, an identifier and a name");
    }
    uint64_t width = 0;
    if (!parse_unsigned(args[1].text, 0, width) || width == 0 || width > 1'000'000) {
      return fail(line, "bad $var width " + quoted(args[1].text));
    }
    VcdWire wire;
    for (const std::string& scope : scopes_) wire.scope += (wire.scope.empty() ? "" : ".") + scope;
    wire.width = static_cast<int>(width);
    wire.id = args[2].text;
    wire.name = args[3].text;
    if (args.size() == 5) wire.name += args[4].text;
    ids_[wire.id].push_back(capture_.wires.size());
    capture_.wires.push_back(std::move(wire));
    levels_.emplace_back();
    return true;
  }

  /// Applies a new level of identifier `id` at the current time (kNoLevel: a real value, only
  /// the identifier is checked).
  bool apply(size_t line, const std::string& id, int level) {
    const auto found = ids_.find(id);
    if (found == ids_.end()) return fail(line, "value change for undeclared identifier " + quoted(id));
    const bool initial = !have_time_ || current_ns_ == capture_.start_time;
    for (size_t index : found->second) {
      VcdWire& wire = capture_.wires[index];
      if (wire.width != 1 || level == kNoLevel) continue;  // vectors and reals are not recorded
      bool& current = levels_[index].level;
      const bool high = level == 1;
      if (initial) {
        wire.initial = high;
      } else if (high != current) {
        wire.edges.push_back(Edge{current_ns_, high});
      }
      current = high;
    }
    return true;
  }

  bool set_time(const Token& token) {
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
    }
    current_ns_ = ns;
    last_units_ = units;
    capture_.end_time = ns;
    return true;
  }

  static bool is_scalar_value(char c) {
    return c == '0' || c == '1' || c == 'x' || c == 'X' || c == 'z' || c == 'Z';
  }

  bool read_values() {
    Token token;
    bool in_dump_block = false;
    while (tokens_.next(token)) {
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

  bool read_vector(const Token& value) {
    const std::string& text = value.text;
    const bool real = text[0] == 'r' || text[0] == 'R';
    if (text.size() < 2) return fail(value.line, "empty vector value " + quoted(text));
    if (!real) {
      for (size_t i = 1; i < text.size(); ++i) {
        if (!is_scalar_value(text[i])) return fail(value.line, "bad binary value " + quoted(text));
      }
    }
    Token id;
    if (!tokens_.next(id)) return fail(tokens_.line(), "unexpected end of file: value " + quoted(text) + " has no identifier");
    if (id.cut) return true;  // the identifier may be cut: the value is not applied
    if (real) return apply(id.line, id.text, kNoLevel);
    return apply(id.line, id.text, text.back() == '1' ? 1 : 0);
  }

  Tokenizer tokens_;
  std::string name_;
  std::string error_;
  VcdCapture capture_;
  std::vector<std::string> scopes_;
  std::unordered_map<std::string, std::vector<size_t>> ids_;
  std::vector<WireState> levels_;
  bool have_time_ = false;
  bool dump_block_open_ = false;
  SimTime current_ns_ = 0;
  uint64_t last_units_ = 0;
};

}  // namespace

VcdReadResult read_vcd(std::istream& in, const std::string& name) {
  Parser parser(in, name);
  VcdReadResult result = parser.run();
  if (result.ok && in.bad()) {
    result.ok = false;
    result.error = name + ":0: read error";
  }
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
