// [[host]]: scripted host clients on boards' USB serial ports (send, stream, wait, pause).
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scenario/file_names.hpp"
#include "scenario/line_pattern.hpp"
#include "scenario/parse_context.hpp"

namespace stepdance::sim::scenario {

namespace {

/// Longest timeout or pause accepted, seconds (a day: far beyond any run).
constexpr double kMaxStepSeconds = 86400;
constexpr int64_t kMaxBufferBytes = 1 << 20;
/// Grbl's acknowledgement lines.
constexpr const char* kDefaultAck = "^(ok|error:[0-9]+)$";

/// The step kinds and the keys that belong to each.
constexpr const char* kKinds[] = {"send", "stream", "stream_file", "wait", "pause_s"};
constexpr std::pair<const char*, const char*> kStepKeys[] = {
    {"flow", "stream"},         {"buffer_bytes", "stream"},         {"ack", "stream"}, {"timeout_s", "stream or wait"},
    {"poll", "stream or wait"}, {"poll_every_s", "stream or wait"},
};

/// Polling: at most once per simulated millisecond (a USB frame), so a tiny interval cannot stall the run.
constexpr double kMinPollSeconds = 0.001;

std::optional<SimTime> read_seconds(TableReader& reader, const char* key, bool allow_zero, double low = 0) {
  const auto seconds = reader.number(key, NumberRange{low, kMaxStepSeconds, !allow_zero, "s"});
  if (!seconds) return std::nullopt;
  return from_seconds(*seconds);
}

bool read_pattern(TableReader& reader, const char* key, std::string& out) {
  const auto text = reader.string(key);
  if (!text) return false;
  const std::string problem = pattern_problem(*text);
  if (!problem.empty()) {
    reader.error(key, "'" + std::string(key) + "' " + problem);
    return false;
  }
  out = *text;
  return true;
}

bool read_file_text(TableReader& reader, const char* key, const ParseContext& context, std::string& out) {
  const auto name = reader.string(key);
  if (!name) return false;
  const std::string path = context.resolve(*name);
  std::error_code error;
  std::ifstream in;
  if (std::filesystem::is_regular_file(path, error)) in.open(path, std::ios::binary);
  if (!in) {
    reader.error(key, "file not found: " + path);
    return false;
  }
  std::ostringstream text;
  text << in.rdbuf();
  out = text.str();
  return true;
}

bool read_stream_options(TableReader& reader, HostStep& step) {
  bool ok = true;
  if (const auto flow = reader.string("flow")) {
    if (*flow == "ack") {
      step.flow = HostStep::Flow::kAck;
    } else if (*flow == "character_counting") {
      step.flow = HostStep::Flow::kCharacterCounting;
    } else {
      reader.error("flow", "'flow' must be \"ack\" or \"character_counting\", got \"" + *flow + "\"");
      ok = false;
    }
  }
  if (reader.has("buffer_bytes")) {
    const auto bytes = reader.integer("buffer_bytes", IntegerRange{1, kMaxBufferBytes, "bytes"});
    if (bytes) step.buffer_bytes = *bytes;
    ok = ok && bytes.has_value();
  }
  step.pattern = kDefaultAck;
  if (reader.has("ack")) ok = read_pattern(reader, "ack", step.pattern) && ok;
  return ok;
}

/// The one step kind the table has, or null (reported) for none or two.
const char* choose_step_kind(TableReader& reader) {
  const char* kind = nullptr;
  for (const char* candidate : kKinds) {
    if (!reader.has(candidate)) continue;
    if (kind != nullptr) {
      reader.accept(kind);
      reader.accept(candidate);
      reader.error(candidate,
                   std::string("a step does one thing, but has both '") + kind + "' and '" + candidate + "'");
      return nullptr;
    }
    kind = candidate;
  }
  if (kind == nullptr) {
    reader.reporter().error(reader.line(), "a [[host.step]] needs one of send, stream, stream_file, wait or pause_s");
  }
  return kind;
}

bool is_stream(const std::string& kind) { return kind == "stream" || kind == "stream_file"; }

/// Reports the keys of kStepKeys that the step's kind does not take; false if there was one.
bool refuse_other_step_keys(TableReader& reader, const std::string& kind) {
  bool ok = true;
  for (const auto& [key, owner] : kStepKeys) {
    const std::string_view name(key);
    const bool for_wait = name == "timeout_s" || name == "poll" || name == "poll_every_s";
    const bool belongs = is_stream(kind) || (kind == "wait" && for_wait);
    if (!belongs && reader.has(key)) {
      reader.accept(key);
      reader.error(key, "'" + std::string(key) + "' only goes with " + owner);
      ok = false;
    }
  }
  return ok;
}

/// stream = "text" or stream_file = "path" (its text), then the stream's options.
bool read_stream_step(TableReader& reader, const std::string& kind, const ParseContext& context, HostStep& step) {
  step.kind = HostStep::Kind::kStream;
  bool ok = true;
  if (kind == "stream") {
    const auto text = reader.string("stream");
    ok = text.has_value();
    if (text) step.bytes = *text;
  } else {
    ok = read_file_text(reader, "stream_file", context, step.bytes);
    if (ok) step.file = context.resolve(*reader.string("stream_file"));
  }
  return read_stream_options(reader, step) && ok;
}

/// The key that names the step: what it sends, streams, waits for, or how long it pauses.
bool read_step_action(TableReader& reader, const std::string& kind, const ParseContext& context, HostStep& step) {
  if (kind == "send") {
    step.kind = HostStep::Kind::kSend;
    const auto text = reader.string("send");
    if (text) step.bytes = *text;
    return text.has_value();
  }
  if (is_stream(kind)) return read_stream_step(reader, kind, context, step);
  if (kind == "wait") {
    step.kind = HostStep::Kind::kWait;
    return read_pattern(reader, "wait", step.pattern);
  }
  step.kind = HostStep::Kind::kPause;
  const auto pause = read_seconds(reader, "pause_s", true);
  if (pause) step.pause = *pause;
  return pause.has_value();
}

/// poll, poll_every_s and timeout_s of a stream or wait step.
bool read_poll_and_timeout(TableReader& reader, HostStep& step) {
  bool ok = true;
  if (const auto poll = reader.string("poll")) step.poll = *poll;
  if (reader.has("poll_every_s")) {
    const auto every = read_seconds(reader, "poll_every_s", true, kMinPollSeconds);
    ok = every.has_value() && ok;
    if (every) step.poll_interval = *every;
  }
  if (reader.has("timeout_s")) {
    const auto timeout = read_seconds(reader, "timeout_s", false);
    ok = timeout.has_value() && ok;
    if (timeout) step.timeout = *timeout;
  }
  return ok;
}

std::optional<HostStep> read_step(const toml::table& table, const ParseContext& context) {
  TableReader reader(table, "[[host.step]]", context.reporter);
  HostStep step;
  step.line = reader.line();
  const char* chosen = choose_step_kind(reader);
  if (chosen == nullptr) {
    reader.finish();
    return std::nullopt;
  }
  const std::string kind(chosen);
  bool ok = refuse_other_step_keys(reader, kind);
  ok = read_step_action(reader, kind, context, step) && ok;
  if (is_stream(kind) || kind == "wait") ok = read_poll_and_timeout(reader, step) && ok;
  reader.finish();
  if (!ok) return std::nullopt;
  return step;
}

/// board: an existing board with no other [[host]].
bool read_host_board(TableReader& reader, const ParseContext& context, HostClientConfig& host) {
  const auto board = reader.string("board", Need::kRequired);
  if (!board) return false;
  host.board = *board;
  bool ok = true;
  if (context.scenario.board(*board) == nullptr) {
    reader.error("board", "unknown board '" + *board + "'");
    ok = false;
  }
  for (const HostClientConfig& other : context.scenario.hosts) {
    if (other.board == *board) {
      reader.error("board", "board '" + *board + "' already has a [[host]] (line " + std::to_string(other.line) + ")");
      ok = false;
    }
  }
  return ok;
}

/// start_s: within the run.
bool read_host_start(TableReader& reader, const ParseContext& context, HostClientConfig& host) {
  if (!reader.has("start_s")) return true;
  const auto start = read_seconds(reader, "start_s", true);
  if (!start) return false;
  host.start = *start;
  if (context.duration_valid && *start > context.scenario.duration) {
    reader.error("start_s", "'start_s' is after the end of the run (duration_s = " +
                                format_number(to_seconds(context.scenario.duration)) + ")");
    return false;
  }
  return true;
}

/// transcript: a file name inside the output folder.
bool read_transcript(TableReader& reader, const ParseContext& context, HostClientConfig& host) {
  const auto transcript = reader.string("transcript");
  if (!transcript) return true;
  if (transcript->empty()) {
    reader.error("transcript", "'transcript' must name a file");
    return false;
  }
  if (const std::string problem = inside_path_problem(*transcript); !problem.empty()) {
    reader.error("transcript", "'transcript' (\"" + *transcript + "\") " + problem);
    return false;
  }
  host.transcript =
      (std::filesystem::path(context.scenario.output.directory) / *transcript).lexically_normal().string();
  host.transcript_line = reader.line_of("transcript");
  return true;
}

void read_host(const toml::table& table, ParseContext& context) {
  TableReader reader(table, "[[host]]", context.reporter);
  HostClientConfig host;
  host.line = reader.line();
  bool ok = read_host_board(reader, context, host);
  ok = read_host_start(reader, context, host) && ok;
  ok = read_transcript(reader, context, host) && ok;
  for_each_table(reader, "step", [&](const toml::table& step_table) {
    if (auto step = read_step(step_table, context)) {
      host.steps.push_back(std::move(*step));
    } else {
      ok = false;
    }
  });
  if (ok && host.steps.empty()) {
    reader.reporter().error(reader.line(), "a [[host]] needs at least one [[host.step]]");
    ok = false;
  }
  reader.finish();
  if (ok) context.scenario.hosts.push_back(std::move(host));
}

}  // namespace

void read_hosts(TableReader& top, ParseContext& context) {
  for_each_table(top, "host", [&](const toml::table& table) { read_host(table, context); });
}

}  // namespace stepdance::sim::scenario
