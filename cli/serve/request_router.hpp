// Pairs the browser tabs' RPC requests with the board's replies over one serial line.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <chrono>
#include <deque>
#include <functional>
#include <map>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace stepdance::cli::serve {

/// A connected client (a browser tab), numbered by the server.
using ClientId = uint64_t;
using Clock = std::chrono::steady_clock;

/// Bounds of the router; each one, when reached, is answered and counted, never waited on.
struct RouterLimits {
  /// Requests a client may have waiting for the serial line; more get "bridge queue full".
  size_t max_queued_per_client = 64;
  /// Requests sent to the board and not yet answered (the board reads a few lines per loop pass).
  size_t max_in_flight = 4;
  /// A request the board has not answered after this long gets "no reply from the board".
  std::chrono::milliseconds reply_timeout{3000};
  /// The board's line limit (RPC::kMaxLineBytes); longer requests are refused here.
  size_t max_request_bytes = 512;
};

/// What the router has done since it started (the page shows these).
struct RouterCounters {
  uint64_t forwarded = 0;    ///< requests sent to the board
  uint64_t replied = 0;      ///< board replies handed to the tab that asked
  uint64_t dropped = 0;      ///< requests refused: the tab's queue was full
  uint64_t refused = 0;      ///< requests refused: not JSON, no name, too long
  uint64_t timed_out = 0;    ///< requests the board did not answer in time
  uint64_t board_lines = 0;  ///< other lines from the board (events, the sketch's prints)
};

/// Error codes the bridge adds to the board's (RPC's 1–14).
enum BridgeError : int {
  kBridgeQueueFull = 20,
  kBridgeNoReply = 21,
};

/// The bridge's pairing logic, apart from any network code (so it can be tested alone).
///
/// A tab's request gets a fresh id of the bridge's own before it goes to the board; the tab's id
/// (any JSON value, or none) is kept and put back into the reply. So tabs may reuse each other's
/// ids. At most max_in_flight requests are on the line at once; the others wait in per-tab queues
/// served round robin, so a tab that floods fills only its own queue. Board lines that answer no
/// request — the sketch's prints, unsolicited events — go to every tab: JSON objects as they are,
/// other text as {"console": "<line>"}.
/// Context: one thread (the server's event loop).
class RequestRouter {
 public:
  using ToBoard = std::function<void(const std::string& line)>;
  using ToClient = std::function<void(ClientId client, const std::string& message)>;

  RequestRouter(RouterLimits limits, ToBoard to_board, ToClient to_client);

  void add_client(ClientId client);
  /// Forgets the tab: its waiting requests are dropped; replies still due to it are discarded.
  void remove_client(ClientId client);
  /// One WebSocket text message from a tab: a request object.
  void from_client(ClientId client, std::string_view text, Clock::time_point now);
  /// One line from the board, without its line ending.
  void from_board(std::string_view line, Clock::time_point now);
  /// Answers requests that have waited too long for the board. Call now and then.
  void expire(Clock::time_point now);

  const RouterCounters& counters() const { return counters_; }
  size_t clients() const { return queues_.size(); }
  size_t in_flight() const { return in_flight_.size(); }

 private:
  struct Pending {
    ClientId client = 0;
    nlohmann::json client_id;  ///< null with has_id false: the tab sent no id
    bool has_id = false;
  };
  struct Waiting {
    Pending pending;
    nlohmann::json request;
  };
  struct InFlight {
    Pending pending;
    Clock::time_point sent;
  };

  void reply_error(const Pending& to, int code, const char* message);
  void deliver(const Pending& to, nlohmann::json reply);
  void broadcast(const std::string& message);
  void pump(Clock::time_point now);
  bool next_waiting(Waiting& out);

  RouterLimits limits_;
  ToBoard to_board_;
  ToClient to_client_;
  std::map<ClientId, std::deque<Waiting>> queues_;
  std::map<uint64_t, InFlight> in_flight_;  ///< by the bridge's id, oldest first
  uint64_t next_bridge_id_ = 1;
  ClientId round_robin_after_ = 0;
  RouterCounters counters_;
};

}  // namespace stepdance::cli::serve
