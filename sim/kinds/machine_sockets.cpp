// MachineSockets: a machine's socket keys, checked against what the board's sockets hold.
#include "kinds/machine_kind.hpp"

namespace stepdance::sim {

using scenario::SocketDevice;

std::optional<char> MachineSockets::take(std::string_view key, SocketDevice device, std::optional<char> fallback) {
  const bool given = reader_.has(key);
  std::optional<char> port = scenario::read_socket_letter(reader_, key);
  if (given && !port) return std::nullopt;
  if (!given) port = fallback;
  if (!port || board_ == nullptr) return port;
  const std::string what = device == SocketDevice::kStepper ? "a stepper" : "a servo";
  const std::string where = std::string("socket ") + *port + " of board '" + board_->name + "'";
  const scenario::SocketConfig* socket = board_->socket(*port);
  if (socket == nullptr) {
    reader_.error(key, "'" + std::string(key) + "' needs " + what + " in " + where + ", but it is empty");
  } else if (socket->device != device) {
    const std::string holds = socket->device == SocketDevice::kStepper ? "a stepper" : "a servo";
    reader_.error(key, "'" + std::string(key) + "' needs " + what + " in " + where + ", but it holds " + holds);
  } else if (const auto user = users_.find(*port); user != users_.end()) {
    reader_.error(key, "'" + std::string(key) + "' uses socket " + std::string(1, *port) + ", already used by '" +
                           user->second + "'");
  }
  users_.emplace(*port, std::string(key));
  return port;
}

}  // namespace stepdance::sim
