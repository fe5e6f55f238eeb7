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
#include <thread>

#include <boost/asio/post.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>
#include <nlohmann/json.hpp>

#include "assembly/run_result.hpp"
#include "exit_codes.hpp"
#include "scenario/load_scenario.hpp"
#include "serve/web_server.hpp"
#include "simulator_hooks.hpp"
#include "view/view_session.hpp"

namespace stepdance::cli::serve {
namespace {

namespace net = boost::asio;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using nlohmann::json;

/// The edit protocol's version, sent in `serve_hello`.
constexpr int kEditProtocolVersion = 1;
/// How often the running simulation is paced and the page updated.
constexpr std::chrono::milliseconds kPacePeriod{2};
/// At --speed max, the longest the event loop is held by the simulation at once, and the
/// simulated time run between looks at the clock.
constexpr std::chrono::milliseconds kMaxSpeedSlice{15};
constexpr sim::SimTime kMaxSpeedStepNs = 10 * sim::kMillisecond;

/// A run request's files, checked: plain names only (no folders, nothing hidden).
struct RunRequest {
  std::string example;
  std::vector<std::pair<std::string, std::string>> files;  ///< name, text
  std::string scenario;
};

bool plain_name(const std::string& name) {
  static const std::regex kPlain("[A-Za-z0-9_][A-Za-z0-9_.-]{0,99}");
  return std::regex_match(name, kPlain) && name.find("..") == std::string::npos;
}

/// The request in `message`, or an error saying what is wrong with it.
std::optional<RunRequest> read_run_request(const json& message, std::string& error) {
  RunRequest request;
  const json* example = message.contains("example") ? &message["example"] : nullptr;
  const json* files = message.contains("files") ? &message["files"] : nullptr;
  const json* scenario = message.contains("scenario") ? &message["scenario"] : nullptr;
  if (!example || !example->is_string() || !plain_name(*example) || !files || !files->is_object() || !scenario ||
      !scenario->is_string()) {
    error = "run: needs `example` (a plain name), `files` ({name: text}) and `scenario` (one of the files)";
    return std::nullopt;
  }
  if (files->size() > kMaxRunFiles) {
    error = "run: at most " + std::to_string(kMaxRunFiles) + " files";
    return std::nullopt;
  }
  request.example = *example;
  request.scenario = *scenario;
  for (const auto& [name, text] : files->items()) {
    if (!plain_name(name) || !text.is_string()) {
      error = "run: '" + name + "' is not a plain file name with a text";
      return std::nullopt;
    }
    request.files.emplace_back(name, text.get<std::string>());
  }
  if (!files->contains(request.scenario)) {
    error = "run: the scenario '" + request.scenario + "' is not among the files";
    return std::nullopt;
  }
  return request;
}

/// A fresh folder of the server's own under the system's temporary folder.
fs::path make_run_folder() {
  std::string pattern = (fs::temp_directory_path() / "stepdance-serve-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot make a folder for the run: " + pattern);
  return pattern;
}

/// `text` with every mention of `folder`/ left out, so the page sees the file names it sent.
std::string relative_to(std::string text, const std::string& folder) {
  const std::string prefix = folder + "/";
  for (size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix, at)) text.erase(at, prefix.size());
  return text;
}

/// What the build thread hands the event loop: a simulation ready to run, or the errors.
struct Built {
  std::unique_ptr<sim::Simulation> simulation;
  std::string errors;
};

Built build(const RunRequest& request, const fs::path& folder, const std::string& cache_directory) {
  const fs::path example = folder / request.example;
  fs::create_directories(example);
  for (const auto& [name, text] : request.files) std::ofstream(example / name, std::ios::binary) << text;
  Built built;
  sim::scenario::LoadResult loaded = sim::scenario::load_scenario((example / request.scenario).string());
  if (!loaded.ok()) {
    built.errors = relative_to(loaded.error_text(), example.string());
    return built;
  }
  loaded.scenario.hosts.clear();  // the page is the host here
  sim::SimulationOptions options;
  plug_front_end(options, cache_directory);
  options.output_directory = (folder / "out").string();
  options.write_vcd = false;
  sim::SimulationError error;
  built.simulation = sim::Simulation::create(loaded.scenario, options, error);
  if (!built.simulation) built.errors = relative_to(error.message, example.string());
  return built;
}

/// One run being shown to one page.
struct ActiveRun {
  ClientId client = 0;
  std::unique_ptr<sim::Simulation> simulation;
  sim::view::RunControl control;
  std::unique_ptr<sim::view::ViewSession> session;
  Clock::time_point anchor_wall;
  sim::SimTime anchor_sim = 0;
  double anchor_speed = -1;
  bool finished = false;
};

class SketchServer {
 public:
  explicit SketchServer(const SketchServerOptions& options) : options_(options), pace_(io_), signals_(io_, SIGINT, SIGTERM) {
    WebServerHooks hooks;
    hooks.connected = [this](ClientId client) {
      server_->send(client, json{{"type", "serve_hello"}, {"version", kEditProtocolVersion},
                                 {"program", "stepdance serve"}, {"compiles", true}}.dump());
    };
    hooks.message = [this](ClientId client, std::string_view text) { receive(client, text); };
    hooks.disconnected = [this](ClientId client) {
      if (run_ && run_->client == client) end_run();
    };
    server_ = std::make_unique<WebServer>(io_, options.host, options.port, options.allowed_origins, hooks);
  }

