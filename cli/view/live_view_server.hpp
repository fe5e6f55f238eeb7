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
/// session accumulates meanwhile, so a slow page gets fewer, larger updates and no lost stroke.
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
  const std::string& token() const { return token_; }

 private:
  void send_updates(double wall_s);
  double wall_now_s() const;

  sim::Simulation& simulation_;
  boost::asio::io_context io_;
  std::string token_;
  sim::view::RunControl control_;
  std::unique_ptr<serve::WebServer> server_;
  std::map<serve::ClientId, std::unique_ptr<sim::view::ViewSession>> sessions_;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_poll_{};
};

}  // namespace stepdance::cli
