// `stepdance serve`: the board link, the request router and the web server on one event loop.
#include "serve_command.hpp"

#include <sys/wait.h>

#include <csignal>
#include <filesystem>
#include <iostream>
#include <memory>

#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>

#include "command_help.hpp"
#include "exit_codes.hpp"
#include "option_kinds.hpp"
#include "scenario/value_range.hpp"
#include "serve/child_board_link.hpp"
#include "serve/request_router.hpp"
#include "serve/serial_device_link.hpp"
#include "serve/sketch_server.hpp"
#include "serve/web_server.hpp"

namespace stepdance::cli {
namespace {

namespace net = boost::asio;
using serve::Clock;

/// How long a simulated board's child may take to write its outputs when the server stops.
constexpr std::chrono::seconds kStopGrace{60};
constexpr std::chrono::milliseconds kHousekeepingPeriod{100};
constexpr int kStatusEveryTicks = 10;  // the counters go to the pages once a second

namespace ranges = sim::scenario::ranges;

/// The numbers of the command line, read by the one number parser (value_range.hpp).
struct ServeNumbers {
  uint16_t port = 8001;
  unsigned baud = 115200;
  double speed = 1.0;
};

/// Reads --port, --baud and --speed; false (messages on stderr) when one is not in its range.
/// --speed, --board and --out only steer a simulation: given with a serial device, they are
/// refused rather than ignored.
bool read_numbers(const ServeCommandOptions& options, bool serial_device, ServeNumbers& numbers) {
  const auto port = read_integer_option("--port", options.port, ranges::kTcpPort);
  const auto baud = read_integer_option("--baud", options.baud, ranges::kBaudRate);
  std::optional<double> speed = 1.0;
  if (!options.speed.empty()) speed = read_number_option("--speed", options.speed, ranges::kServeSpeed);
  if (!port || !baud || !speed) return false;
  if (serial_device && (!options.speed.empty() || !options.board.empty() || !options.output_directory.empty())) {
    std::cerr << "serve: --speed, --board and --out steer a simulation; " << options.target << " is a serial device\n";
    return false;
  }
  numbers = {static_cast<uint16_t>(*port), static_cast<unsigned>(*baud), *speed};
  return true;
}

/// The board's child: `stepdance run-board` with the command line's simulation options.
std::vector<std::string> board_runner_arguments(const ServeCommandOptions& options, double speed) {
  std::vector<std::string> arguments{"run-board", "--scenario", options.target, "--speed", std::to_string(speed)};
  if (!options.board.empty()) arguments.insert(arguments.end(), {"--board", options.board});
  if (!options.cache_directory.empty()) arguments.insert(arguments.end(), {"--cache", options.cache_directory});
  if (!options.output_directory.empty()) {
    const std::string out = std::filesystem::absolute(options.output_directory).lexically_normal().string();
    arguments.insert(arguments.end(), {"--out", out});
  }
  return arguments;
}

nlohmann::json status_message(const serve::RequestRouter& router, const serve::WebServer& server) {
  const serve::RouterCounters& c = router.counters();
  return {{"bridge",
           {{"clients", router.clients()},
            {"forwarded", c.forwarded},
            {"replied", c.replied},
            {"dropped", c.dropped},
            {"refused", c.refused},
            {"timed_out", c.timed_out},
            {"board_lines", c.board_lines},
            {"messages_dropped", server.dropped_messages()},
            {"connections_refused", server.refused_connections()},
            {"connections_open", server.open_connections()},
            {"accept_failures", server.accept_failures()}}}};
}

/// The simulated board's drawing and the report of its run's end go to every page.
void show_simulation_to_pages(serve::ChildBoardLink& simulated, serve::WebServer& server) {
  simulated.on_drawing([&server](const nlohmann::json& update) { server.broadcast(update.dump()); });
  simulated.on_ended([&server](const nlohmann::json& report) {
    std::cerr << "serve: " << report["ended"]["text"].get<std::string>();
    server.broadcast(report.dump());
  });
}

/// Runs the loop: the link, router and server wired together, until a signal stops it.
int serve_until_stopped(net::io_context& io, serve::BoardLink& link, serve::ChildBoardLink* simulated,
                        const ServeCommandOptions& options, uint16_t port) {
  std::unique_ptr<serve::WebServer> server;
  serve::RequestRouter router(
      serve::RouterLimits{}, [&link](const std::string& line) { link.send(line); },
      [&server](serve::ClientId client, const std::string& message) { server->send(client, message); });
  serve::WebServerHooks hooks;
  hooks.connected = [&](serve::ClientId client) {
    router.add_client(client);
    if (simulated != nullptr && simulated->ended()) simulated->restart();  // from the files as they are now
    nlohmann::json hello = {{"hello", {{"board", link.describe()}, {"simulated", simulated != nullptr}}}};
    if (simulated != nullptr) hello["hello"].update(simulated->machine_description());
    server->send(client, hello.dump());
  };
  hooks.message = [&router](serve::ClientId client, std::string_view text) {
    router.from_client(client, text, Clock::now());
  };
  hooks.disconnected = [&router](serve::ClientId client) { router.remove_client(client); };
  server = std::make_unique<serve::WebServer>(io, options.host, port, options.allowed_origins, hooks);
  link.on_line([&router](std::string_view line) { router.from_board(line, Clock::now()); });
  if (simulated != nullptr) show_simulation_to_pages(*simulated, *server);

  net::steady_timer housekeeping(io);
  int ticks = 0;
  uint64_t dropped_reported = 0;
  std::function<void()> schedule = [&] {
    housekeeping.expires_after(kHousekeepingPeriod);
    housekeeping.async_wait([&](const boost::system::error_code& error) {
      if (error) return;
      router.expire(Clock::now());
      if (++ticks % kStatusEveryTicks == 0) {
        server->broadcast(status_message(router, *server).dump());
        const uint64_t dropped = router.counters().dropped + server->dropped_messages();
        if (dropped != dropped_reported) {
          std::cerr << "serve: " << router.counters().dropped << " requests and " << server->dropped_messages()
                    << " messages to pages dropped so far (a client sends or reads too slowly)\n";
          dropped_reported = dropped;
        }
      }
      schedule();
    });
  };
  schedule();

  net::signal_set signals(io, SIGINT, SIGTERM);
  signals.async_wait([&](const boost::system::error_code&, int) {
    server->stop();
    housekeeping.cancel();
    io.stop();
  });
  const std::string shown_host = options.host.find(':') != std::string::npos ? "[" + options.host + "]" : options.host;
  std::cout << "serving http://" << shown_host << ":" << server->port() << "/ for " << link.describe() << std::endl;
  io.run();
  return kExitOk;
}

/// A scenario's board, run by a child process: waits until it runs (or ends: a scenario or
/// sketch that does not build, its exit status returned), serves, then stops it so that it
/// writes its outputs.
int serve_simulation(net::io_context& io, const ServeCommandOptions& options, const ServeNumbers& numbers) {
  serve::ChildBoardLink link(io, board_runner_arguments(options, numbers.speed), options.board);
  while (!link.running() && !link.ended()) io.run_one_for(std::chrono::milliseconds(100));
  if (!link.running()) {
    const int status = link.exit_status();
    return WIFEXITED(status) && WEXITSTATUS(status) != kExitOk ? WEXITSTATUS(status) : kExitFailure;
  }
  serve_until_stopped(io, link, &link, options, numbers.port);
  for (const std::string& file : link.stop(io, kStopGrace)) std::cout << "wrote " << file << "\n";
  return kExitOk;
}

/// `stepdance serve` without a target: the Stepdance page's sketch server.
int run_sketch_server_command(const ServeCommandOptions& options) {
  if (!options.board.empty() || !options.speed.empty() || !options.output_directory.empty() ||
      options.baud != "115200") {
    std::cerr << "serve: --board, --speed, --out and --baud need a target; the sketch server takes the page's runs\n";
    return kExitBadInput;
  }
  const auto port = read_integer_option("--port", options.port, ranges::kTcpPort);
  if (!port) return kExitBadInput;
  serve::SketchServerOptions server;
  server.host = options.host;
  server.port = static_cast<uint16_t>(*port);
  server.allowed_origins = options.allowed_origins;
  server.cache_directory = options.cache_directory;
  server.unconfined = options.unconfined;
  return serve::run_sketch_server(server);
}

}  // namespace

CLI::App& add_serve_command(CLI::App& app, ServeCommandOptions& options) {
  CLI::App& serve = add_command(
      app, "serve",
      "Serve a web control page for a board's RPC names and bridge it over WebSocket to the board's serial "
      "line: a real board (a serial device such as /dev/ttyACM0) or a simulated one (a scenario or example "
      "folder, run live with a view of its drawing). Listens on 127.0.0.1 only unless --host says otherwise; "
      "only the page's own origin may connect unless --allow-origin adds others. Stop with Ctrl-C; a "
      "simulation then writes its output files.");
  serve.add_option("target", options.target,
                   "a serial device, or a scenario .toml / example folder; without one, compile and run the "
                   "sketches the Stepdance page (docs/web.md) sends from an --allow-origin origin");
  serve.add_option("--host", options.host, "address to listen on (default 127.0.0.1)");
  add_number_option(serve, "--port", options.port, "TCP port, in [0, 65,535] (default 8001; 0 picks a free one)");
  serve.add_option("--allow-origin", options.allowed_origins,
                   "also accept WebSockets from this origin, e.g. http://192.168.1.5:8001 (repeatable)");
  add_number_option(
      serve, "--baud", options.baud,
      "serial device: baud rate, in " + describe(ranges::kBaudRate) + " (default 115200; USB ignores it)");
  serve.add_option("--board", options.board, "simulation: the board to bridge (default the first)");
  add_number_option(
      serve, "--speed", options.speed,
      "simulation: simulated seconds per wall-clock second, in " + describe(ranges::kServeSpeed) + " (default 1)");
  add_output_folder_option(serve, options.output_directory, "simulation: ");
  add_cache_folder_option(serve, options.cache_directory, "simulation: ");
  serve.add_flag("--unconfined", options.unconfined,
                 "sketch server: run the pages' sketches with your rights, without the confinement docs/web.md "
                 "describes (needed where the kernel lacks Landlock ABI 6 or seccomp)");
  return serve;
}

int run_serve_command(const ServeCommandOptions& options) {
  if (options.target.empty()) return run_sketch_server_command(options);
  const bool serial_device = std::filesystem::is_character_file(options.target);
  ServeNumbers numbers;
  if (!read_numbers(options, serial_device, numbers)) return kExitBadInput;
  net::io_context io;
  try {
    if (serial_device) {
      serve::SerialDeviceLink link(io, options.target, numbers.baud);
      return serve_until_stopped(io, link, nullptr, options, numbers.port);
    }
    return serve_simulation(io, options, numbers);
  } catch (const std::exception& failure) {
    std::cerr << "serve: " << failure.what() << "\n";
    return kExitFailure;
  }
}

}  // namespace stepdance::cli
