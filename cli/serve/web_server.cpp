// WebServer: the listening socket and the client registry.
#include "web_server.hpp"

#include <stdexcept>

#include "web_sessions.hpp"

namespace stepdance::cli::serve {

namespace net = boost::asio;
using tcp = net::ip::tcp;

WebServer::WebServer(net::io_context& io, const std::string& address, uint16_t port,
                     std::vector<std::string> allowed_origins, WebServerHooks hooks, WebServerContent content)
    : acceptor_(io),
      retry_timer_(io),
      policy_(address, port, std::move(allowed_origins)),
      hooks_(std::move(hooks)),
      content_(std::move(content)) {
  boost::system::error_code error;
  const net::ip::address ip = net::ip::make_address(address, error);
  if (error) throw std::runtime_error("--host: '" + address + "' is not an IP address");
  const tcp::endpoint endpoint(ip, port);
  acceptor_.open(endpoint.protocol(), error);
  if (!error) acceptor_.set_option(net::socket_base::reuse_address(true), error);
  if (!error) acceptor_.bind(endpoint, error);
  if (!error) acceptor_.listen(net::socket_base::max_listen_connections, error);
  if (error)
    throw std::runtime_error("cannot listen on " + address + ":" + std::to_string(port) + ": " + error.message());
  port_ = acceptor_.local_endpoint().port();
  policy_.set_port(port_);
  accept();
}

WebServer::~WebServer() = default;

bool WebServer::token_allowed(std::string_view target) const {
  if (content_.token.empty()) return true;
  const size_t query = target.find('?');
  if (query == std::string_view::npos) return false;
  std::string_view rest = target.substr(query + 1);
  while (!rest.empty()) {
    const size_t end = rest.find('&');
    if (rest.substr(0, end) == "token=" + content_.token) return true;
    if (end == std::string_view::npos) break;
    rest = rest.substr(end + 1);
  }
  return false;
}

void WebServer::accept() {
  acceptor_.async_accept(
      [this](boost::system::error_code error, tcp::socket socket) { on_accept(error, std::move(socket)); });
}

void WebServer::on_accept(const boost::system::error_code& error, tcp::socket socket) {
  if (stopped_) return;
  if (error) {
    // Out of descriptors (EMFILE) and the like: the connection stays queued in the kernel and
    // the listening socket stays readable, so accepting again at once would spin. Wait instead.
    ++accept_failures_;
    retry_timer_.expires_after(kAcceptRetryDelay);
    retry_timer_.async_wait([this](const boost::system::error_code& cancelled) {
      if (!cancelled && !stopped_) accept();
    });
    return;
  }
  if (auto ticket = take_ticket()) {
    std::make_shared<HttpSession>(std::move(socket), *this, std::move(ticket))->run();
  } else {
    ++refused_connections_;
    boost::system::error_code ignored;
    socket.close(ignored);  // full: its descriptor is given back at once
  }
  accept();
}

std::unique_ptr<ConnectionTicket> WebServer::take_ticket() {
  if (*open_connections_ >= kMaxConnections) return nullptr;
  return std::make_unique<ConnectionTicket>(open_connections_);
}

ClientId WebServer::add_client(const std::shared_ptr<WebSocketSession>& session) {
  const ClientId client = next_client_++;
  clients_[client] = session;
  if (hooks_.connected) hooks_.connected(client);
  return client;
}

void WebServer::remove_client(ClientId client) {
  if (clients_.erase(client) > 0 && hooks_.disconnected) hooks_.disconnected(client);
}

void WebServer::send(ClientId client, const std::string& message) {
  auto found = clients_.find(client);
  if (found == clients_.end()) return;
  if (auto session = found->second.lock()) session->send(message);
}

size_t WebServer::queued_messages(ClientId client) const {
  auto found = clients_.find(client);
  if (found == clients_.end()) return 0;
  auto session = found->second.lock();
  return session ? session->queued_messages() : 0;
}

void WebServer::broadcast(const std::string& message) {
  for (const auto& [client, weak] : clients_) {
    if (auto session = weak.lock()) session->send(message);
  }
}

void WebServer::stop() {
  stopped_ = true;
  boost::system::error_code ignored;
  retry_timer_.cancel();
  acceptor_.close(ignored);
  // A session's close() removes it from clients_ (remove_client): walk a copy.
  const auto clients = clients_;
  for (const auto& [client, weak] : clients) {
    if (auto session = weak.lock()) session->close();
  }
}

}  // namespace stepdance::cli::serve
