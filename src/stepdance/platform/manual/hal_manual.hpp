// Test controls of the manual host backend: step time by hand, set inputs, inspect outputs.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <string>

#include "stepdance/hal/hal.hpp"

namespace stepdance::hal_manual {

/// Returns every pin, port, timer and buffer to power-on state; time starts at start_us.
void reset(uint32_t start_us = 0);

/// Like reset(), but the non-volatile store keeps its contents, as flash does across a reset or
/// power cycle.
void reboot(uint32_t start_us = 0);

/// Size of the non-volatile store (a Teensy 4.0's EEPROM emulation).
constexpr size_t kEepromBytes = 1080;
/// The store's bytes, to inspect or corrupt them; and how many writes it has taken since reset.
uint8_t* eeprom_bytes();
uint32_t eeprom_writes();

/// Takes the card slot away (false: open() answers kUnsupported, as on a Teensy 4.0) or gives it
/// back; reset() gives it back.
void set_storage_present(bool present);

/// Runs n frame ticks: each advances time by 40 µs and calls the frame ISR if the frame timer
/// runs; every 25th tick also calls the kilohertz ISR after the frame (if that timer runs).
void run_frames(uint32_t n);
/// Advances time without running any timer (for loop-only tests).
void advance_us(uint32_t us);

/// Each cycles_now() read advances the cycle counter by this much (default 0). The engine
/// reads it twice per frame, so this is the modelled cost of one frame in cycles.
void set_cycles_per_read(uint32_t cycles);

/// True while the frame / kilohertz timer runs.
bool frame_timer_running();
bool khz_timer_running();

/// The last frame handed to an output port, and how many were handed over since reset.
protocol::FrameWords last_frame(uint8_t port);
uint32_t frames_written(uint8_t port);
/// True once port_out_begin() claimed the port.
bool output_claimed(uint8_t port);

/// Delivers a captured pulse to an input port's sink, as its capture ISR would.
/// Returns false if the port was never begun.
bool inject_pulse(uint8_t port, const protocol::CapturedPulse& pulse);
/// The DIR sampling edge an input port was begun with.
protocol::DirSampleEdge input_edge(uint8_t port);

/// Sets a quadrature decoder's count (what the hardware would have counted).
void set_quadrature(uint8_t index, int32_t count);
/// Sets a pin's ADC value (0..1023) and counts one new conversion.
void set_adc(uint8_t pin, uint16_t value);
/// Drives an input pin's level from outside.
void set_pin(uint8_t pin, bool high);
/// A pin's current level and mode.
bool pin_level(uint8_t pin);
hal::PinMode pin_mode(uint8_t pin);

/// True once enter_safe_state() ran; the last fault text logged ("reason: detail").
bool in_safe_state();
const std::string& last_fault_log();

/// Bytes a sketch wrote to the console, and bytes to feed it.
std::string take_console_output();
void feed_console(const std::string& bytes);

/// Highest pin number the manual backend accepts.
constexpr uint8_t kMaxPin = 54;

}  // namespace stepdance::hal_manual
