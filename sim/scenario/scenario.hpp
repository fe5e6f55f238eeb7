// The scenario as plain, validated data: boards, machine, devices, cables, timeline, outputs, checks.
#pragma once

#include <any>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/sim_time.hpp"
#include "models/cable.hpp"
#include "stepdance/boards/driver_module_v1.hpp"

namespace stepdance::sim {
struct DeviceKind;
struct ExpectationKind;
struct MachineKind;
}  // namespace stepdance::sim

namespace stepdance::sim::scenario {

/// What sits in a driver socket.
enum class SocketDevice { kStepper, kServo };

/// Hobby-servo firmware build: ±500 steps or ±750 steps.
enum class ServoBuild { k90deg, k180deg };

/// One populated driver socket of a Driver Module.
struct SocketConfig {
  /// 'A'..'D'.
  char port = 'A';
  SocketDevice device = SocketDevice::kStepper;
  /// Stepper only: microsteps per full step (1..64, powers of two) and full steps per revolution.
  int microsteps = 16;
  int full_steps_per_rev = 200;
  /// Stepper only: the motor is plugged in the other way round (it turns backwards).
  bool reversed = false;
  /// Servo only.
  ServoBuild build = ServoBuild::k90deg;
  int line = 0;
};

/// One simulated module and its sketch.
/// The simulated SD card of a board ([board.sd_card]); zeros are an ideal card.
struct SdCardConfig {
  double write_kb_per_s = 0;  ///< sustained write rate (0 = instant)
  double read_kb_per_s = 0;   ///< sustained read rate (0 = instant)
  double stall_every_kb = 0;  ///< a stall after every this many kB written (0 = never)
  double stall_ms = 0;        ///< length of each stall
  double fail_after_kb = 0;   ///< writes beyond this many kB fail (0 = never)
};

struct BoardConfig {
  std::string name;
  /// Absolute path of the `.ino` (checked to exist); "" for a board that runs an image and
  /// names no sketch.
  std::string sketch;
  /// Absolute path of a Teensy 4.x firmware ELF the board runs on an emulated chip instead of
  /// its host-compiled sketch ("" = none; checked to exist). `stepdance sim --image` replaces it.
  std::string image;
  /// The module it is: a table of the board registry (kinds/board_registry.hpp), found by its
  /// scenario name (`module = "basic"`); the Driver Module unless the file says otherwise.
  const BoardDefinition* module = &kDriverModuleV1;
  /// How often loop() runs, in µs of virtual time (> 0).
  int64_t loop_period_us = 200;
  /// Offset of this board's 40 µs frame clock, µs (0..39).
  int frame_phase_us = 0;
  /// Set from code, never from the file: the board's clocks to the nanosecond, to line a host
  /// board up with an image board's measured ones (tests/sim/image_examples). Unset: the frame
  /// clock at frame_phase_us, the kilohertz tick half a frame after it (sim_board.hpp).
  std::optional<SimTime> frame_phase_ns;
  std::optional<SimTime> khz_phase_ns;
  std::optional<SimTime> encoder_sample_phase_ns;  ///< BoardOptions::encoder_sample_phase_ns
  /// Set from code, never from the file: when the board powers on, ns (unset: at 0). A host
  /// board's sketch costs no simulated time, an image's does; the image example tests start the
  /// host board this much later so its first step lands where the image's did.
  std::optional<SimTime> power_on_ns;
  /// Populated sockets, sorted by port (boards with driver sockets only).
  std::vector<SocketConfig> sockets;
  /// Speed and failures of the board's card.
  SdCardConfig sd_card;
  int line = 0;

  /// The socket at `port`, or null if it is empty.
  const SocketConfig* socket(char port) const;
};

/// The machine and the board whose sockets drive it.
struct MachineConfig {
  std::string board;
  /// Its kind (kinds/machine_kind.hpp) and the kind's settings (its config struct, e.g.
  /// CorexyConfig in kinds/machines/corexy_plotter.hpp).
  const MachineKind* kind = nullptr;
  std::any settings;
  int line = 0;

  /// The settings if they are a T (the machine is of T's kind), else null.
  template <typename T>
  const T* settings_as() const {
    return std::any_cast<T>(&settings);
  }
};

/// Connectors on a module's edge.
enum class Connector {
  kEnc1,
  kEnc2,
  kA1,
  kA2,
  kA3,
  kA4,
  kD1,
  kD2,
  kLimitA,
  kLimitB,
  kLimitC,
  kLimitD,
  kQwiic0,
  kQwiic1
};

/// The connector's silkscreen name, e.g. "ENC1", "LIMIT_A".
std::string_view connector_name(Connector connector);

/// One input device on a board connector: what every kind has, its kind, and the kind's own
/// settings.
struct DeviceConfig {
  std::string name;
  std::string board;
  Connector connector = Connector::kEnc1;
  /// Its kind (kinds/device_kind.hpp) and the kind's settings (its config struct, e.g.
  /// EncoderConfig in kinds/devices/encoder.hpp).
  const DeviceKind* kind = nullptr;
  std::any settings;
  /// On QWIIC0/QWIIC1: the 7-bit I2C address (−1 elsewhere).
  int i2c_address = -1;
  int line = 0;

