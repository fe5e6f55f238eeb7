// Which web pages may open the bridge's WebSocket, and under which host names it answers.
#pragma once

#include <stdint.h>

#include <string>
#include <string_view>
#include <vector>

namespace stepdance::cli::serve {

/// The server answers only requests whose Host header names it: a loopback name (127.0.0.1,
/// localhost, [::1]) or the address it listens on, with its port. That stops a foreign site from
/// reaching it through a DNS name rebound to 127.0.0.1. A WebSocket upgrade must also come from
/// the page's own origin, http://<Host>, or from an origin given with --allow-origin (compared
/// exactly, e.g. "http://192.168.1.5:8001", which also lets that host name in). An upgrade without
/// an Origin header is refused: programs other than browsers send the page's origin too.
class OriginPolicy {
 public:
  OriginPolicy(std::string listen_address, uint16_t port, std::vector<std::string> allowed_origins);
  /// Whether `host` (the Host header) names this server.
  bool host_allowed(std::string_view host) const;
  /// Whether a WebSocket with this Origin header (empty: none) and Host header may connect.
  bool origin_allowed(std::string_view origin, std::string_view host) const;
  void set_port(uint16_t port) { port_ = port; }

 private:
  std::string listen_address_;
  uint16_t port_;
  std::vector<std::string> allowed_origins_;
};

}  // namespace stepdance::cli::serve
