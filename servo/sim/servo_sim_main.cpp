// servo_sim_main.cpp: runs the servo driver firmware ELF on simavr against the harness scenarios.
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "expectations.h"
#include "report.h"
#include "scenarios.h"

namespace {

void print_usage(const char* program) {
  std::cerr << "usage: " << program
            << " FIRMWARE.elf [--top-limit-steps N] [--bottom-limit-steps N]"
               " [--neutral-width-us N] [--period-us N] [--position-symbol NAME]\n";
}

// Fills expect from argv; false on a malformed command line.
bool parse_arguments(int argc, char** argv, servo_sim::Expectations& expect) {
  if (argc < 2) {
    return false;
  }
  expect.elf_path = argv[1];
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string option = argv[i];
    const std::string value = argv[i + 1];
    if (option == "--position-symbol") {
      expect.position_symbol = value;
      continue;
    }
    const int number = std::stoi(value);
    if (option == "--top-limit-steps") {
      expect.top_limit_steps = number;
    } else if (option == "--bottom-limit-steps") {
      expect.bottom_limit_steps = number;
    } else if (option == "--neutral-width-us") {
      expect.neutral_width_us = number;
    } else if (option == "--period-us") {
      expect.period_us = number;
    } else {
      return false;
    }
  }
  return argc % 2 == 0;
}

}  // namespace

int main(int argc, char** argv) {
  servo_sim::Expectations expect;
  try {
    if (!parse_arguments(argc, argv, expect)) {
      print_usage(argv[0]);
      return 2;
    }
  } catch (const std::exception&) {
    print_usage(argv[0]);
    return 2;
  }
  std::cout << "servo firmware " << expect.elf_path << ": window [" << expect.bottom_limit_steps << ", "
            << expect.top_limit_steps << "] steps, neutral " << expect.neutral_width_us << " us, period "
            << expect.period_us << " us\n"
            << "note: Debian's simavr 1.6 does not drive the OC1B pin (PA5) in Timer1 fast PWM mode 14, and\n"
            << "      its internal compare-B output ignores OCR1B writes after start-up; the pulse is\n"
            << "      therefore checked through the OCR1B and ICR1 registers (and the compare-B output\n"
            << "      only at start-up).\n";

  servo_sim::Report report;
  try {
    servo_sim::scenario_start_up(expect, report);
    servo_sim::scenario_stepdance_stream(expect, report);
    servo_sim::scenario_direction_changes(expect, report);
    servo_sim::scenario_dir_sampled_at_rising_edge(expect, report);
    servo_sim::scenario_clamp_beyond_window(expect, report);
    servo_sim::scenario_step_edges_during_position_read(expect, report);
    servo_sim::scenario_every_signal_width(expect, report);
  } catch (const std::exception& error) {
    std::cout << "  FAIL: " << error.what() << '\n';
    return 1;
  }
  if (report.failures() != 0) {
    std::cout << report.failures() << " check(s) failed\n";
    return 1;
  }
  std::cout << "all checks passed\n";
  return 0;
}
