// Names for Status codes.
#include "stepdance/core/status.hpp"

namespace stepdance {

const char* to_string(Status status) {
  switch (status) {
    case Status::kOk: return "ok";
    case Status::kFull: return "full";
    case Status::kEmpty: return "empty";
    case Status::kBadArgument: return "bad argument";
    case Status::kNoSuchPin: return "no such pin";
    case Status::kBusy: return "busy";
    case Status::kNotStarted: return "not started";
    case Status::kUnsupported: return "unsupported";
    case Status::kIoError: return "i/o error";
  }
  return "unknown";
}

}  // namespace stepdance
