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
  std::string cache_directory;
};

/// Serves the Stepdance page's edit path on host:port until SIGINT or SIGTERM: a WebSocket on
/// /ws speaking the edit protocol (docs/web.md): a `run` request's files are written into a
/// fresh folder of their own (never the user's), the scenario read, the sketches compiled with
/// the host toolchain (on a thread of their own, one run being built at a time), then run paced
/// to the wall clock and shown through the view protocol on the same socket, until its duration
/// or the next run. Announces `serving sketches on http://<host>:<port>/` on stdout once
/// listening. Returns kExitOk, or kExitFailure when it cannot listen.
int run_sketch_server(const SketchServerOptions& options);

}  // namespace stepdance::cli::serve
