// The sketch server: the edit protocol's requests built on a thread, runs paced on the event loop.
#include "serve/sketch_server.hpp"

#include <stdlib.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <regex>
#include <stdexcept>

#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>
#include <nlohmann/json.hpp>

#include "confine/confinement.hpp"
#include "exit_codes.hpp"
#include "serve/run_folders.hpp"
#include "serve/served_run.hpp"
#include "serve/web_server.hpp"

namespace stepdance::cli::serve {
namespace {

namespace net = boost::asio;
namespace fs = std::filesystem;
using nlohmann::json;

/// The edit protocol's version, sent in `serve_hello`. Version 2 named the run request
/// `sketch_run` (version 1's `run` was the view protocol's run control's name too: issue 40).
constexpr int kEditProtocolVersion = 2;
/// The edit protocol's run request. Every other message from the page goes to its run's view.
constexpr const char* kRunRequestType = "sketch_run";
/// How often the server looks at its run's process.
constexpr std::chrono::milliseconds kCheckPeriod{100};

/// "" when the kernel has every guard (or the user chose --unconfined); else why runs are
/// refused. Says so on stderr either way.
std::string confinement_refusal(bool unconfined) {
  const std::vector<std::string> missing = confine::missing_guards();
  if (unconfined) {
    std::cerr << "serve: --unconfined: the sketches pages send run with your rights (docs/web.md)\n";
    return "";
  }
  if (missing.empty()) return "";
  std::string text = "this server refuses to run sketches: the kernel lacks\n";
  for (const std::string& guard : missing) text += "  " + guard + "\n";
  text += "start it with --unconfined to run them with your rights anyway (docs/web.md)\n";
  std::cerr << "serve: " << text;
  return text;
}

/// A run request's files, checked: plain names only (no folders, nothing hidden).
struct RunRequest {
  struct OtherFile {
    std::string folder;  ///< another example's folder, beside the run's example
    std::string name;
    std::string text;
  };
  std::string example;
  std::vector<std::pair<std::string, std::string>> files;  ///< name, text
  std::vector<OtherFile> others;                           ///< files of other examples' folders the scenario names
  std::string scenario;
};

bool plain_name(const std::string& name) {
  static const std::regex kPlain("[A-Za-z0-9_][A-Za-z0-9_.-]{0,99}");
  return std::regex_match(name, kPlain) && name.find("..") == std::string::npos;
}

/// The request's optional `others` ({folder: {name: text}}: files of other examples' folders, as
/// ChainedPlotterDriver's scenario names ../ChainedKnobsBasic/ChainedKnobsBasic.ino) into
/// `request`; false with `error` when they are not plain names with texts.
bool read_other_files(const json& message, RunRequest& request, std::string& error) {
  if (!message.contains("others")) return true;
  const json& others = message["others"];
  error = "sketch_run: `others` must be {folder: {name: text}}, plain names, other than the example's";
  if (!others.is_object()) return false;
  for (const auto& [folder, files] : others.items()) {
    if (!plain_name(folder) || folder == request.example || !files.is_object()) return false;
    for (const auto& [name, text] : files.items()) {
      if (!plain_name(name) || !text.is_string()) return false;
      request.others.push_back({folder, name, text.get<std::string>()});
    }
  }
  error.clear();
  return true;
}

/// The request in `message`, or an error saying what is wrong with it.
std::optional<RunRequest> read_run_request(const json& message, std::string& error) {
  RunRequest request;
  const json* example = message.contains("example") ? &message["example"] : nullptr;
  const json* files = message.contains("files") ? &message["files"] : nullptr;
  const json* scenario = message.contains("scenario") ? &message["scenario"] : nullptr;
  if (!example || !example->is_string() || !plain_name(*example) || !files || !files->is_object() || !scenario ||
      !scenario->is_string()) {
    error = "sketch_run: needs `example` (a plain name), `files` ({name: text}) and `scenario` (one of the files)";
    return std::nullopt;
  }
  if (files->size() > kMaxRunFiles) {
    error = "sketch_run: at most " + std::to_string(kMaxRunFiles) + " files";
    return std::nullopt;
  }
  request.example = *example;
  request.scenario = *scenario;
  for (const auto& [name, text] : files->items()) {
    if (!plain_name(name) || !text.is_string()) {
      error = "sketch_run: '" + name + "' is not a plain file name with a text";
      return std::nullopt;
    }
    request.files.emplace_back(name, text.get<std::string>());
  }
  if (!files->contains(request.scenario)) {
    error = "sketch_run: the scenario '" + request.scenario + "' is not among the files";
    return std::nullopt;
  }
  if (!read_other_files(message, request, error)) return std::nullopt;
  if (request.files.size() + request.others.size() > kMaxRunFiles) {
    error = "sketch_run: at most " + std::to_string(kMaxRunFiles) + " files";
    return std::nullopt;
  }
  return request;
}

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out.flush()) throw std::runtime_error("cannot write " + path.filename().string() + " for the run");
}

