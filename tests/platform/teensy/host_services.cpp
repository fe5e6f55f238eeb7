// The HAL log functions the model tests need, kept in memory (the backend's log.cpp writes to
// Teensyduino's USB serial, which the host does not have).
#include "stepdance/hal/hal.hpp"

namespace stepdance::hal {

void log_message(const char*) {}
void log_fault(const char*, const char*) {}

}  // namespace stepdance::hal