  /// The settings if they are a T (the device is of T's kind), else null.
  template <typename T>
  const T* settings_as() const {
    return std::any_cast<T>(&settings);
  }
};

/// A board's port: "board:A".
struct PortRef {
  std::string board;
  char port = 'A';
};

/// A TRRS cable from an output port to an input port, with the model's settings (delay, stretch
/// and glitches, in ns: models/cable.hpp).
struct CableConfig {
  PortRef from;
  PortRef to;
  CableSettings settings;
  int line = 0;
};

/// User actions on the timeline.
enum class ActionType { kTurn, kPress, kRelease, kClick, kSet, kSerial };

/// One timeline entry. Only the fields of its type are meaningful.
struct Action {
  /// When the action starts (ns, 0..duration).
  SimTime time = 0;
  ActionType type = ActionType::kPress;
  /// Device name (turn, press, release, click, set) or board name (serial).
  std::string target;
  /// Turn: signed counts, spread evenly over `over` ns.
  int64_t counts = 0;
  SimTime over = 0;
  /// Click: time between press and release (ns).
  SimTime hold = 100 * kMillisecond;
  /// Set: new wiper position, 0..1.
  double position = 0;
  /// Serial: the bytes to send (the text, or the file's contents) and the file's absolute path
  /// (empty for text).
  std::string serial_bytes;
  std::string serial_file;
  int line = 0;
};

/// One step of a scripted host client ([[host]] … [[host.step]]).
struct HostStep {
  enum class Kind { kSend, kStream, kWait, kPause } kind = Kind::kSend;
  /// Send: bytes written at once. Stream: the text sent line by line (each line keeps its '\n').
  std::string bytes;
  /// Stream flow control: kAck sends a line only when the previous one was acknowledged;
  /// kCharacterCounting keeps up to buffer_bytes of unacknowledged lines in flight (Grbl's
  /// recommended streaming).
  enum class Flow { kAck, kCharacterCounting } flow = Flow::kAck;
  int64_t buffer_bytes = 128;
  /// Stream: the RE2 pattern (scenario/line_pattern.hpp) a received line must match (anywhere in it; anchor with ^…$)
  /// to acknowledge a line. Wait: the regex a received line must match to end the step.
  std::string pattern;
  /// Wait: the step fails (and the client stops) if no line matches for this long (ns).
  /// Stream: … if no acknowledgement arrives for this long.
  SimTime timeout = 60 * kSecond;
  /// Pause: how long (ns).
  SimTime pause = 0;
  /// Stream from a file: its absolute path (an input of the run, never an output).
  std::string file;
  /// Wait and stream: bytes to send when the step starts and again every poll_interval while
  /// it runs (a sender polling `?`); empty: none.
  std::string poll;
  SimTime poll_interval = 200 * kMillisecond;
  int line = 0;
};

/// A program on the host end of a board's USB serial: runs its steps in order from `start`,
/// reacting within a simulated millisecond (a USB frame), and keeps a transcript.
struct HostClientConfig {
  std::string board;
  SimTime start = 0;
  std::vector<HostStep> steps;
  /// Absolute path of the transcript file to write (empty: none) and the line naming it.
  std::string transcript;
  int transcript_line = 0;
  int line = 0;
};

/// One line of a port: "board:OUT_A" or "board:IN_A".
struct PortLineRef {
  std::string board;
  bool output = true;
  char port = 'A';
};

/// Which files to write. Paths are absolute; an empty path means "do not write it".
struct OutputConfig {
  std::string directory;
  std::string svg;
  std::string png;
  double png_px_per_mm = 4;
  bool pen_up_travel = false;
  std::string vcd;
  std::vector<PortLineRef> vcd_ports;
  std::string csv;
  double csv_interval_ms = 10;
  /// The replay page (one self-contained HTML file; "" = none). The simulator library only
  /// plans it; the front end records and writes it (sim/view/replay_recorder.hpp).
  std::string html;
  std::string summary;
  /// Line of each file key ("svg", "png", "vcd", "csv", "html", "summary") given in [output]; a name left
  /// at its default has none.
  std::map<std::string, int> lines;
};

/// One end-of-run check ([[expect]]): its line, its kind (kinds/expectation_kind.hpp: the key
/// that names it, its reader and its check) and the kind's settings (its own struct, e.g.
/// MotorStepsCheck in kinds/expectations/motor_steps.cpp).
struct Expectation {
  const ExpectationKind* kind = nullptr;
  std::any settings;
  int line = 0;

  /// The settings if they are a T (the check is of T's kind), else null.
  template <typename T>
  const T* settings_as() const {
    return std::any_cast<T>(&settings);
  }
};

/// A whole scenario.
struct Scenario {
  /// Absolute path of the scenario file and of its folder (the base of relative paths).
  std::string file;
  std::string directory;
  /// Simulated time to run (ns, > 0).
  SimTime duration = 0;
  /// Seed for everything random.
  uint64_t seed = 1;
  std::vector<BoardConfig> boards;
  std::optional<MachineConfig> machine;
  std::vector<DeviceConfig> devices;
  std::vector<CableConfig> cables;
  /// Sorted by time; entries with equal times keep their order in the file.
  std::vector<Action> timeline;
  /// Scripted host clients, at most one per board.
  std::vector<HostClientConfig> hosts;
  OutputConfig output;
  std::vector<Expectation> expectations;

  /// The board / device with this name, or null.
  const BoardConfig* board(std::string_view name) const;
  const DeviceConfig* device(std::string_view name) const;
};

}  // namespace stepdance::sim::scenario