/// The run's files written into its folder: <folder>/<example>/<name>, and the other examples'
/// beside it: <folder>/<other>/<name>.
void write_files(const RunRequest& request, const fs::path& folder) {
  const fs::path example = folder / request.example;
  fs::create_directories(example);
  for (const auto& [name, text] : request.files) write_file(example / name, text);
  for (const RunRequest::OtherFile& other : request.others) {
    fs::create_directories(folder / other.folder);
    write_file(folder / other.folder / other.name, other.text);
  }
}

class SketchServer {
 public:
  explicit SketchServer(const SketchServerOptions& options)
      : options_(options), check_(io_), signals_(io_, SIGINT, SIGTERM) {
    WebServerHooks hooks;
    hooks.connected = [this](ClientId client) {
      server_->send(client, json{{"type", "serve_hello"},
                                 {"version", kEditProtocolVersion},
                                 {"program", "stepdance serve"},
                                 {"compiles", true}}
                                .dump());
    };
    hooks.message = [this](ClientId client, std::string_view text) { receive(client, text); };
    hooks.disconnected = [this](ClientId client) {
      if (run_ && client_ == client) run_.reset();
    };
    server_ = std::make_unique<WebServer>(io_, options.host, options.port, options.allowed_origins, hooks);
  }

  int serve() {
    signals_.async_wait([this](const boost::system::error_code&, int) {
      server_->stop();
      check_.cancel();
      run_.reset();
      io_.stop();
    });
    const int stale = remove_stale_run_folders();
    if (stale > 0) std::cout << "removed " << stale << " run folder(s) left by servers that ended" << std::endl;
    refusal_ = confinement_refusal(options_.unconfined);
    std::cout << "serving sketches on http://" << options_.host << ":" << server_->port() << "/" << std::endl;
    schedule_check();
    io_.run();
    run_.reset();
    return kExitOk;
  }

 private:
  void error(ClientId client, const std::string& message) {
    server_->send(client, json{{"type", "error"}, {"message", message}}.dump());
  }

  void receive(ClientId client, std::string_view text) {
    json message = json::parse(text, nullptr, false);
    if (message.is_object() && message.value("type", "") == kRunRequestType) return start_run(client, message);
    if (run_ && client_ == client && !run_->over()) {
      if (!message.is_object()) return error(client, "not a JSON object");
      return run_->to_child(message.dump());  // one line, whatever the page's layout
    }
    error(client, "not a sketch_run request, and no run of yours is going: send {\"type\": \"sketch_run\", …} first");
  }

  void start_run(ClientId client, const json& message) {
    std::string problem;
    std::optional<RunRequest> request = read_run_request(message, problem);
    if (!request) return error(client, problem);
    run_.reset();  // the run before, or its build, ends here
    if (!refusal_.empty()) {
      server_->send(client, json{{"type", "failed"}, {"text", refusal_}}.dump());
      return;
    }
    client_ = client;
    server_->send(client, json{{"type", "building"}}.dump());
    try {
      const std::string folder = make_run_folder();
      try {
        write_files(*request, folder);
      } catch (...) {
        remove_run_folder(folder);
        throw;
      }
      run_ =
          std::make_unique<ServedRun>(io_, folder, runner_arguments(*request, folder), ServedRunLimits{},
                                      [this, client](const std::string& line, bool) { server_->send(client, line); });
    } catch (const std::exception& failure) {  // a file that cannot be written, say
      server_->send(client, json{{"type", "failed"}, {"text", failure.what()}}.dump());
    }
  }

  std::vector<std::string> runner_arguments(const RunRequest& request, const std::string& folder) const {
    std::vector<std::string> arguments{"run-sketch",     "--folder",      folder,
                                       "--example",      request.example, "--scenario",
                                       request.scenario, "--watchdog-s",  std::to_string(options_.watchdog_s)};
    if (options_.unconfined) arguments.insert(arguments.end(), {"--unconfined", "--cache", options_.cache_directory});
    return arguments;
  }

  // Every kCheckPeriod: a run whose process ended, or whose build is too long, is reported and
  // its folder removed.
  void schedule_check() {
    check_.expires_after(kCheckPeriod);
    check_.async_wait([this](const boost::system::error_code& failure) {
      if (failure) return;
      if (run_ && run_->check()) run_.reset();
      schedule_check();
    });
  }

  SketchServerOptions options_;
  net::io_context io_;
  std::unique_ptr<WebServer> server_;
  net::steady_timer check_;
  net::signal_set signals_;
  std::string refusal_;
  ClientId client_ = 0;
  std::unique_ptr<ServedRun> run_;
};

}  // namespace

int run_sketch_server(const SketchServerOptions& options) {
  try {
    SketchServer server(options);
    return server.serve();
  } catch (const std::exception& failure) {
    std::cerr << "serve: " << failure.what() << "\n";
    return kExitFailure;
  }
}

}  // namespace stepdance::cli::serve
