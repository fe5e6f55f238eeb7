// Expectation kind "host": host = "board" with reply = "regex" (count, within_ms, after) or
// replies = ["regex", …] in order — the lines a host client received; or completed = true — the
// client ran all its steps without a timeout.
#include "kinds/expectations/host.hpp"

#include <algorithm>
#include <cstdio>

#include "kinds/expectations/expectation_parts.hpp"
#include "scenario/line_pattern.hpp"

namespace stepdance::sim {
namespace {

bool valid_pattern(scenario::TableReader& reader, const char* key, const std::string& pattern) {
  const std::string problem = scenario::pattern_problem(pattern);
  if (!problem.empty()) reader.error(key, "'" + std::string(key) + "' " + problem);
  return problem.empty();
}

/// completed = true, which takes none of the reply keys.
bool read_completed(scenario::TableReader& reader, HostCheck& check) {
  check.completed = true;
  const auto completed = reader.boolean("completed");
  bool ok = completed.has_value();
  if (completed && !*completed) {
    reader.error("completed", "'completed' can only be true");
    ok = false;
  }
  for (const char* other : {"reply", "replies", "count", "within_ms", "after"}) {
    if (!reader.has(other)) continue;
    reader.accept(other);
    reader.error(other, std::string("'") + other + "' does not go with 'completed'");
    ok = false;
  }
  return ok;
}

/// replies = a non-empty list of regexes; nullopt (reported) when an item is not a string.
std::optional<bool> read_reply_list(scenario::TableReader& reader, const toml::array& replies, HostCheck& check) {
  bool ok = true;
  for (const toml::node& item : replies) {
    const auto* text = item.as_string();
    if (text == nullptr) {
      reader.error("replies", "'replies' must be a list of strings");
      return std::nullopt;
    }
    ok = valid_pattern(reader, "replies", text->get()) && ok;
    check.replies.push_back(text->get());
  }
  if (check.replies.empty()) {
    reader.error("replies", "'replies' must not be empty");
    ok = false;
  }
  return ok;
}

/// Exactly one of reply = "regex" and replies = [...]: whether they are right, or nullopt
/// (reported) when the check's other keys cannot be read either.
std::optional<bool> read_replies(scenario::TableReader& reader, HostCheck& check) {
  if (reader.has("reply") == reader.has("replies")) {
    reader.reporter().error(reader.line(), "a 'host' check needs 'reply' (one regex) or 'replies' (regexes in order)");
    reader.accept("reply");
    reader.accept("replies");
    return std::nullopt;
  }
  if (const auto reply = reader.string("reply")) {
    check.replies.push_back(*reply);
    return valid_pattern(reader, "reply", *reply);
  }
  const toml::array* replies = reader.array("replies");
  if (replies == nullptr) return false;
  return read_reply_list(reader, *replies, check);
}

/// count (one reply only), within_ms, and after (with within_ms).
bool read_count_and_timing(scenario::TableReader& reader, HostCheck& check) {
  bool ok = true;
  if (const auto count = reader.integer("count")) {
    if (*count < 0 || check.replies.size() != 1) {
      reader.error("count", "'count' must be >= 0 and goes with a single 'reply'");
      ok = false;
    }
    check.count = *count;
  }
  if (reader.has("within_ms")) {
    const auto within =
        reader.number("within_ms", scenario::NumberRange{0, scenario::ranges::kTimeMs.high, true, "ms"});
    if (within) check.within = from_seconds(*within / 1e3);
    ok = ok && within.has_value();
  }
  if (const auto after = reader.string("after")) {
    ok = valid_pattern(reader, "after", *after) && ok;
    check.after = *after;
    if (!check.within) {
      reader.error("after", "'after' goes with 'within_ms'");
      ok = false;
    }
  }
  return ok;
}

bool read(ExpectationReading& reading) {
  scenario::TableReader& reader = reading.reader;
  const auto board = reader.string("host");
  if (!board) return false;
  HostCheck check;
  check.board = *board;
  const auto& hosts = reading.context.scenario.hosts;
  bool ok = std::any_of(hosts.begin(), hosts.end(),
                        [&](const scenario::HostClientConfig& host) { return host.board == *board; });
  if (!ok) reader.error("host", "no [[host]] client on board '" + *board + "'");
  if (reader.has("completed")) {
    ok = read_completed(reader, check) && ok;
  } else {
    const std::optional<bool> replies_ok = read_replies(reader, check);
    if (!replies_ok.has_value()) return false;
    ok = read_count_and_timing(reader, check) && *replies_ok && ok;
  }
  reading.settings = check;
  return ok;
}

std::string quoted_list(const std::vector<std::string>& patterns) {
  std::string text;
  for (const std::string& pattern : patterns) text += (text.empty() ? "\"" : ", \"") + pattern + "\"";
  return text;
}

/// Replies matched in order, one after another.
ExpectationResult replies_in_order(const HostCheck& check, const std::vector<HostLine>& transcript,
                                   const std::string& what) {
  std::vector<scenario::LinePattern> patterns;
  for (const std::string& reply : check.replies) patterns.emplace_back(reply);
  size_t next = 0;
  for (const HostLine& line : transcript) {
    if (!line.from_host && next < patterns.size() && patterns[next].found_in(line.text)) ++next;
  }
  return {next == check.replies.size(),
          what + " in order: matched " + std::to_string(next) + " of " + std::to_string(check.replies.size())};
}

/// Timed: from the first sent line matching `after` (or the client's first line) to the reply.
ExpectationResult reply_in_time(const HostCheck& check, const std::vector<HostLine>& transcript,
                                const std::string& what) {
  const scenario::LinePattern reply(check.replies[0]);
  const scenario::LinePattern after(check.after.empty() ? std::string(".*") : check.after);
  std::optional<SimTime> from;
  for (const HostLine& entry : transcript) {
    if (!from && entry.from_host && after.found_in(entry.text)) from = entry.time;
    if (from && !entry.from_host && reply.found_in(entry.text)) {
      const SimTime took = entry.time - *from;
      char text[64];
      std::snprintf(text, sizeof text, " within %.3f ms: took %.3f ms", to_seconds(*check.within) * 1e3,
                    to_seconds(took) * 1e3);
      return {took <= *check.within, what + text};
    }
  }
  return {false, what + ": no such reply" + (from ? "" : " (nothing sent matched 'after')")};
}

/// Replies in order; or one reply (count, within_ms after a sent line).
ExpectationResult check_replies(const HostCheck& check, const std::vector<HostLine>& transcript) {
  const std::string what = "host " + check.board + " received " + quoted_list(check.replies);
  if (check.replies.size() > 1) return replies_in_order(check, transcript, what);
  if (check.within && !check.count) return reply_in_time(check, transcript, what);
  const scenario::LinePattern reply(check.replies[0]);
  int64_t matches = 0;
  for (const HostLine& line : transcript) matches += !line.from_host && reply.found_in(line.text) ? 1 : 0;
  if (check.count) return compare(what + " (lines)", *check.count, matches);
  return {matches > 0, what + ": " + std::to_string(matches) + " matching lines"};
}

ExpectationResult check(const scenario::Expectation& expectation, const FinishedRun& run) {
  const auto& check = settings_of<HostCheck>(expectation);
  const std::optional<HostOutcome> client = run.host(check.board);
  if (!client) return {false, "host " + check.board + ": no client"};
  if (!check.completed) return check_replies(check, *client->transcript);
  if (client->completed) return {true, "host " + check.board + " ran every step"};
  return {false,
          client->failure.empty() ? "host " + check.board + " was still running when the run ended" : client->failure};
}

}  // namespace

const ExpectationKind& host_expectation() {
  static const ExpectationKind kind{
      "host", {"reply", "replies", "count", "within_ms", "after", "completed"}, read, check};
  return kind;
}

}  // namespace stepdance::sim
