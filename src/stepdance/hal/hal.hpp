// The hardware-abstraction facade: the only door from the portable core to time, timers and pins.
//
// The facade is the headers of src/stepdance/hal/, and every function a backend defines is
// declared in one of them:
//   - hal.hpp          time, timers, critical sections, ports, capture, quadrature, ADC, GPIO,
//                      safe state and log
//   - i2c.hpp          the QWIIC I2C buses
//   - console.hpp      the console stream
//   - storage.hpp      file storage
//   - nonvolatile.hpp  the non-volatile byte store
// Exactly one backend defines them, chosen at build time; the three sit side by side under
// src/stepdance/platform/<name>/, each file compiled only under its own switch (so an Arduino
// build, which compiles all of src/, keeps only the Teensy one):
//   - teensy/  i.MX RT1062 (when __IMXRT1062__ is defined)
//   - manual/  unit tests: time and inputs advanced by hand (STEPDANCE_PLATFORM_MANUAL)
//   - sim/     inside a simulated board, through the board ABI (STEPDANCE_PLATFORM_SIM)
// The contracts below are the single statement of each primitive's semantics; backends must not
// relax them, and one conformance suite (tests/hal/conformance/) checks every backend against
// them. No function here allocates or throws.
#pragma once

#include <stdint.h>

#include "stepdance/core/status.hpp"
#include "stepdance/protocol/pulse_decoder.hpp"
#include "stepdance/protocol/signals.hpp"

namespace stepdance::hal {

/// An interrupt handler with no arguments.
using Isr = void (*)();

// ---- Time -------------------------------------------------------------------------------------

/// Microseconds since boot, wrapping at 2^32 (compare with wrap-safe subtraction). Context: any.
uint32_t micros_now();
/// Free-running CPU cycle counter, wrapping at 2^32. Context: any.
uint32_t cycles_now();
/// Rate of cycles_now() in Hz (600 000 000 on a Teensy 4.x at stock speed). Context: any.
uint32_t cycles_per_second();

// ---- Timers -----------------------------------------------------------------------------------

/// Calls on_frame every period_us at the highest application priority. Context: loop.
Status frame_timer_start(uint32_t period_us, Isr on_frame);
/// Calls on_tick every period_us at a priority below the frame timer, so it can never delay a
/// frame. Context: loop.
Status khz_timer_start(uint32_t period_us, Isr on_tick);
/// Stops both timers. Context: any.
void timers_stop();

// ---- Critical sections ------------------------------------------------------------------------

/// Disables interrupts and returns the previous state. Context: any.
uint32_t irq_save();
/// Restores the state irq_save() returned. Context: any.
void irq_restore(uint32_t state);

/// Scope guard: interrupts are off from construction to destruction. Context: any.
class CriticalSection {
 public:
  CriticalSection() : state_(irq_save()) {}
  ~CriticalSection() { irq_restore(state_); }
  CriticalSection(const CriticalSection&) = delete;
  CriticalSection& operator=(const CriticalSection&) = delete;

 private:
  uint32_t state_;
};

// ---- Motion-stream output ports ---------------------------------------------------------------

/// Claims output port `port` (0..3 = A..D) and its STEP/DIR pins. kNoSuchPin if the board lacks
/// it, kBusy if already claimed. Context: loop.
Status port_out_begin(uint8_t port);
/// Hands over the words of the frame just computed. The backend starts shifting them out at the
/// next frame tick, at a fixed phase, 1 µs per bit, STEP and DIR in lock-step. Context: frame ISR.
void port_out_frame(uint8_t port, const protocol::FrameWords& words);

// ---- Motion-stream input ports ----------------------------------------------------------------

/// Receives one captured pulse. Context: the capture ISR of the port.
using PulseSink = void (*)(void* context, const protocol::CapturedPulse& pulse);

/// Claims input port `port` (0..3 = A..D) and starts capturing STEP pulses, sampling DIR at
/// `edge`; every pulse is passed to sink(context, pulse). Calling it again on a claimed port
/// changes the edge and sink. kNoSuchPin if the board lacks the port. Context: loop.
Status port_in_begin(uint8_t port, protocol::DirSampleEdge edge, PulseSink sink, void* context);
/// The capture clock of an input port (derived from the real bus clock). Context: any.
protocol::CaptureClock port_in_clock(uint8_t port);

// ---- Quadrature decoders ----------------------------------------------------------------------

/// Starts hardware decoder `index` (0 = ENC1, 1 = ENC2) counting x4 edges. Context: loop.
Status quadrature_begin(uint8_t index);
/// Current signed count. Context: any.
int32_t quadrature_read(uint8_t index);
/// Overwrites the count. Context: any.
void quadrature_write(uint8_t index, int32_t count);

// ---- Analog inputs ----------------------------------------------------------------------------

/// Starts background conversions of a board pin. kNoSuchPin if the pin has no ADC. Context: loop.
Status adc_begin(uint8_t pin);
/// Latest 10-bit conversion (0..1023) of a started pin. Context: any.
uint16_t adc_read(uint8_t pin);
/// Number of conversions completed on a pin so far (wraps); tells the loop a new value exists.
/// Context: any.
uint32_t adc_sample_count(uint8_t pin);

// ---- Digital pins -----------------------------------------------------------------------------

/// Electrical configuration of a digital pin.
enum class PinMode : uint8_t { kInput, kInputPullup, kInputPulldown, kOutput };

/// Configures a pin. kNoSuchPin if it does not exist. Context: loop.
Status gpio_mode(uint8_t pin, PinMode mode);
/// Reads a pin's level. Context: any.
bool gpio_read(uint8_t pin);
/// Drives an output pin. Context: any.
void gpio_write(uint8_t pin, bool high);

// ---- Fault and log ----------------------------------------------------------------------------

/// Puts every output in its safe state: timers stopped, frames idle, drivers disabled.
/// Called by stepdance::fault(). Context: any.
void enter_safe_state();
/// Reports a fault to the user (serial console, simulator summary). Context: any; must not block.
void log_fault(const char* reason, const char* detail);
/// Prints a line of diagnostics to the console. Context: loop.
void log_message(const char* text);

}  // namespace stepdance::hal
