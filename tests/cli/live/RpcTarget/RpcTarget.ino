// Test fixture for the RPC client tests: names no example enrolls, a planner and a parameter.
#define module_driver
#include "stepdance.hpp"

RPC rpc;
TimeBasedInterpolator tbi;
double level = 0.25;
int blinks = 0;

void blink() { ++blinks; }
int blink_count() { return blinks; }
double scale(double value, double factor) { return value * factor; }
const char* label(const char* text) { return text; }

void setup() {
  tbi.begin();
  rpc.begin(&Serial);
  rpc.enroll("blink", blink);
  rpc.enroll("blink_count", blink_count);
  rpc.enroll("scale", scale);
  rpc.enroll("label", label);
  rpc.enroll("level", level);
  rpc.enroll("tbi", tbi);
  dance_start();
}

void loop() { dance_loop(); }
