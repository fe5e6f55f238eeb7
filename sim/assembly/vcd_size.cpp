// The VCD's size estimate and its refusal text.
#include "assembly/vcd_size.hpp"

#include <cmath>
#include <cstdio>

namespace stepdance::sim {

double estimate_vcd_bytes(size_t ports, SimTime duration) {
  return static_cast<double>(ports) * kVcdBytesPerPortSecond * to_seconds(duration);
}

std::string vcd_size_problem(const std::string& path, size_t ports, SimTime duration, uint64_t max_bytes) {
  const double estimate = estimate_vcd_bytes(ports, duration);
  if (estimate <= static_cast<double>(max_bytes)) return "";
  char text[600];
  std::snprintf(text, sizeof text,
                "%s: the VCD could reach %.2f GB (%zu port(s) × at most %.3f MB per simulated second × %.0f s), "
                "above the cap of %.2f GB: raise it with --vcd-max-gb %.0f, shorten the run, list fewer "
                "vcd_ports, or leave the VCD out with --no-vcd",
                path.c_str(), estimate / 1e9, ports, kVcdBytesPerPortSecond / 1e6, to_seconds(duration),
                static_cast<double>(max_bytes) / 1e9, std::ceil(estimate / 1e9));
  return text;
}

}  // namespace stepdance::sim
