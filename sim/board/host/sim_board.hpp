// The simulator's side of one board: its timers, its parts (pins, ports, console, buses), how the
// world is wired to it, and the sketch it runs.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "board/abi/board_abi.h"
#include "board/host/board_console.hpp"
#include "board/host/board_firmware.hpp"
#include "board/host/board_i2c.hpp"
#include "board/host/board_pins.hpp"
#include "board/host/board_ports.hpp"
#include "board/host/board_storage.hpp"
#include "board/host/board_wiring.hpp"
#include "board/host/sketch_stop.hpp"
#include "board/host/wire.hpp"
#include "board/loader/board_library.hpp"
#include "common/sim_time.hpp"
#include "kernel/scheduler/periodic_timer.hpp"
#include "kernel/scheduler/scheduler.hpp"
#include "models/i2c_bus.hpp"
#include "models/sd_card.hpp"
#include "stepdance/boards/board.hpp"
#include "stepdance/protocol/pulse_decoder.hpp"

namespace stepdance::sim {

/// How a board runs in virtual time.
struct BoardOptions {
  std::string name = "board";
  /// Offset of this board's frame clock: frames tick at phase + k × 40 µs (boards are not in
  /// lock-step). The kilohertz tick runs half a frame later, at phase + 20 µs + k × 1 ms, so
  /// it never coincides with a frame.
  SimTime frame_phase_ns = 0;
  /// The kilohertz tick's phase on its 1 ms grid instead (ticks at phase + k × 1 ms): set to line
  /// a host board up with an image board's measured clocks. Unset: phase + 20 µs as above.
  std::optional<SimTime> khz_phase_ns;
  /// Set: the sketch reads its encoders as a Teensy image does, from counts latched at
  /// phase + k × the frame period (the backend's sample clock, src/stepdance/platform/teensy/
  /// sample_clock.cpp), from the first such instant after the first frame tick on, until the
  /// frame clock stops. Each instant is an event that latches the counts then (a knob's counts
  /// may be state its timeline events change, not a function of any time). Unset: the counts at
  /// the instant of reading.
  std::optional<SimTime> encoder_sample_phase_ns;
  /// loop() runs every this long (each pass takes no simulated time).
  SimTime loop_period_ns = 200 * kMicrosecond;
  /// Folder behind the board's file storage ("" = no card).
  std::string storage_dir;
  /// Speed and failures of the card (default: instant, never failing).
  SdCardSettings sd_card;
  /// Names the addresses of a crashed sketch's backtrace (null: they stay addresses).
  const BoardSource* board_source = nullptr;
};

/// A fault the board reported through hal::log_fault().
struct BoardFault {
  SimTime time_ns = 0;
  std::string text;  ///< "reason: detail"
};

/// One simulated board. It loads nothing itself: it is given a loaded BoardLibrary, attaches to
/// it, and from power_on() on answers every HAL call of the sketch from simulated state:
///
///   frame timer tick ─► play last frame's words to WireListeners ─► sketch's frame ISR
///   kHz timer tick   ─► sketch's kilohertz ISR
///   loop timer       ─► sketch's loop()
///   capture()        ─► sketch's capture ISR (input ports)
///
/// Everything outside plugs in through wire(terminal, …) (board_wiring.hpp): inputs (encoders,
/// ADC pins, input pins) are pulled from sources when the sketch reads them; outputs (pins,
/// ports) are pushed to listeners when the sketch writes them; I2C devices answer transfers.
///
/// Its parts own their state: BoardConsole (the USB serial), BoardPorts (frames played, pulses
/// captured), BoardPins (digital pins), BoardI2c (the QWIIC buses), BoardStorage (the SD card's
/// files). The board itself keeps the timers, the entry into the sketch, the encoders, the ADC
/// and the readouts of the sketch's counters.
class SimBoard {
 public:
  template <typename T>
  using Source = sim::Source<T>;