  ~SketchServer() {
    if (builder_.joinable()) builder_.join();
    end_run();
    if (!folder_.empty()) fs::remove_all(folder_);
  }

  int serve() {
    signals_.async_wait([this](const boost::system::error_code&, int) {
      server_->stop();
      pace_.cancel();
      io_.stop();
    });
    std::cout << "serving sketches on http://" << options_.host << ":" << server_->port() << "/" << std::endl;
    schedule_pace();
    io_.run();
    return kExitOk;
  }

 private:
  void error(ClientId client, const std::string& message) {
    server_->send(client, json{{"type", "error"}, {"message", message}}.dump());
  }

  void receive(ClientId client, std::string_view text) {
    json message = json::parse(text, nullptr, false);
    if (message.is_object() && message.value("type", "") == "run") return start_build(client, message);
    if (run_ && run_->client == client) {
      for (const std::string& reply : run_->session->receive(text)) server_->send(client, reply);
      return;
    }
    error(client, "not a run request, and no run of yours is going: send {\"type\": \"run\", …} first");
  }

  void start_build(ClientId client, const json& message) {
    std::string problem;
    std::optional<RunRequest> request = read_run_request(message, problem);
    if (!request) return error(client, problem);
    if (building_) return error(client, "busy: another run is being built; send it again when it has started");
    end_run();
    if (builder_.joinable()) builder_.join();
    if (!folder_.empty()) fs::remove_all(folder_);
    folder_ = make_run_folder();
    building_ = true;
    server_->send(client, json{{"type", "building"}}.dump());
    builder_ = std::thread([this, client, request = std::move(*request), folder = folder_]() {
      auto built = std::make_shared<Built>();
      try {
        *built = build(request, folder, options_.cache_directory);
      } catch (const std::exception& failure) {  // a file that cannot be written, say
        built->errors = failure.what();
      }
      net::post(io_, [this, client, built]() { built_one(client, std::move(*built)); });
    });
  }

  void built_one(ClientId client, Built built) {
    building_ = false;
    if (!built.simulation) {
      server_->send(client, json{{"type", "failed"}, {"text", built.errors}}.dump());
      return;
    }
    run_ = std::make_unique<ActiveRun>();
    run_->client = client;
    run_->simulation = std::move(built.simulation);
    run_->session = std::make_unique<sim::view::ViewSession>(*run_->simulation, run_->control);
    for (const auto& board : run_->simulation->scenario().boards) {
      sim::SimBoard* sim_board = run_->simulation->board(board.name);
      sim::view::ViewSession* session = run_->session.get();
      const std::string name = board.name;
      sim_board->on_console_bytes(
          [session, name](const uint8_t* data, size_t length) { session->console_output(name, data, length); });
    }
    server_->send(client, json{{"type", "started"}}.dump());
    server_->send(client, run_->session->hello());
  }

  void end_run() {
    if (!run_) return;
    for (const auto& board : run_->simulation->scenario().boards) run_->simulation->board(board.name)->on_console_bytes(nullptr);
    run_.reset();
  }

  void schedule_pace() {
    pace_.expires_after(kPacePeriod);
    pace_.async_wait([this](const boost::system::error_code& failure) {
      if (failure) return;
      if (run_ && !run_->finished) pace_run(*run_);
      schedule_pace();
    });
  }

  // Runs the simulation as far as the wall clock and the page's speed say, then updates the page.
  void pace_run(ActiveRun& run) {
    sim::Simulation& simulation = *run.simulation;
    const Clock::time_point now = Clock::now();
    if (run.control.paused) {
      run.anchor_speed = -1;  // paced from where it resumes
    } else {
      if (run.anchor_speed != run.control.speed) {
        run.anchor_wall = now;
        run.anchor_sim = simulation.now();
        run.anchor_speed = run.control.speed;
      }
      if (run.control.speed > 0) {
        const double due_s = std::chrono::duration<double>(now - run.anchor_wall).count() * run.control.speed;
        simulation.run_until(std::min(simulation.duration(), run.anchor_sim + sim::from_seconds(due_s)));
      } else {
        while (Clock::now() - now < kMaxSpeedSlice && simulation.now() < simulation.duration() && !simulation.stopped())
          simulation.run_until(std::min(simulation.duration(), simulation.now() + kMaxSpeedStepNs));
      }
    }
    const double wall_s = std::chrono::duration<double>(now.time_since_epoch()).count();
    if (auto update = run.session->update(wall_s)) server_->send(run.client, *update);
    if (simulation.now() >= simulation.duration() || simulation.stopped()) finish_run(run);
  }

  void finish_run(ActiveRun& run) {
    run.finished = true;
    server_->send(run.client, run.session->update_now());
    try {
      const sim::SimulationReport report = run.simulation->finish();
      json result = json::parse(sim::run_result_json(*run.simulation, report));
      server_->send(run.client, json{{"type", "result"}, {"result", result}}.dump());
    } catch (const std::exception& failure) {
      error(run.client, std::string("the run's outputs: ") + failure.what());
    }
  }

  SketchServerOptions options_;
  net::io_context io_;
  std::unique_ptr<WebServer> server_;
  net::steady_timer pace_;
  net::signal_set signals_;
  std::thread builder_;
  bool building_ = false;
  fs::path folder_;
  std::unique_ptr<ActiveRun> run_;
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
