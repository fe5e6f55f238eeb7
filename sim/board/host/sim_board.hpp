// The simulator's side of one board: its timers, pins, ports and console, and the sketch it runs.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "board/abi/board_abi.h"
#include "board/host/board_firmware.hpp"
#include "board/host/board_storage.hpp"
#include "board/host/frame_pulses.hpp"
#include "board/host/wire.hpp"
#include "common/sim_time.hpp"
#include "board/loader/board_library.hpp"
#include "models/i2c_bus.hpp"
#include "models/sd_card.hpp"
#include "kernel/scheduler/periodic_timer.hpp"
#include "board/host/sketch_stop.hpp"
#include "kernel/scheduler/scheduler.hpp"
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
/// Inputs (encoders, ADC pins, input pins) are pulled from sources when the sketch reads them;
/// outputs (pins) are pushed to listeners when the sketch writes them.
class SimBoard {
 public:
  /// A source of a value as a function of simulated time.
  template <typename T>
  using Source = std::function<T(SimTime)>;
  /// Told when an output pin changes: (time, level, whether the pin is driven as an output).
  using PinListener = std::function<void(SimTime, bool level, bool driven)>;

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

  // ---- wiring: the world feeding the board ----
  /// The quadrature decoder `index` (0 = ENC1) counts what `counts` says at each read.
  void connect_encoder(uint8_t index, Source<int64_t> counts);
  /// The ADC of `pin` converts `value` (0..1023).
  void connect_adc(uint8_t pin, Source<uint16_t> value);
  /// An external device drives input pin `pin`.
  void connect_input_pin(uint8_t pin, Source<bool> level);
  /// Calls `listener` whenever the sketch changes pin `pin`'s output.
  void on_pin_change(uint8_t pin, PinListener listener);
  /// Adds a listener of output port `port`'s wire (the board does not own it).
  void add_wire_listener(uint8_t port, WireListener* listener);
  /// Plugs `device` into QWIIC bus `bus` (0 or 1) at 7-bit `address` (the board does not own it).
  void attach_i2c_device(uint8_t bus, uint8_t address, I2cDevice* device) { i2c_[bus].model.attach(address, device); }
  /// Breaks or mends bus `bus` (fault scenarios and tests).
  void set_i2c_fault(uint8_t bus, I2cBusFault fault) { i2c_[bus].model.set_fault(fault); }
  /// A STEP pulse reaches input port `port`; call at pulse.fall_ns (when the capture ISR runs).
  void capture(uint8_t port, const ArrivingPulse& pulse);
  /// Calls `listener` at every frame tick, after the previous frame's words were played and
  /// before the sketch's frame ISR runs, with the tick's time.
  void on_frames_played(std::function<void(SimTime)> listener) { tick_listener_ = std::move(listener); }
  /// The run ends at `end_ns`: pulses falling after it are not counted as sent (they are cut
  /// off, like the VCD). Default: never.
  void set_end_time(SimTime end_ns) { end_ns_ = end_ns; }
  /// The board's USB serial receive buffer: a Teensy 4 holds 8 packets of 512 bytes
  /// (teensy4/usb_serial.c in PJRC's cores); a host cannot get further ahead of the sketch.
  static constexpr size_t kConsoleInputBytes = 8 * 512;
  /// What the sketch printed is kept for inspection up to this much (the newest; older is dropped
  /// and counted; a one-hour soak's status replies made a megabyte of it), and a line longer than
  /// kConsoleLineBytes is handed on in pieces.
  static constexpr size_t kConsoleTextBytes = 64 * 1024;
  static constexpr size_t kConsoleLineBytes = 4096;
  /// A line left unfinished this long (simulated) is handed on as it is.
  static constexpr SimTime kConsoleQuietNs = 100 * kMillisecond;

  /// Queues bytes for the sketch's Serial input (scripted senders: the scenario bounds them).
  void send_console(const std::string& bytes);
  /// Room left in the receive buffer: a live terminal is read no further than this, so a host
  /// writing faster than the sketch reads is held back, as by a real board's USB.
  size_t console_input_room() const;
  /// Counts console bytes a live terminal dropped because nobody read them (the summary's
  /// console entry reports them).
  void count_console_dropped(uint64_t bytes) { console_dropped_bytes_ += bytes; }
  uint64_t console_dropped_bytes() const { return console_dropped_bytes_; }
  /// Bytes of console_text() dropped to keep it within kConsoleTextBytes.
  uint64_t console_text_dropped_bytes() const { return console_text_dropped_; }
  /// Calls `listener` with every complete line the sketch prints (without the line ending).
  void on_console_line(std::function<void(const std::string&)> listener);
  /// Hands the line the sketch has begun but not ended to the line listener (at the run's end,
  /// or after a quiet while), as if it had ended.
  void flush_console_line();
  /// Calls `listener` with the sketch's console bytes as they are written, unchanged (the live
  /// simulator forwards them to a pseudo-terminal).
  void on_console_bytes(std::function<void(const uint8_t*, size_t)> listener);

