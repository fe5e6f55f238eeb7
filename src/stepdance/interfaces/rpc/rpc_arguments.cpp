// RPC argument conversion for BlockPorts: read, read_deep and reset_deep(position).
#include "stepdance/interfaces/rpc/rpc_arguments.hpp"

#include "stepdance/core/block_port.hpp"

namespace stepdance::rpc {

// The three port operations Registry::add_port enrolls, chosen by callable[0]: 0 read (the port's
// absolute position), 1 read_deep (through the chain), 2 reset_deep(position) (no motion).
Problem invoke_port(Entry& entry, const JsonRequest& request, TextWriter& reply) {
  BlockPort& port = *static_cast<BlockPort*>(entry.object);
  const uint8_t operation = entry.callable[0];
  if (operation == 2) {
    if (request.arg_count != 1) return kWrongCount;
    const Problem problem = check<double>(request.args[0]);
    if (!problem.ok()) return {problem.code, "bad position"};
    port.reset_deep(as<double>(request.args[0]));
    return {};
  }
  if (request.arg_count != 0) return kWrongCount;
  write_return<double>(reply, operation == 0 ? port.read_absolute() : port.read_deep());
  return {};
}

}  // namespace stepdance::rpc
