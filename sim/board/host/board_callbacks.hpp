// The host half of the board ABI: C callbacks that forward a sketch's HAL calls to its SimBoard.
#pragma once

#include "board/abi/board_abi.h"

namespace stepdance::sim {

/// Builds the StepdanceHostV1 table every SimBoard hands to its library. Each callback casts
/// its context back to the SimBoard and answers from simulated state.
struct BoardCallbacks {
  static StepdanceHostV1 table();

 private:
  static void add_timer_callbacks(StepdanceHostV1& host);    ///< timers, delay()
  static void add_port_callbacks(StepdanceHostV1& host);     ///< output and input ports
  static void add_input_callbacks(StepdanceHostV1& host);    ///< quadrature, ADC, GPIO
  static void add_console_callbacks(StepdanceHostV1& host);  ///< faults, console, storage
  static void add_i2c_callbacks(StepdanceHostV1& host);      ///< the QWIIC buses
  static void add_end_callback(StepdanceHostV1& host);       ///< exit() and abort() in a sketch
};

}  // namespace stepdance::sim