  // ---- observation ----
  /// The level the sketch would read on `pin` now (or that it drives).
  bool pin_level(uint8_t pin) const;
  /// Pulses the board played on output port `port` (decoded from the wire).
  const PulseCounts& sent(uint8_t port) const { return ports_[port].sent; }
  /// Pulses that reached input port `port`, decoded as the port's mode does (STEP_DIR-mode
  /// steps are tallied under SIGNAL_X: the host cannot see which signal the sketch chose).
  const PulseCounts& received(uint8_t port) const { return ports_[port].received; }
  /// Pulses that reached an input port no InputPort had begun (they went nowhere).
  uint64_t unclaimed_pulses(uint8_t port) const { return ports_[port].unclaimed; }
  bool output_claimed(uint8_t port) const { return ports_[port].output_claimed; }
  /// Whether the sketch began input port `port` (a firmware image: whether it set the port up).
  bool input_begun(uint8_t port) const {
    return firmware_ ? firmware_->input_port_begun(port) : ports_[port].input_begun;
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
  /// What the sketch printed so far: everything, or its newest kConsoleTextBytes.
  const std::string& console_text() const { return console_text_; }
  /// Time the sketch's loop spent in I2C transfers (their wire time at the bus clock): the most
  /// in any one loop pass, and in all. Transfers in setup() are counted apart.
  struct I2cTiming {
    SimTime max_loop_pass_ns = 0;
    SimTime total_ns = 0;
    SimTime setup_ns = 0;
    uint64_t transfers = 0;
    uint64_t loop_passes_with_i2c = 0;
  };
  const I2cTiming& i2c_timing() const { return i2c_timing_; }
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
  int set_pin_mode(uint8_t pin, int mode);
  void write_pin(uint8_t pin, bool high);
  /// The encoder's raw quadrature count (no offset) on ENC `index` (0 or 1).
  int64_t encoder_counts(uint8_t index) const;
  /// The analog level on `pin`, 0..1023 (0 with nothing connected).
  uint16_t analog_level(uint8_t pin) const;
  /// Sets the clock of QWIIC bus `bus` (0 or 1) in Hz; 0 = not begun.
  void set_i2c_clock(uint8_t bus, uint32_t clock_hz) { i2c_[bus].clock_hz = clock_hz; }
  int i2c_transfer(uint8_t bus, uint8_t address, const uint8_t* write, size_t write_length, uint8_t* read,
                   size_t read_length, int64_t* wire_ns);
  /// The sketch writes `length` bytes to its console (the USB serial); all are taken.
  size_t write_console(const uint8_t* data, size_t length);
  /// Bytes the host has sent that the sketch has not read.
  size_t console_available() const { return console_input_.size() - console_read_position_; }
  /// The next byte the host sent, or -1.
  int read_console();
  /// Output port `port` plays `words` from `start_ns`; its next frame starts `frame_ns` later
  /// (a firmware's frame clock: a host-compiled sketch's frames are played by the board's own
  /// frame timer). Idle words reach only the listeners that want idle frames.
  void play_frame(uint8_t port, SimTime start_ns, const protocol::FrameWords& words, SimTime frame_ns);

 private:
  friend struct BoardCallbacks;
  static constexpr uint8_t kPorts = 4;
  static constexpr uint8_t kPins = kTeensy41.highest_pin + 1;  ///< the largest Teensy's pins

  struct PortState {
    bool output_claimed = false;
    bool frame_pending = false;
    protocol::FrameWords pending{};
    std::vector<WireListener*> listeners;
    std::vector<WireListener*> idle_listeners;  ///< the subset that also wants idle frames
    PulseCounts sent;
    bool input_begun = false;
    protocol::DirSampleEdge edge = protocol::DirSampleEdge::kFalling;
    PulseCounts received;
    uint64_t unclaimed = 0;
  };
  struct PinState {
    int mode = STEPDANCE_PIN_INPUT;
    bool driven_level = false;
    Source<bool> source;
    std::vector<PinListener> listeners;
  };
  struct I2cState {
    I2cBusModel model;
    uint32_t clock_hz = 0;  ///< 0 until the sketch begins the bus
  };
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
  /// Hands on a console line left unfinished for kConsoleQuietNs.
  struct ConsoleQuietEvent : Event {
    explicit ConsoleQuietEvent(SimBoard& board) : Event(&fire), owner(board) {}
    static void fire(Event& event, Scheduler& scheduler);
    SimBoard& owner;
  };
  void keep_console_text(const uint8_t* data, size_t length);
  void add_storage_warnings(std::vector<BoardWarning>& out) const;

  /// Runs one entry point of the sketch (`call` returns its code) unless the board is frozen;
  /// an escape freezes it and, for anything but the end of the run, reports the stop.
  template <typename Call>
  void enter(SketchEntry entry, Call call);
  void escaped(SketchEntry entry);

  static void frame_tick(void* context, SimTime time);
  static void khz_tick(void* context, SimTime time);
  void play_pending_frames(SimTime start_ns);
  void play_words(PortState& port, SimTime start_ns, const protocol::FrameWords& words, SimTime frame_ns);
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
  void notify_pin(uint8_t pin);
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
  ConsoleQuietEvent console_quiet_event_;
  bool in_isr_ = false;
  bool safe_state_ = false;
  std::array<PortState, kPorts> ports_{};
  uint8_t pending_ports_ = 0;       ///< bit p: port p has a frame to play at the next tick
  uint8_t idle_listening_ports_ = 0;  ///< bit p: port p has listeners that want idle frames
  std::array<PinState, kPins> pins_{};
  std::array<AdcState, kPins> adcs_{};
  std::array<Source<int64_t>, 2> encoders_{};
  std::array<int64_t, 2> encoder_offsets_{};
  std::array<I2cState, 2> i2c_{};
  I2cTiming i2c_timing_;
  bool in_loop_pass_ = false;
  SimTime i2c_ns_this_pass_ = 0;
  std::vector<uint8_t> console_input_;
  size_t console_read_position_ = 0;
  std::string console_text_;
  uint64_t console_text_dropped_ = 0;
  uint64_t console_dropped_bytes_ = 0;
  std::string console_line_;
  std::function<void(const std::string&)> console_listener_;
  std::function<void(const uint8_t*, size_t)> console_bytes_listener_;
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
