// LiveViewServer: a WebServer with the view's page and token, one ViewSession per page.
#include "view/live_view_server.hpp"

#include <cstdio>
#include <random>

namespace stepdance::cli {
namespace {

/// How often serve_now() looks at the network at most (it is called every simulated ms, which
/// at --speed max comes far more often than pages need).
constexpr std::chrono::milliseconds kPollPeriod{1};

/// 128 random bits as 32 hex digits: the run's token.
std::string random_token() {
  std::random_device source;
  static const char kHex[] = "0123456789abcdef";
  std::string token;
  for (int i = 0; i < 8; ++i) {
    uint32_t word = source();
    for (int j = 0; j < 4; ++j, word >>= 4) token += kHex[word & 0xF];
  }
  return token;
}

}  // namespace

LiveViewServer::LiveViewServer(sim::Simulation& simulation, uint16_t port)
    : simulation_(simulation), token_(random_token()) {
  serve::WebServerHooks hooks;
  hooks.connected = [this](serve::ClientId client) {
    ++totals_.pages;
    auto session = std::make_unique<sim::view::ViewSession>(simulation_, control_);
    server_->send(client, session->hello());
    sessions_[client] = std::move(session);
  };
  hooks.message = [this](serve::ClientId client, std::string_view text) {
    auto found = sessions_.find(client);
    if (found == sessions_.end()) return;
    for (const std::string& reply : found->second->receive(text)) server_->send(client, reply);
  };
  hooks.disconnected = [this](serve::ClientId client) {
    auto found = sessions_.find(client);
    if (found == sessions_.end()) return;
    count(*found->second);
    sessions_.erase(found);
  };
  serve::WebServerContent content;
  content.find_asset = serve::find_view_asset;
  content.token = token_;
  server_ = std::make_unique<serve::WebServer>(io_, "127.0.0.1", port, std::vector<std::string>{}, hooks, content);
}

LiveViewServer::~LiveViewServer() {
  server_->stop();
  io_.restart();
  io_.poll();
}

std::string LiveViewServer::announcement() const {
  return "view: http://127.0.0.1:" + std::to_string(server_->port()) + "/?token=" + token_;
}

void LiveViewServer::console(const std::string& board, const uint8_t* data, size_t length) {
  for (auto& [client, session] : sessions_) session->console_output(board, data, length);
}

double LiveViewServer::wall_now_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
}

void LiveViewServer::send_updates(double wall_s) {
  for (auto& [client, session] : sessions_) {
    if (!session->due(wall_s)) continue;
    // Back-pressure: a page whose last messages are still queued gets no new update yet (the
    // update is held back and counted); its session keeps what the page was last sent, so the
    // delta it gets once its queue has drained carries everything since (the drawing in full,
    // console text up to its cap). The queue holds one update and replies: bounded.
    if (server_->queued_messages(client) > 0) {
      session->hold_back(wall_s);
      continue;
    }
    if (auto update = session->update(wall_s)) server_->send(client, *update);
  }
}

void LiveViewServer::serve_now(double wall_s) {
  const auto now = std::chrono::steady_clock::now();
  if (now - last_poll_ < kPollPeriod) return;
  last_poll_ = now;
  if (io_.stopped()) io_.restart();
  io_.poll();
  send_updates(wall_s);
}

void LiveViewServer::serve_for(std::chrono::steady_clock::duration span) {
  if (io_.stopped()) io_.restart();
  io_.run_for(span);
  last_poll_ = std::chrono::steady_clock::now();
  send_updates(wall_now_s());
}

void LiveViewServer::finish() {
  // Every page gets the run's last state, "ended", the drawing in as many updates as it takes
  // (each after the page's queue has drained, as during the run), then the sockets are served
  // until nothing happens for 5 ms, for 200 ms at most (a page that does not read is not waited for).
  for (auto& [client, session] : sessions_) session->end_run();
  std::map<serve::ClientId, bool> last_sent;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(200);
  while (std::chrono::steady_clock::now() < deadline) {
    bool all_sent = true;
    for (auto& [client, session] : sessions_) {
      if (last_sent[client] && !session->strokes_behind()) continue;
      all_sent = false;
      if (server_->queued_messages(client) > 0) continue;
      server_->send(client, session->update_now());
      last_sent[client] = true;
    }
    if (io_.stopped()) io_.restart();
    if (io_.run_for(std::chrono::milliseconds(5)) == 0 && all_sent) break;
  }
  std::printf("%s\n", report().c_str());
  std::fflush(stdout);
}

void LiveViewServer::count(const sim::view::ViewSession& session) {
  totals_.updates += session.updates_made();
  totals_.held_back += session.held_back();
  totals_.console_dropped_bytes += session.console_dropped_bytes();
}

std::string LiveViewServer::report() const {
  ViewTotals totals = totals_;
  for (const auto& [client, session] : sessions_) {
    totals.updates += session->updates_made();
    totals.held_back += session->held_back();
    totals.console_dropped_bytes += session->console_dropped_bytes();
  }
  return "live view: " + std::to_string(totals.pages) + " page(s); " + std::to_string(totals.updates) +
         " updates sent, " + std::to_string(totals.held_back) +
         " held back while a page had not read the last (the next carried what they missed), " +
         std::to_string(server_->dropped_messages()) + " replies dropped (a page's queue full), " +
         std::to_string(totals.console_dropped_bytes) + " console bytes dropped";
}

}  // namespace stepdance::cli
