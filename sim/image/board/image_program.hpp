// An image board's program: a Teensy 4.x firmware ELF on the emulated i.MX RT1062, wired to its
// SimBoard's world.
#pragma once

#include <memory>
#include <string>

#include "board/host/board_firmware.hpp"
#include "image/chip/board_io.hpp"
#include "image/cpu/image_chip.hpp"
#include "image/rt1062/clock_and_pin_blocks.hpp"
#include "image/rt1062/motion_blocks.hpp"
#include "image/usb/usb_blocks.hpp"

namespace stepdance::sim::image {

/// The chip, its peripherals and the emulated USB host, as one BoardFirmware. The peripherals
/// reach the board's world through the BoardIo side of this class, which forwards to the
/// SimBoard (Teensy pin numbers, the board's ports, its console, its QWIIC buses).
///
///   firmware ELF ─► ImageChip (Cortex-M7, NVIC, SysTick) ─► PeripheralBus
///        CCM, IOMUXC, GPIO ─► pins;   FLEXIO3 ─► output ports;   PWM capture ◄─ input ports
///        ENC ◄─ knobs;   ADC ◄─ pots;   LPI2C ─► QWIIC devices;   USB1 ◄─► emulated host ◄─► console
///
/// Context: the simulator's thread.
class ImageProgram final : public BoardFirmware, private BoardIo {
 public:
  ImageProgram(Scheduler& scheduler, TeensyModel model, std::string image_path);
  ~ImageProgram() override;
  /// Loads the ELF; false with `error` (one line) if it cannot run. Before start().
  bool load(std::string& error);
  ImageChip& chip() { return chip_; }

  // ---- BoardFirmware ----
  bool start(SimBoard& board, std::string& error) override;
  void power_on(SimTime time_ns) override;
  SimTime now_ns() const override { return chip_.now_ns(); }
  void pulse_arrived(uint8_t port, const ArrivingPulse& pulse) override;
  StepdanceBoardStatsV1 stats() const override;
  /// The port's STEP pad is routed to its capture input (the backend's InputPort begin()).
  bool input_port_begun(uint8_t port) const override;
  std::vector<std::pair<std::string, double>> figures() const override;
  /// Asks the image itself: a debugger's call to its stepdance_debug_counters or
  /// stepdance_debug_warnings (src/stepdance/platform/teensy/debug_entries.cpp). Nothing if the
  /// image has no such function (one built before them) or the image has stopped.
  void read_counters(StepdanceCounterFnV1 emit, void* context) override;
  void read_warnings(StepdanceWarningFnV1 emit, void* context) override;
  const std::string& image_path() const override { return image_path_; }
  void on_stop(std::function<void(const SketchStop&)> listener) override { stop_listener_ = std::move(listener); }

  /// The frame interrupt's cost: instructions in FLEXIO3's handler per entry (0 before any).
  double frame_isr_instructions() const;

 private:
  // ---- BoardIo: the peripherals' world ----
  void pin_config(SimTime now_ns, uint8_t pin, PinConfig config) override;
  void pin_drive(SimTime now_ns, uint8_t pin, bool high) override;
  bool pin_level(SimTime now_ns, uint8_t pin) override;
  void port_frame(uint8_t port, SimTime start_ns, const protocol::FrameWords& words, SimTime frame_ns) override;
  int64_t encoder_counts(SimTime now_ns, uint8_t index) override;
  uint16_t analog_level(SimTime now_ns, uint8_t pin) override;
  int i2c_transfer(SimTime now_ns, uint8_t bus, uint32_t clock_hz, uint8_t address, const uint8_t* write,
                   size_t write_length, uint8_t* read, size_t read_length, SimTime& wire_ns) override;
  size_t serial_from_device(SimTime now_ns, const uint8_t* data, size_t length) override;
  size_t serial_to_device(SimTime now_ns, uint8_t* data, size_t capacity) override;

  bool add_blocks(std::string& error);
  /// Calls the image's function `symbol` with (kCalloutAddress, 0); each callout calls `callout`.
  void call_reporter(const char* symbol, const std::function<void()>& callout);
  /// The NUL-terminated string at `address` in the image's memory (at most 128 bytes).
  std::string image_string(uint32_t address);
  void watch_setup();
  /// The frame interrupts (tick entries) and the instructions of the tick and stage handlers.
  ImageChip::HandlerCost frame_cost() const;
  /// When the sample clock first latched an encoder's holds, s; -1 if it never has.
  double first_encoder_sample_s() const;
  void stopped(const ImageStop& stop);

  TeensyModel model_;
  std::string image_path_;
  ImageChip chip_;
  SimBoard* board_ = nullptr;
  std::unique_ptr<rt1062::ClockAndPinBlocks> clocks_;
  std::unique_ptr<MotionBlocks> motion_;
  std::unique_ptr<usb::UsbBlocks> usb_;
  std::function<void(const SketchStop&)> stop_listener_;
  SimTime powered_on_ns_ = 0;
  bool setup_reached_ = false;  ///< the image has entered setup() (-1 in figures until then)
  uint64_t instructions_to_setup_ = 0;
  SimTime time_to_setup_ns_ = 0;
};

}  // namespace stepdance::sim::image