  SimBoard(Scheduler& scheduler, BoardOptions options, std::unique_ptr<BoardLibrary> library);
  /// A board whose program is `firmware` (a firmware image on an emulated chip) on the module
  /// `module`: the firmware runs by its own clock and reaches the world through the program side
  /// below.
  SimBoard(Scheduler& scheduler, BoardOptions options, std::unique_ptr<BoardFirmware> firmware,
           const BoardDefinition& module);
  ~SimBoard();
  SimBoard(const SimBoard&) = delete;
  SimBoard& operator=(const SimBoard&) = delete;

  /// Binds the library (or the firmware) to this board. False (with `error`) if the ABI versions
  /// differ or the firmware cannot run here.
  bool attach(std::string& error);
  /// The board's time (ns): the scheduler's, or inside a firmware's execution the firmware's.
  SimTime now() const { return firmware_ ? firmware_->now_ns() : scheduler_.now(); }
  /// The firmware this board runs, or null for a host-compiled sketch.
  const BoardFirmware* firmware() const { return firmware_.get(); }
  /// The board the sketch selected (`#define module_basic`, …), as the board registry
  /// (kinds/board_registry.hpp) has it; the Driver Module until attach().
  const BoardDefinition& definition() const { return *definition_; }
  const std::string& name() const { return options_.name; }

  /// Runs setup() at `time_ns`, then loop() every loop period.
  void power_on(SimTime time_ns);
  /// Called when the simulator had to stop this board's sketch (a crash, exit(), a hang, an
  /// interrupt). The board runs no more sketch code after that, and the scheduler stops.
  void on_sketch_stop(std::function<void(const SketchStop&)> listener) { stop_listener_ = std::move(listener); }
  /// Whether the sketch runs no more: it was stopped, or the run ended inside one of its delays.
  bool frozen() const { return frozen_; }

  // ---- wiring: one call, by terminal (board_wiring.hpp); the board owns none of these ----
  /// The quadrature decoder counts what `counts` says at each read.
  void wire(terminal::Encoder at, Source<int64_t> counts) { connect_encoder(at.index, std::move(counts)); }
  /// The ADC of the pin converts `value` (0..1023).
  void wire(terminal::Analog at, Source<uint16_t> value) { connect_adc(at.pin, std::move(value)); }
  /// An external device drives the input pin.
  void wire(terminal::InputPin at, Source<bool> level) { pins_.connect_input(at.pin, std::move(level)); }
  /// `listener` hears every change the sketch makes to the pin's output.
  void wire(terminal::OutputPin at, PinListener listener) { pins_.on_change(at.pin, std::move(listener)); }
  /// `listener` hears the frames the output port plays.
  void wire(terminal::OutputPort at, WireListener* listener) { ports_.add_listener(at.port, listener); }
  /// `device` answers transfers to its address on the bus.
  void wire(terminal::I2c at, I2cDevice* device) { i2c_.attach(at.bus, at.address, device); }

  /// A STEP pulse reaches input port `port`; call at pulse.fall_ns (when the capture ISR runs).
  void capture(uint8_t port, const ArrivingPulse& pulse);
  /// Calls `listener` at every frame tick, after the previous frame's words were played and
  /// before the sketch's frame ISR runs, with the tick's time.
  void on_frames_played(std::function<void(SimTime)> listener) { tick_listener_ = std::move(listener); }
  /// The run ends at `end_ns`: pulses falling after it are not counted as sent (they are cut
  /// off, like the VCD). Default: never.
  void set_end_time(SimTime end_ns) { end_ns_ = end_ns; }

  /// The USB serial console: what a host sends, what the sketch prints.
  BoardConsole& console() { return console_; }
  const BoardConsole& console() const { return console_; }
  /// The QWIIC buses (a fault can be set on one; their timing is read after the run).
  BoardI2c& i2c() { return i2c_; }
  const BoardI2c& i2c() const { return i2c_; }
  /// The ports: pulses sent and received, which were claimed.
  const BoardPorts& ports() const { return ports_; }

