// `stepdance serve` without a target: compiles and runs the sketches the Stepdance page sends.
#pragma once

#include <stdint.h>

#include <string>
#include <vector>

namespace stepdance::cli::serve {

/// Limits of one run request (docs/web.md, "Editing a sketch"): the files of an example.
constexpr size_t kMaxRunFiles = 32;

/// What the sketch server listens on and whom it answers.
struct SketchServerOptions {
  std::string host = "127.0.0.1";
  uint16_t port = 8001;
  /// Web origins whose pages may connect (the Stepdance page's, e.g. http://127.0.0.1:8000),
  /// besides the server's own. Each may run native code on this machine: a sketch is C++.
  std::vector<std::string> allowed_origins;
  /// Compiled sketches cached here, for --unconfined runs only ("" = the default): a confined
  /// run caches in its own folder, which it alone may write.
  std::string cache_directory;
  /// Run sketches without confinement (docs/web.md): when the kernel lacks a guard, or to trust
  /// the pages.
  bool unconfined = false;
  /// Wall seconds a sketch may run without simulated time moving before it is stopped.
  double watchdog_s = 5;
};

/// Serves the Stepdance page's edit path on host:port until SIGINT or SIGTERM: a WebSocket on
/// /ws speaking the edit protocol (docs/web.md): a `run` request's files are written into a
/// fresh folder of their own (never the user's) and built and run by a child process of their
/// own (`stepdance run-sketch`, serve/sketch_runner.hpp), confined to that folder, whose messages
/// the server forwards. A child that crashes, hangs or is ended is reported to its page; the
/// folder is removed after any end, and those of servers that died are removed at start.
/// Announces `serving sketches on http://<host>:<port>/` on stdout once listening. Returns
/// kExitOk, or kExitFailure when it cannot listen.
int run_sketch_server(const SketchServerOptions& options);

}  // namespace stepdance::cli::serve
