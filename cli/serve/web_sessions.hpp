// One HTTP connection (the page's files, or an upgrade) and one WebSocket client of WebServer.
#pragma once

#include <deque>
#include <memory>
#include <optional>
#include <string>

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include "web_server.hpp"

namespace stepdance::cli::serve {

/// Reads HTTP requests on one connection: answers the page's files, refuses what the policy
/// forbids, and hands an allowed upgrade on /ws to a WebSocketSession.
class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(boost::asio::ip::tcp::socket socket, WebServer& server, std::unique_ptr<ConnectionTicket> ticket);
  void run() { read(); }

 private:
  using Request = boost::beast::http::request<boost::beast::http::string_body>;
  void read();
  void on_request(Request request);
  void respond(const Request& request, boost::beast::http::status status, std::string_view content_type,
               std::string body);

  boost::beast::tcp_stream stream_;
  boost::beast::flat_buffer buffer_;
  std::optional<boost::beast::http::request_parser<boost::beast::http::string_body>> parser_;
  WebServer& server_;
  std::unique_ptr<ConnectionTicket> ticket_;  ///< handed on to the WebSocket after an upgrade
};

/// A connected page: its messages go to the server's hooks; messages for it wait in a bounded queue.
class WebSocketSession : public std::enable_shared_from_this<WebSocketSession> {
 public:
  WebSocketSession(boost::beast::tcp_stream stream, WebServer& server, std::unique_ptr<ConnectionTicket> ticket);
  /// Completes the upgrade `request` asked for, then reads messages until the page goes.
  void accept(boost::beast::http::request<boost::beast::http::string_body> request);
  void send(const std::string& message);
  /// Messages not yet handed to the socket whole (the one being written included).
  size_t queued_messages() const { return outgoing_.size(); }
  void close();

 private:
  void read();
  void write();
  void finish();

  boost::beast::websocket::stream<boost::beast::tcp_stream> socket_;
  boost::beast::flat_buffer buffer_;
  std::deque<std::string> outgoing_;
  WebServer& server_;
  std::unique_ptr<ConnectionTicket> ticket_;
  ClientId id_ = 0;
  bool writing_ = false;
  bool finished_ = false;
};

}  // namespace stepdance::cli::serve