  // ---- observation ----
  /// The level the sketch would read on `pin` now (or that it drives).
  bool pin_level(uint8_t pin) const { return pins_.level(pin, now()); }
  /// Whether the sketch began input port `port` (a firmware image: whether it set the port up).
  bool input_begun(uint8_t port) const {
    return firmware_ ? firmware_->input_port_begun(port) : ports_.input_begun(port);
  }
  /// The board's own counters (frames, overruns, faults, pulses sent, signals carried).
  StepdanceBoardStatsV1 stats() const;
  /// One named counter of one block on the board.
  struct BlockCounter {
    std::string block;  ///< class name and instance, e.g. "OutputPort#0"
    std::string name;
    uint64_t value = 0;
  };
  /// Every block's named counters, in the engine's block order.
  std::vector<BlockCounter> counters() const;
  /// One kind of warning the board's fault path tallied (a source and a reason).
  struct BoardWarning {
    std::string name;    ///< "source: reason", e.g. "Eibotboard: overrun"
    std::string detail;  ///< the first report's detail ("" if it was only counted)
    uint64_t count = 0;
  };
  /// Every kind of warning reported since dance_start(), in the order first seen, then what the
  /// board's card refused ("SD card: full", "SD card: too many open files"; board_storage.hpp).
  std::vector<BoardWarning> warnings() const;
  /// Counter `name` of the block of class `block_class` whose "port" counter is `port` (an
  /// OutputPort or InputPort), or 0 if there is none.
  uint64_t port_counter(const std::string& block_class, uint8_t port, const std::string& name) const;
  /// Faults reported, in order: the first kFaultLogEntries of them, and how many more came.
  static constexpr size_t kFaultLogEntries = 1000;
  const std::vector<BoardFault>& faults() const { return faults_; }
  uint64_t faults_not_logged() const { return faults_not_logged_; }
  bool in_safe_state() const { return safe_state_; }
  /// delay() calls made from an interrupt handler (ignored: they cannot block there).
  uint64_t delays_in_isr() const { return delays_in_isr_; }
  /// Storage calls made from an interrupt handler (refused: storage is loop-only, and the run
  /// fails when there is any).
  uint64_t storage_calls_in_isr() const { return storage_calls_in_isr_; }
  /// The card's timing model (bytes written, stalls).
  const SdCardTiming& sd_card() const { return sd_timing_; }

  // ---- program side: what the sketch's HAL calls (through the board ABI) and a firmware's
  // peripherals reach. Times are now(). ----
  /// Configures `pin` (a StepdancePinMode); kBadArgument for a pin the board lacks.
  int set_pin_mode(uint8_t pin, int mode) { return pins_.set_mode(pin, mode, now()); }
  void write_pin(uint8_t pin, bool high) { pins_.write(pin, high, now()); }
  /// The encoder's raw quadrature count (no offset) on ENC `index` (0 or 1).
  int64_t encoder_counts(uint8_t index) const;
  /// The analog level on `pin`, 0..1023 (0 with nothing connected).
  uint16_t analog_level(uint8_t pin) const;
  /// One transfer on QWIIC bus `bus` now (BoardI2c::transfer).
  int i2c_transfer(uint8_t bus, uint8_t address, const uint8_t* write, size_t write_length, uint8_t* read,
                   size_t read_length, int64_t* wire_ns) {
    return i2c_.transfer(bus, address, write, write_length, read, read_length, now(), wire_ns);
  }
  /// The sketch writes `length` bytes to its console now; all are taken.
  size_t write_console(const uint8_t* data, size_t length) { return console_.write(data, length, now()); }
  /// Output port `port` plays `words` from `start_ns`; its next frame starts `frame_ns` later
  /// (a firmware's frame clock: a host-compiled sketch's frames are played by the board's own
  /// frame timer). Idle words reach only the listeners that want idle frames.
  void play_frame(uint8_t port, SimTime start_ns, const protocol::FrameWords& words, SimTime frame_ns);

 private:
  friend struct BoardCallbacks;
  static constexpr uint8_t kPorts = BoardPorts::kPorts;
  static constexpr uint8_t kPins = kTeensy41.highest_pin + 1;  ///< the largest Teensy's pins

