// OutputPort: collects each frame's signals, encodes them and hands the frame to the hardware.
#pragma once

#include <stdint.h>

#include "stepdance/boards/board.hpp"
#include "stepdance/core/block.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/protocol/frame_encoder.hpp"
#include "stepdance/protocol/signals.hpp"

namespace stepdance {

/// Output port selectors (the PCB's OUTPUT A..D).
enum OutputPortId : uint8_t { OUTPUT_A = 0, OUTPUT_B = 1, OUTPUT_C = 2, OUTPUT_D = 3 };
constexpr uint8_t OUTPUT_A_LEGACY = OUTPUT_A;
constexpr uint8_t OUTPUT_B_LEGACY = OUTPUT_B;
constexpr uint8_t NUM_AVAILABLE_OUTPUT_PORTS = 4;

/// Transmission formats (OUTPUT_FRAME_32US … OUTPUT_FRAME_4US) are in protocol/frame_format.hpp.
/// Whether the engine transmits the port every frame, or the sketch calls transmit_frame().
enum OutputTransmitMode : uint8_t { OUTPUT_TRANSMIT_ON_FRAME = 1, OUTPUT_TRANSMIT_MANUAL = 2 };
/// How a port puts pulses on its lines.
enum OutputMode : uint8_t {
  /// Width-coded multiplex of up to six signals (X 2 µs … E 7 µs), DIR a per-pulse qualifier.
  /// For Stepdance input ports and boards. The default.
  OUTPUT_MODE_STEPDANCE = 0,
  /// One signal as plain step/dir: 2 µs pulses 2 µs apart, several per frame when pending,
  /// DIR high over a frame's forward pulses with 1 µs setup and hold. For ordinary stepper
  /// drivers and INPUT_MODE_STEP_DIR inputs.
  OUTPUT_MODE_STEP_DIR = 1,
};

/// A motion-stream output port. Channels queue at most one pulse per signal per frame with
/// add_signal(); every frame the port encodes its pending pulses (protocol/frame_encoder) and
/// hands the words to the HAL. A pulse that does not fit is carried to the next frame and
/// counted; a forward and a reverse pulse still pending on one signal cancel (net position kept).
class OutputPort : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "OutputPort"; }
  OutputPort() = default;
  ~OutputPort() { forget(this); }

  /// Claims the port on the active board and transmits every frame, in the widest format that
  /// fits the frame period dance_start() runs (OUTPUT_FRAME_32US at 40 µs). kNoSuchPin if the
  /// board has no such port. Context: loop.
  Status begin(uint8_t port);
  /// The original's full form: a fixed transmission format (OUTPUT_FRAME_32US/16US/8US/4US) and
  /// OUTPUT_TRANSMIT_ON_FRAME or OUTPUT_TRANSMIT_MANUAL. A format that does not end before the
  /// chosen frame period does (e.g. OUTPUT_FRAME_32US in a 20 µs frame), an unknown format or
  /// transmit mode is refused on the fault path (kBadConfiguration) with kBadArgument, and
  /// dance_start() then refuses to start. Context: loop.
  Status begin(uint8_t port, uint8_t format, uint8_t transmit_mode);
  /// Chooses the line code (see OutputMode). In OUTPUT_MODE_STEP_DIR only `step_dir_signal` is
  /// sent; a pulse added on another signal is refused, counted (pulses_refused()) and reported
  /// once as a warning. Pending pulses are kept. kBadArgument for an unknown mode or signal.
  /// Context: loop.
  Status set_output_mode(OutputMode mode, uint8_t step_dir_signal = SIGNAL_X);
  /// The current line code. Context: any.
  OutputMode output_mode() const { return mode_; }
  /// Where the port puts its signals in a frame: the fixed format's layout, or for begin(port)
  /// the whole frame of the period dance_start() runs. Context: any.
  const protocol::FrameLayout& layout() const { return layout_; }
  /// True if `signal` fits a frame of this port at `period_us` (in OUTPUT_MODE_STEP_DIR: if it is
  /// the port's signal). Channels check it at dance_start(). Context: loop.
  bool can_carry(uint8_t signal, uint32_t period_us) const;
  /// Fixes the layout for the period the engine is about to run; refuses (fault path) a fixed
  /// format that does not end before the frame does. Context: loop.
  bool accept_frame_period(uint32_t period_us) override;

  /// Queues one pulse of `signal` (0..5) in `direction` (DIRECTION_FORWARD/REVERSE).
  /// Context: frame ISR (channels), or loop while the engine is stopped.
  void add_signal(uint8_t signal, uint8_t direction);
  /// Queues one pulse for the next frame (the original sent it at once and could collide with
  /// a frame on the wire). Context: any.
  void step_now(uint8_t direction, uint8_t signal = SIGNAL_E);
  /// Encodes the pending pulses and hands the frame to the HAL: by the sketch in manual mode,
  /// at most once a frame while the engine runs (a second frame in one period would overlap
  /// the first on the wire). An OUTPUT_TRANSMIT_ON_FRAME port is sent by the engine's output
  /// stage, so while the engine runs the sketch's call is ignored. An ignored call is counted
  /// (transmits_refused()) and the first one reported as a warning. With the engine stopped,
  /// every call sends a frame. Context: frame ISR, or loop while the engine is stopped.
  void transmit_frame();
  /// The engine's output stage: the frame of an OUTPUT_TRANSMIT_ON_FRAME port. Context: frame ISR.
  void run() override { transmit_once_this_frame(); }
  /// OUTPUT_TRANSMIT_ON_FRAME or OUTPUT_TRANSMIT_MANUAL, as begun. Context: any.
  uint8_t transmit_mode() const { return transmit_mode_; }
  /// Calls of transmit_frame() ignored because the port had sent, or the engine sends, this
  /// frame's frame. Context: any.
  uint32_t transmits_refused() const { return transmits_refused_; }

  /// Drives the driver's ENABLE low (enabled). kNoSuchPin on a board without drivers.
  /// Context: loop.
  Status enable_driver();
  /// Drives ENABLE high (disabled). kNoSuchPin on a board without drivers. Context: any.
  Status disable_driver();
  /// Disables the driver once the port has sent nothing for `ms` milliseconds, and enables it
  /// again the frame motion comes back (its first pulse plays the frame after, one period later),
  /// as Grbl's $1 step idle delay does; 0 (the default) keeps the driver as the sketch left it.
  /// Only a driver the sketch enabled is idled; disable_driver() stays in force. Context: any.
  void set_driver_idle_timeout_ms(uint32_t ms);
  /// True while the idle timeout holds the driver disabled. Context: any.
  bool driver_idle() const { return idle_disabled_; }
  /// Amps per volt of VREF for the fitted driver (1.0 for BigTreeTech TMC2209). Context: any.
  void set_drive_current_gain(float amps_per_volt) { current_gain_a_per_v_ = amps_per_volt; }
  /// Driver peak current in amps from the VREF read-back; −1 if the board has no VREF pin.
  /// The first call starts the conversions. Context: loop.
  float read_drive_current_amps();
  float read_drive_current_amps(float amps_per_volt);
  /// True while the port's limit switch is active (input high). False without a limit pin.
  /// Context: any.
  bool read_limit_switch();

  /// Pulses placed on the wire for a signal in one direction since begin. Context: any.
  uint32_t pulses_sent(uint8_t signal, uint8_t direction) const;
  /// Signal-frames deferred because the frame was full (each deferral counts once).
  uint32_t signals_carried() const { return signals_carried_; }
  /// Pulses refused because the port cannot carry their signal: another signal than the one of
  /// OUTPUT_MODE_STEP_DIR, or one too wide for the frame (E in OUTPUT_FRAME_8US).
  uint32_t pulses_refused() const { return pulses_refused_; }
  /// port (its index), carried, and sent_<signal>_<forward|reverse> for x, y, r, t, z, e.
  /// Context: loop.
  void report_counters(CounterSink& sink) const override;
  /// Net pulses still waiting for a frame on a signal (+ forward, − reverse).
  int32_t pending(uint8_t signal) const { return signal < kNumSignals ? pending_[signal] : 0; }
  /// Forgets pending pulses and zeroes the statistics (begin() does this). Context: loop.
  void clear_statistics();
  /// The port index (0..3), or 255 before begin().
  uint8_t port_index() const { return port_; }
  /// "OUTPUT A" .. "OUTPUT D".
  const char* port_name = "OUTPUT ?";

 private:
  // Inline destructor: no key function, so RTTI-built code can use OutputPort (see Block).
  static void forget(OutputPort* port);
  // A physical port has one owner: a second begin() on the same port retires the first object.
  void release_previous_owner(uint8_t port);
  const OutputPortPins* pins() const;
  // begin()'s common part, after the format and transmit mode were checked.
  Status claim(uint8_t port, uint8_t format, uint8_t transmit_mode);
  // Takes the pulses just placed on the wire off the pending counts and into the statistics.
  void account_sent(uint8_t sent_mask);
  // Counts a pulse the port cannot carry; the first one is reported. Context: any.
  void refuse_pulse();
  // Sends the frame unless this port already sent one in the engine's current frame. Frame ISR.
  void transmit_once_this_frame();
  // Counts a transmit_frame() call that would have sent a second frame; the first is reported.
  void refuse_transmit();
  // Every change of a pending count goes through here, so the masks always match the counts.
  void set_pending(uint8_t signal, int32_t count);

  // Frame context: the two line codes.
  protocol::FrameWords encode_stepdance();
  protocol::FrameWords encode_step_dir();

  uint8_t port_ = 255;
  static constexpr uint8_t kFormatForPeriod = 255;  // begin(port): the widest that fits
  uint8_t requested_format_ = kFormatForPeriod;
  protocol::FrameLayout layout_ = protocol::kLayout32Us;
  volatile OutputMode mode_ = OUTPUT_MODE_STEPDANCE;
  uint8_t step_dir_signal_ = SIGNAL_X;
  uint32_t pulses_refused_ = 0;
  uint8_t transmit_mode_ = OUTPUT_TRANSMIT_ON_FRAME;
  uint32_t transmits_refused_ = 0;
  bool transmitted_ = false;           // a frame has gone out while the engine ran …
  uint32_t transmitted_in_frame_ = 0;  // … in this engine frame (Engine::frame_count())
  uint8_t carried_mask_ = 0;
  volatile int32_t pending_[kNumSignals] = {};
  // Signals with a non-zero / positive pending count: the frame reads these instead of scanning.
  volatile uint8_t pending_mask_ = 0;
  volatile uint8_t forward_mask_ = 0;
  uint32_t sent_[kNumSignals][2] = {};
  uint32_t signals_carried_ = 0;
  void idle_check(bool moving);
  void write_enable_pin(bool enabled);
  volatile uint32_t idle_timeout_ms_ = 0;  // 0: off
  uint64_t idle_us_ = 0;
  volatile bool driver_enabled_ = false;  // by the sketch (enable_driver)
  volatile bool idle_disabled_ = false;
  float current_gain_a_per_v_ = 1.0f;
  bool vref_started_ = false;
};

/// Transmits the frames of the begun ports the engine does not send itself: the
/// OUTPUT_TRANSMIT_MANUAL ones while the engine runs (the engine's output stage sends the
/// OUTPUT_TRANSMIT_ON_FRAME ones), every begun port while it is stopped. Each port still sends at
/// most one frame per engine frame. Context: frame ISR, or loop while the engine is stopped.
void transmit_frames_on_all_output_ports();
/// Calls fn for every begun output port. Context: loop.
void iterate_across_all_output_ports(void (*fn)(OutputPort* port));
/// Enables / disables the drivers of every begun port. kNoSuchPin on a board without drivers.
/// Context: loop.
Status enable_drivers();
Status disable_drivers();
/// set_driver_idle_timeout_ms(ms) on every begun port (0 = off). Context: loop.
void set_drivers_idle_timeout_ms(uint32_t ms);

}  // namespace stepdance
