// InputPort: decodes a motion stream received on an input port into six axis BlockPorts.
#pragma once

#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/protocol/pulse_decoder.hpp"
#include "stepdance/protocol/signals.hpp"

namespace stepdance {

/// Input port selectors (the PCB's INPUT A..D). The two legacy names of the original's
/// "wheelprint" boards are kept so old sketches compile; no current board has them, so
/// begin() refuses them with Status::kNoSuchPin.
enum InputPortId : uint8_t {
  INPUT_A = 0,
  INPUT_B = 1,
  INPUT_C = 2,
  INPUT_D = 3,
  INPUT_B_LEGACY = 4,
  INPUT_C_LEGACY = 5,
};
constexpr uint8_t NUM_AVAILABLE_INPUT_PORTS = 4;

/// A motion-stream input port.
///
///   capture ISR ──► decode_pulse ──► int32 counter per signal (ISR writes, nobody else)
///   frame, input-port stage ──► one snapshot per counter ──► Δ = snapshot − previous snapshot
///                           ──► output_<axis>.set(Δ pulses, INCREMENTAL) ──► push()
///
/// Every received pulse reaches the BlockPorts exactly once: a pulse that lands after a frame's
/// snapshot is part of the next frame's Δ (the original re-read a double the ISR was still
/// writing and could drop pulses). Block units are pulses; set_ratio() gives world units.
/// Rejected pulses are counted by reason, and pulses of disabled signals are counted as ignored.
class InputPort : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "InputPort"; }
  InputPort();
  ~InputPort() { detach(); }

  /// Claims input port `port` (INPUT_A..INPUT_D) on the active board, enables all six signals
  /// and registers in the input-port stage. kNoSuchPin if the board has no such port (the Basic
  /// Module only has INPUT_A). Context: loop.
  Status begin(uint8_t port);

  /// Chooses how pulses are decoded. INPUT_MODE_STEPDANCE (default): axis by pulse width, DIR
  /// sampled at the STEP falling edge. INPUT_MODE_STEP_DIR: every pulse longer than 0.5 µs (it
  /// rounds to ≥ 1 µs), however long, is one step of `step_dir_signal`, DIR sampled at the STEP
  /// rising edge, for ordinary step/dir sources.
  /// After begin() it re-arms the capture with the edge the mode needs. kBadArgument if
  /// step_dir_signal is not SIGNAL_X..SIGNAL_E. Context: loop.
  Status set_input_mode(InputMode mode, uint8_t step_dir_signal = SIGNAL_X);
  /// The current decoding mode. Context: any.
  InputMode input_mode() const { return mode_; }

  /// Lets every signal through. Context: any.
  void enable_all_signals() { enabled_mask_ = kAllSignalsMask; }
  /// Ignores every signal (pulses are still counted by ignored()). Context: any.
  void disable_all_signals() { enabled_mask_ = 0; }
  /// Lets signal `signal` (SIGNAL_X..SIGNAL_E) through; other values are ignored. Context: any.
  void enable_signal(uint8_t signal);
  /// Ignores signal `signal` (SIGNAL_X..SIGNAL_E); other values are ignored. Context: any.
  void disable_signal(uint8_t signal);
  /// True while signal `signal` is let through. Context: any.
  bool signal_enabled(uint8_t signal) const;

  /// world_units per `pulses` received, on all six BlockPorts (e.g. set_ratio(0.01) for the
  /// standard 0.01 mm per pulse). Each port can still be given its own ratio afterwards.
  /// Context: loop.
  void set_ratio(double world_units, double pulses = 1.0);

  /// Accepted pulses of an enabled signal in one direction (DIRECTION_FORWARD / _REVERSE)
  /// since begin(). Context: any.
  uint32_t pulses_received(uint8_t signal, uint8_t direction) const;
  /// Pulses rejected for being shorter than the mode accepts (noise, glitches). Context: any.
  uint32_t rejected_too_short() const { return rejected_too_short_; }
  /// Pulses rejected for being longer than the widest signal (STEPDANCE mode), however long:
  /// the backends measure pulses past the capture counter's wrap. Context: any.
  uint32_t rejected_too_long() const { return rejected_too_long_; }
  /// Accepted pulses of disabled signals, which were not passed on. Context: any.
  uint32_t ignored() const { return ignored_; }
  /// The port index (0..3), or 255 before begin(). Context: any.
  uint8_t port_index() const { return port_; }
  /// port, received_<signal>_<forward|reverse>, rejected_too_short, rejected_too_long, ignored.
  /// Context: loop.
  void report_counters(CounterSink& sink) const override;

  /// The BlockPort of one signal (SIGNAL_X..SIGNAL_E); SIGNAL_X's for other values.
  /// Context: any.
  BlockPort& output(uint8_t signal);

  /// Frame work: hands the pulses counted since the last frame to the BlockPorts.
  /// Called by the engine in the input-port stage. Context: frame ISR.
  void run() override { hand_off_pulses(); }

  /// Decodes one captured pulse and counts it. Called by the port's capture ISR through the
  /// HAL (public so a backend or test may feed pulses directly). Context: capture ISR.
  void receive_pulse(const protocol::CapturedPulse& pulse);

  BlockPort output_x;  ///< 2 µs pulses
  BlockPort output_y;  ///< 3 µs pulses
  BlockPort output_r;  ///< 4 µs pulses
  BlockPort output_t;  ///< 5 µs pulses (θ)
  BlockPort output_z;  ///< 6 µs pulses
  BlockPort output_e;  ///< 7 µs pulses

 private:
  // Virtuals stay inline (no key function), so RTTI-built code can use this class although
  // the core is built with -fno-rtti (see Block).
  Status arm_capture();
  void detach();
  void hand_off_pulses();

  BlockPort* const outputs_[kNumSignals];
  DecimalPosition positions_pulses_[kNumSignals] = {};
  // Net pulse count per signal: written only by the capture ISR, read once per frame.
  volatile int32_t counts_[kNumSignals] = {};
  int32_t counts_seen_[kNumSignals] = {};
  volatile uint32_t received_[kNumSignals][2] = {};
  volatile uint32_t rejected_too_short_ = 0;
  volatile uint32_t rejected_too_long_ = 0;
  volatile uint32_t ignored_ = 0;
  volatile uint8_t enabled_mask_ = kAllSignalsMask;
  volatile InputMode mode_ = INPUT_MODE_STEPDANCE;
  volatile uint8_t step_dir_signal_ = SIGNAL_X;
  uint8_t port_ = 255;
};

}  // namespace stepdance