  struct AdcState {
    Source<uint16_t> value;
    bool begun = false;
    SimTime begun_at = 0;
  };
  /// The loop pass: an event that requeues itself only after loop() returns, so a delay()
  /// inside loop() can never re-enter it.
  struct LoopEvent : Event {
    explicit LoopEvent(SimBoard& board) : Event(&fire), owner(board) {}
    static void fire(Event& event, Scheduler& scheduler);
    SimBoard& owner;
  };
  struct SetupEvent : Event {
    explicit SetupEvent(SimBoard& board) : Event(&fire), owner(board) {}
    static void fire(Event& event, Scheduler& scheduler);
    SimBoard& owner;
  };
  /// The quadrature decoder `index` (0 = ENC1) counts what `counts` says at each read.
  void connect_encoder(uint8_t index, Source<int64_t> counts);
  /// The ADC of `pin` converts `value` (0..1023).
  void connect_adc(uint8_t pin, Source<uint16_t> value);
  void add_storage_warnings(std::vector<BoardWarning>& out) const;

  /// Runs one entry point of the sketch (`call` returns its code) unless the board is frozen;
  /// an escape freezes it and, for anything but the end of the run, reports the stop.
  template <typename Call>
  void enter(SketchEntry entry, Call call);
  void escaped(SketchEntry entry);

  static void frame_tick(void* context, SimTime time);
  static void khz_tick(void* context, SimTime time);
  void firmware_stopped(const SketchStop& stop);
  SimTime next_aligned(SimTime offset_ns, SimTime period_ns) const;
  /// The counts an encoder read sees now: the last latched sample while sampling, else live.
  int64_t encoder_counts_seen(uint8_t index) const;
  static void encoder_sample(void* context, SimTime time);

  // HAL answers (called through BoardCallbacks).
  int start_timer(int timer_id, uint32_t period_us);
  void stop_timers();
  void delay(SimTime duration_ns);
  /// True once the run has reached its end or was stopped: a delay() must not return to the
  /// sketch then.
  bool run_is_over() const;
  int32_t read_quadrature(uint8_t index);
  void write_quadrature(uint8_t index, int32_t count);
  uint32_t adc_samples(uint8_t pin) const;
  void enter_safe_state();
  int storage_write(int handle, const uint8_t* data, size_t length);
  int storage_read(int handle, uint8_t* data, size_t length, size_t* read);
  bool storage_refused_in_isr();

  Scheduler& scheduler_;
  BoardOptions options_;
  std::unique_ptr<BoardLibrary> library_;
  std::unique_ptr<BoardFirmware> firmware_;  ///< set instead of library_ for a firmware board
  const StepdanceBoardV1* board_ = nullptr;
  const BoardDefinition* definition_ = &kDriverModuleV1;
  std::unique_ptr<StepdanceHostV1> host_table_;
  PeriodicTimer frame_timer_;
  PeriodicTimer khz_timer_;
  PeriodicTimer encoder_sampler_;  ///< BoardOptions::encoder_sample_phase_ns
  bool encoders_sampled_ = false;  ///< the sampler has latched since it started
  std::array<int64_t, 2> encoder_samples_{};
  LoopEvent loop_event_;
  SetupEvent setup_event_;
  bool in_isr_ = false;
  bool safe_state_ = false;
  BoardConsole console_;
  BoardPorts ports_;
  BoardPins pins_;
  std::array<AdcState, kPins> adcs_{};
  std::array<Source<int64_t>, 2> encoders_{};
  std::array<int64_t, 2> encoder_offsets_{};
  BoardI2c i2c_;
  BoardStorage storage_;
  std::vector<BoardFault> faults_;
  uint64_t faults_not_logged_ = 0;
  uint64_t delays_in_isr_ = 0;
  SdCardTiming sd_timing_;
  uint64_t storage_calls_in_isr_ = 0;
  std::function<void(SimTime)> tick_listener_;
  SimTime last_played_tick_ns_ = -1;  ///< a firmware's last launch time told to tick_listener_
  SimTime end_ns_ = INT64_MAX;
  bool frozen_ = false;
  std::function<void(const SketchStop&)> stop_listener_;
};

}  // namespace stepdance::sim
