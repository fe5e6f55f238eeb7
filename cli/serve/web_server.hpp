// The HTTP and WebSocket server of `stepdance serve` (Boost.Beast on one Asio event loop).
#pragma once

#include <stdint.h>

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>

#include "origin_policy.hpp"
#include "request_router.hpp"
#include "web_assets.hpp"

namespace stepdance::cli::serve {

class WebSocketSession;

/// Held by every open connection (HTTP or WebSocket): counts it while it lives. The count is
/// shared, so a connection that outlives the server (its handler still queued on the event
/// loop) releases its place safely.
class ConnectionTicket {
 public:
  explicit ConnectionTicket(std::shared_ptr<size_t> open) : open_(std::move(open)) { ++*open_; }
  ~ConnectionTicket() { --*open_; }
  ConnectionTicket(const ConnectionTicket&) = delete;
  ConnectionTicket& operator=(const ConnectionTicket&) = delete;

 private:
  std::shared_ptr<size_t> open_;
};

/// What the server does with its clients' traffic.
struct WebServerHooks {
  std::function<void(ClientId)> connected;
  std::function<void(ClientId, std::string_view)> message;
  std::function<void(ClientId)> disconnected;
};

/// What a server serves, beyond its hooks: the page's files and the token its WebSocket needs.
struct WebServerContent {
  /// The file served at a path ("/" asks for "/index.html"), or null: the control page's files
  /// unless another page's are given (the live view's).
  const WebAsset* (*find_asset)(std::string_view path) = find_web_asset;
  /// When not empty, a WebSocket upgrade must carry `?token=<this>` in its URL (a secret of the
  /// run, handed out in the announced address), or it gets 403.
  std::string token;
};

/// Serves the control page (GET /, /app.js, /style.css: files built into the program) and
/// WebSockets on /ws. Every request's Host header and every upgrade's Origin header is checked
/// (OriginPolicy); anything else gets 403, 404 or 405. At most kMaxClients WebSockets at once
/// (503 after). Each client's outgoing messages wait in a queue of kMaxQueuedMessages; beyond it
/// they are dropped and counted (dropped_messages()), so a client that does not read cannot grow
/// the server. Incoming messages over kMaxMessageBytes close that connection.
///
/// Connections: at most kMaxConnections open at once, HTTP and WebSocket together; one beyond
/// is closed as soon as it is accepted (counted in refused_connections()). A request must arrive
/// whole within kRequestTimeout of the connection opening or of the previous response (keep-alive),
/// so half-open connections free their place quickly. When accepting fails (the process is out
/// of file descriptors, say) the server waits kAcceptRetryDelay before trying again instead of
/// spinning, and counts the failure (accept_failures()).
/// Context: the event loop's thread only.
class WebServer {
 public:
  static constexpr size_t kMaxClients = 32;
  static constexpr size_t kMaxQueuedMessages = 1024;
  static constexpr size_t kMaxMessageBytes = 64 * 1024;
  static constexpr size_t kMaxConnections = 64;
  static constexpr std::chrono::seconds kRequestTimeout{5};
  static constexpr std::chrono::milliseconds kAcceptRetryDelay{100};

  /// Listens on address:port (port 0: any free port, see port()). Throws std::runtime_error.
  WebServer(boost::asio::io_context& io, const std::string& address, uint16_t port,
            std::vector<std::string> allowed_origins, WebServerHooks hooks, WebServerContent content = {});
  ~WebServer();

  uint16_t port() const { return port_; }
  /// Queues a text message for one client (ignored if it has gone).
  void send(ClientId client, const std::string& message);
  /// Messages waiting to go to `client` (the one being written included; 0 if it has gone).
  /// A sender that makes its next message only at 0 never loses one to kMaxQueuedMessages:
  /// the page's socket holds it back (back-pressure).
  size_t queued_messages(ClientId client) const;
  /// Queues a text message for every client.
  void broadcast(const std::string& message);
  /// Stops accepting and closes every connection.
  void stop();
  uint64_t dropped_messages() const { return dropped_messages_; }
  uint64_t refused_connections() const { return refused_connections_; }
  uint64_t accept_failures() const { return accept_failures_; }
  /// Connections open now (HTTP and WebSocket).
  size_t open_connections() const { return *open_connections_; }

  // ---- for the sessions ----
  const OriginPolicy& policy() const { return policy_; }
  const WebServerContent& content() const { return content_; }
  /// Whether an upgrade's target ("/ws?token=…") carries the token (always, without one).
  bool token_allowed(std::string_view target) const;
  bool has_room() const { return clients_.size() < kMaxClients; }
  ClientId add_client(const std::shared_ptr<WebSocketSession>& session);
  /// A place for one more connection, or null when kMaxConnections are open.
  std::unique_ptr<ConnectionTicket> take_ticket();
  void remove_client(ClientId client);
  void deliver(ClientId client, std::string_view message) { hooks_.message(client, message); }
  void count_refused() { ++refused_connections_; }
  void count_dropped() { ++dropped_messages_; }

 private:
  void accept();
  void on_accept(const boost::system::error_code& error, boost::asio::ip::tcp::socket socket);

  boost::asio::ip::tcp::acceptor acceptor_;
  boost::asio::steady_timer retry_timer_;
  std::shared_ptr<size_t> open_connections_ = std::make_shared<size_t>(0);
  uint64_t accept_failures_ = 0;
  uint16_t port_ = 0;
  OriginPolicy policy_;
  WebServerHooks hooks_;
  WebServerContent content_;
  std::map<ClientId, std::weak_ptr<WebSocketSession>> clients_;
  ClientId next_client_ = 1;
  uint64_t dropped_messages_ = 0;
  uint64_t refused_connections_ = 0;
  bool stopped_ = false;
};

}  // namespace stepdance::cli::serve
