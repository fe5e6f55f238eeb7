// The HTTP and WebSocket server of `stepdance serve` (Boost.Beast on one Asio event loop).
#pragma once

#include <stdint.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>

#include "origin_policy.hpp"
#include "request_router.hpp"

namespace stepdance::cli::serve {

class WebSocketSession;

/// What the server does with its clients' traffic.
struct WebServerHooks {
  std::function<void(ClientId)> connected;
  std::function<void(ClientId, std::string_view)> message;
  std::function<void(ClientId)> disconnected;
};

/// Serves the control page (GET /, /app.js, /style.css: files built into the program) and
/// WebSockets on /ws. Every request's Host header and every upgrade's Origin header is checked
/// (OriginPolicy); anything else gets 403, 404 or 405. At most kMaxClients WebSockets at once
/// (503 after). Each client's outgoing messages wait in a queue of kMaxQueuedMessages; beyond it
/// they are dropped and counted (dropped_messages()), so a client that does not read cannot grow
/// the server. Incoming messages over kMaxMessageBytes close that connection.
/// Context: the event loop's thread only.
class WebServer {
 public:
  static constexpr size_t kMaxClients = 32;
  static constexpr size_t kMaxQueuedMessages = 1024;
  static constexpr size_t kMaxMessageBytes = 64 * 1024;

  /// Listens on address:port (port 0: any free port, see port()). Throws std::runtime_error.
  WebServer(boost::asio::io_context& io, const std::string& address, uint16_t port,
            std::vector<std::string> allowed_origins, WebServerHooks hooks);
  ~WebServer();

  uint16_t port() const { return port_; }
  /// Queues a text message for one client (ignored if it has gone).
  void send(ClientId client, const std::string& message);
  /// Queues a text message for every client.
  void broadcast(const std::string& message);
  /// Stops accepting and closes every connection.
  void stop();
  uint64_t dropped_messages() const { return dropped_messages_; }
  uint64_t refused_connections() const { return refused_connections_; }

  // ---- for the sessions ----
  const OriginPolicy& policy() const { return policy_; }
  bool has_room() const { return clients_.size() < kMaxClients; }
  ClientId add_client(const std::shared_ptr<WebSocketSession>& session);
  void remove_client(ClientId client);
  void deliver(ClientId client, std::string_view message) { hooks_.message(client, message); }
  void count_refused() { ++refused_connections_; }
  void count_dropped() { ++dropped_messages_; }

 private:
  void accept();

  boost::asio::ip::tcp::acceptor acceptor_;
  uint16_t port_ = 0;
  OriginPolicy policy_;
  WebServerHooks hooks_;
  std::map<ClientId, std::weak_ptr<WebSocketSession>> clients_;
  ClientId next_client_ = 1;
  uint64_t dropped_messages_ = 0;
  uint64_t refused_connections_ = 0;
  bool stopped_ = false;
};

}  // namespace stepdance::cli::serve
