// The live view's server: the view protocol (sim/view) over the web server of `stepdance serve`.
#pragma once

#include <stdint.h>

#include <map>
#include <memory>
#include <string>

#include <boost/asio/io_context.hpp>

#include "live_run.hpp"
#include "serve/web_server.hpp"
#include "view/view_session.hpp"

namespace stepdance::cli {

/// Serves the live view's page (web/view/, built into the program) on 127.0.0.1 and one
/// ViewSession per WebSocket, with serve's checks (Host and Origin: OriginPolicy; connection,
/// client and message limits: WebServer) and a token of the run's own that the WebSocket's URL
/// must carry. Runs on the simulation's thread: the network is served only from serve_now()
/// and serve_for(), between simulated milliseconds, so pages act on the run only there.
/// A page gets its next update only once its previous messages have gone (back-pressure): its
/// session accumulates meanwhile, so a slow page gets fewer, larger updates and no lost stroke,
/// and the server holds one update and at most WebServer::kMaxQueuedMessages replies for it,
/// however long it does not read. finish() prints what the pages got and missed (report()).
class LiveViewServer : public LiveView {
 public:
  /// Listens on 127.0.0.1:`port` (0: any free port). Throws std::runtime_error.
  LiveViewServer(sim::Simulation& simulation, uint16_t port);
  ~LiveViewServer() override;

  std::string announcement() const override;
  void console(const std::string& board, const uint8_t* data, size_t length) override;
  void serve_now(double wall_s) override;
  void serve_for(std::chrono::steady_clock::duration span) override;
  sim::view::RunControl& control() override { return control_; }
  void finish() override;

  uint16_t port() const { return server_->port(); }
  /// "live view: N page(s); U updates sent, H held back …, R replies dropped …, C console bytes
  /// dropped": every page of the run, those gone included.
  std::string report() const;
  const std::string& token() const { return token_; }

 private:
  /// What the pages of the run got and missed, those still open left out.
  struct ViewTotals {
    uint64_t pages = 0;
    uint64_t updates = 0;
    uint64_t held_back = 0;
    uint64_t console_dropped_bytes = 0;
  };
  void send_updates(double wall_s);
  /// Adds a closing page's figures to totals_.
  void count(const sim::view::ViewSession& session);
  double wall_now_s() const;

  sim::Simulation& simulation_;
  boost::asio::io_context io_;
  std::string token_;
  sim::view::RunControl control_;
  std::unique_ptr<serve::WebServer> server_;
  std::map<serve::ClientId, std::unique_ptr<sim::view::ViewSession>> sessions_;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_poll_{};
  ViewTotals totals_;
};

}  // namespace stepdance::cli
