// RequestRouter: id rewriting, the in-flight window, per-tab queues, timeouts.
#include "request_router.hpp"

#include <utility>

namespace stepdance::cli::serve {
namespace {

std::string to_text(const nlohmann::json& value) {
  return value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace

RequestRouter::RequestRouter(RouterLimits limits, ToBoard to_board, ToClient to_client)
    : limits_(limits), to_board_(std::move(to_board)), to_client_(std::move(to_client)) {}

void RequestRouter::add_client(ClientId client) { queues_[client]; }

void RequestRouter::remove_client(ClientId client) { queues_.erase(client); }

void RequestRouter::from_client(ClientId client, std::string_view text, Clock::time_point now) {
  auto queue = queues_.find(client);
  if (queue == queues_.end()) return;
  Waiting waiting;
  waiting.pending.client = client;
  waiting.request = nlohmann::json::parse(text, nullptr, false);
  nlohmann::json& request = waiting.request;
  if (request.is_object() && request.contains("id")) {
    waiting.pending.client_id = request["id"];
    waiting.pending.has_id = true;
  }
  if (text.size() > limits_.max_request_bytes) {
    ++counters_.refused;
    reply_error(waiting.pending, 14, "line too long");
    return;
  }
  if (!request.is_object()) {
    ++counters_.refused;
    reply_error(waiting.pending, 1, "malformed JSON");
    return;
  }
  if (!request.contains("name") || !request["name"].is_string()) {
    ++counters_.refused;
    reply_error(waiting.pending, 2, "no name");
    return;
  }
  if (queue->second.size() >= limits_.max_queued_per_client) {
    ++counters_.dropped;
    reply_error(waiting.pending, kBridgeQueueFull, "bridge queue full: request dropped");
    return;
  }
  queue->second.push_back(std::move(waiting));
  pump(now);
}

void RequestRouter::from_board(std::string_view line, Clock::time_point now) {
  if (line.empty()) return;
  nlohmann::json reply = nlohmann::json::parse(line, nullptr, false);
  const bool is_reply = reply.is_object() && reply.contains("result");
  auto answered = in_flight_.end();
  if (is_reply && reply.contains("id") && reply["id"].is_number_unsigned()) {
    answered = in_flight_.find(reply["id"].get<uint64_t>());
  } else if (is_reply && !reply.contains("id") && !in_flight_.empty()) {
    answered = in_flight_.begin();  // the board answers in order; a reply without id is the oldest's
  }
  if (answered == in_flight_.end()) {
    ++counters_.board_lines;
    broadcast(reply.is_object() ? to_text(reply) : to_text(nlohmann::json{{"console", std::string(line)}}));
    return;
  }
  const Pending pending = answered->second.pending;
  in_flight_.erase(answered);
  ++counters_.replied;
  deliver(pending, std::move(reply));
  pump(now);
}

void RequestRouter::expire(Clock::time_point now) {
  for (auto it = in_flight_.begin(); it != in_flight_.end();) {
    if (now - it->second.sent < limits_.reply_timeout) {
      ++it;
      continue;
    }
    ++counters_.timed_out;
    reply_error(it->second.pending, kBridgeNoReply, "no reply from the board");
    it = in_flight_.erase(it);
  }
  pump(now);
}

void RequestRouter::pump(Clock::time_point now) {
  Waiting waiting;
  while (in_flight_.size() < limits_.max_in_flight && next_waiting(waiting)) {
    const uint64_t bridge_id = next_bridge_id_++;
    waiting.request["id"] = bridge_id;
    std::string line = to_text(waiting.request);
    if (line.size() > limits_.max_request_bytes) {  // the longer id pushed it over
      ++counters_.refused;
      reply_error(waiting.pending, 14, "line too long");
      continue;
    }
    in_flight_.emplace(bridge_id, InFlight{waiting.pending, now});
    ++counters_.forwarded;
    to_board_(line + "\n");
  }
}

bool RequestRouter::next_waiting(Waiting& out) {
  // Round robin: the first non-empty queue after the client served last, wrapping around.
  auto start = queues_.upper_bound(round_robin_after_);
  for (int pass = 0; pass < 2; ++pass) {
    for (auto it = pass == 0 ? start : queues_.begin(); it != (pass == 0 ? queues_.end() : start); ++it) {
      if (it->second.empty()) continue;
      out = std::move(it->second.front());
      it->second.pop_front();
      round_robin_after_ = it->first;
      return true;
    }
  }
  return false;
}

void RequestRouter::reply_error(const Pending& to, int code, const char* message) {
  deliver(to, nlohmann::json{{"result", "error"}, {"error", message}, {"code", code}});
}

void RequestRouter::deliver(const Pending& to, nlohmann::json reply) {
  if (queues_.count(to.client) == 0) return;  // the tab has gone
  if (reply.is_object()) {
    reply.erase("id");
    if (to.has_id) reply["id"] = to.client_id;
  }
  to_client_(to.client, to_text(reply));
}

void RequestRouter::broadcast(const std::string& message) {
  for (const auto& [client, queue] : queues_) to_client_(client, message);
}

}  // namespace stepdance::cli::serve
