// HttpSession and WebSocketSession: Beast's asynchronous reads and writes, one of each at a time.
#include "web_sessions.hpp"

#include <chrono>

#include "web_assets.hpp"

namespace stepdance::cli::serve {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;

namespace {

constexpr size_t kMaxRequestBodyBytes = 4096;

/// Boost 1.74's Beast has its own string_view.
std::string_view text_of(beast::string_view text) { return {text.data(), text.size()}; }

}  // namespace

// ---- HTTP ---------------------------------------------------------------------------------------

HttpSession::HttpSession(boost::asio::ip::tcp::socket socket, WebServer& server,
                         std::unique_ptr<ConnectionTicket> ticket)
    : stream_(std::move(socket)), server_(server), ticket_(std::move(ticket)) {}

void HttpSession::read() {
  parser_.emplace();
  parser_->body_limit(kMaxRequestBodyBytes);
  stream_.expires_after(WebServer::kRequestTimeout);
  http::async_read(stream_, buffer_, *parser_, [self = shared_from_this()](beast::error_code error, size_t) {
    if (error) {
      self->stream_.socket().shutdown(boost::asio::ip::tcp::socket::shutdown_both, error);
      return;
    }
    self->on_request(self->parser_->release());
  });
}

void HttpSession::on_request(Request request) {
  const std::string host(text_of(request[http::field::host]));
  if (websocket::is_upgrade(request)) {
    const std::string_view target = text_of(request.target());
    if (target.substr(0, target.find('?')) != "/ws") {
      return respond(request, http::status::not_found, "text/plain", "no such socket\n");
    }
    if (!server_.policy().origin_allowed(text_of(request[http::field::origin]), host)) {
      server_.count_refused();
      return respond(request, http::status::forbidden, "text/plain", "origin not allowed\n");
    }
    if (!server_.token_allowed(target)) {
      server_.count_refused();
      return respond(request, http::status::forbidden, "text/plain", "missing or wrong token\n");
    }
    if (!server_.has_room()) {
      server_.count_refused();
      return respond(request, http::status::service_unavailable, "text/plain", "too many connections\n");
    }
    std::make_shared<WebSocketSession>(std::move(stream_), server_, std::move(ticket_))->accept(std::move(request));
    return;
  }
  if (!server_.policy().host_allowed(host)) {
    server_.count_refused();
    return respond(request, http::status::forbidden, "text/plain", "unknown host\n");
  }
  if (request.method() != http::verb::get && request.method() != http::verb::head) {
    return respond(request, http::status::method_not_allowed, "text/plain", "only GET\n");
  }
  std::string_view target = text_of(request.target());
  target = target.substr(0, target.find('?'));
  const WebAsset* asset = server_.content().find_asset(target == "/" ? "/index.html" : target);
  if (asset == nullptr) return respond(request, http::status::not_found, "text/plain", "not found\n");
  respond(request, http::status::ok, asset->content_type, std::string(asset->body));
}

void HttpSession::respond(const Request& request, http::status status, std::string_view content_type,
                          std::string body) {
  auto response = std::make_shared<http::response<http::string_body>>(status, request.version());
  response->set(http::field::server, "stepdance serve");
  response->set(http::field::content_type, beast::string_view(content_type.data(), content_type.size()));
  response->set(http::field::cache_control, "no-store");
  response->set("X-Content-Type-Options", "nosniff");
  response->set("Content-Security-Policy",
                "default-src 'self'; connect-src 'self' ws://" + std::string(text_of(request[http::field::host])));
  response->keep_alive(request.keep_alive() && status == http::status::ok);
  response->body() = request.method() == http::verb::head ? std::string() : std::move(body);
  response->prepare_payload();
  if (request.method() == http::verb::head) response->content_length(body.size());
  stream_.expires_after(WebServer::kRequestTimeout);  // a client that never reads the response
  http::async_write(stream_, *response, [self = shared_from_this(), response](beast::error_code error, size_t) {
    if (!error && response->keep_alive()) return self->read();
    self->stream_.socket().shutdown(boost::asio::ip::tcp::socket::shutdown_send, error);
  });
}

// ---- WebSocket ----------------------------------------------------------------------------------

WebSocketSession::WebSocketSession(beast::tcp_stream stream, WebServer& server,
                                   std::unique_ptr<ConnectionTicket> ticket)
    : socket_(std::move(stream)), server_(server), ticket_(std::move(ticket)) {}

void WebSocketSession::accept(http::request<http::string_body> request) {
  beast::get_lowest_layer(socket_).expires_never();
  socket_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
  socket_.read_message_max(WebServer::kMaxMessageBytes);
  socket_.set_option(websocket::stream_base::decorator(
      [](websocket::response_type& response) { response.set(http::field::server, "stepdance serve"); }));
  socket_.async_accept(request, [self = shared_from_this()](beast::error_code error) {
    if (error) return;
    self->id_ = self->server_.add_client(self);
    self->read();
  });
}

void WebSocketSession::read() {
  socket_.async_read(buffer_, [self = shared_from_this()](beast::error_code error, size_t) {
    if (error) return self->finish();
    if (self->socket_.got_text()) self->server_.deliver(self->id_, beast::buffers_to_string(self->buffer_.data()));
    self->buffer_.consume(self->buffer_.size());
    self->read();
  });
}

void WebSocketSession::send(const std::string& message) {
  if (finished_) return;
  if (outgoing_.size() >= WebServer::kMaxQueuedMessages) {
    server_.count_dropped();
    return;
  }
  outgoing_.push_back(message);
  write();
}

void WebSocketSession::write() {
  if (writing_ || outgoing_.empty() || finished_) return;
  writing_ = true;
  socket_.text(true);
  socket_.async_write(boost::asio::buffer(outgoing_.front()),
                      [self = shared_from_this()](beast::error_code error, size_t) {
                        self->writing_ = false;
                        self->outgoing_.pop_front();
                        if (error) return self->finish();
                        self->write();
                      });
}

void WebSocketSession::close() {
  beast::error_code ignored;
  beast::get_lowest_layer(socket_).socket().close(ignored);  // the server is stopping: no handshake
  finish();
}

void WebSocketSession::finish() {
  if (finished_) return;
  finished_ = true;
  server_.remove_client(id_);
}

}  // namespace stepdance::cli::serve
