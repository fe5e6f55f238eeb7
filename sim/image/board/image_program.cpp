// An image board's program: the emulated chip wired to its SimBoard.
#include "image/board/image_program.hpp"

#include <unicorn/unicorn.h>

#include <cstdio>

#include "board/host/sim_board.hpp"

namespace stepdance::sim::image {
namespace {

/// Exception number of an interrupt (ARMv7-M B1.5.2: 16 + IRQ).
constexpr unsigned exception_of_irq(unsigned irq) { return 16 + irq; }
/// The Teensy backend's frame: FLEXIO3's tick interrupt (IRQ 156) pends IRQ 155, an interrupt the
/// chip leaves unused, whose handler runs the frame's stages (src/stepdance/platform/teensy/
/// regs_nvic.hpp, kIrqReservedForFrame). The frame's cost is both handlers' instructions.
constexpr unsigned kFrameStagesIrq = 155;
/// The backend's kilohertz tick: GPT2's interrupt (RM table 4-2; src/stepdance/platform/teensy/
/// khz_timer.cpp).
constexpr unsigned kKhzTickIrq = 101;

/// Seconds of a first entry, -1 for none.
double first_entry_s(const ImageChip::HandlerCost& cost) {
  return cost.first_entry_ns < 0 ? -1.0 : to_seconds(cost.first_entry_ns);
}

}  // namespace

ImageProgram::ImageProgram(Scheduler& scheduler, TeensyModel model, std::string image_path)
    : model_(model), image_path_(std::move(image_path)), chip_(scheduler, model) {}

ImageProgram::~ImageProgram() = default;

bool ImageProgram::load(std::string& error) { return chip_.load(image_path_, error); }

bool ImageProgram::start(SimBoard& board, std::string& error) {
  board_ = &board;
  if (!add_blocks(error)) return false;
  // The boot ROM hands a FlexSPI image over with the core on a PLL, not at the reset state's
  // 12 MHz (ClockAndPinBlocks::apply_boot_rom_clocks says what it sets and why).
  clocks_->apply_boot_rom_clocks();
  clocks_->ccm.add_rates_listener([this](const rt1062::ClockRates& rates) {
    if (rates.core_hz != 0) chip_.set_core_clock_hz(rates.core_hz);
  });
  chip_.on_stop([this](const ImageStop& stop) { stopped(stop); });
  watch_setup();
  return true;
}

// The first arrival at the sketch's setup() (its symbol, C++ mangled as the Arduino IDE links
// it): the boot's cost in instructions and simulated time.
void ImageProgram::watch_setup() {
  uint32_t address = 0;
  if (!chip_.symbols().find("_Z5setupv", address) && !chip_.symbols().find("setup", address)) return;
  chip_.on_reach(address, [this](uint64_t instructions, SimTime time_ns) {
    if (setup_reached_) return;
    setup_reached_ = true;
    instructions_to_setup_ = instructions;
    time_to_setup_ns_ = time_ns - powered_on_ns_;
  });
}

// The chip's blocks, each group added whole or not at all; an overlap is a bug of the models.
bool ImageProgram::add_blocks(std::string& error) {
  BoardIo& world = *this;
  clocks_ = rt1062::add_clock_and_pin_blocks(chip_.bus(), chip_, world, model_);
  motion_ = clocks_ ? add_motion_blocks(chip_.bus(), chip_, world, model_) : nullptr;
  if (motion_) {
    clocks_->pit.set_trigger_sink([xbar = &motion_->xbar1()](unsigned channel) {
      xbar->pulse(static_cast<uint8_t>(Xbar1::kInputPitTrigger0 + channel));
    });
  }
  usb_ = motion_ ? usb::add_usb_blocks(chip_.bus(), chip_, world) : nullptr;
  if (usb_) return true;
  error = "the RT1062 model's peripheral windows overlap (a simulator bug)";
  return false;
}

void ImageProgram::power_on(SimTime time_ns) {
  powered_on_ns_ = time_ns;
  chip_.power_on(time_ns);
}

void ImageProgram::pulse_arrived(uint8_t port, const ArrivingPulse& pulse) {
  motion_->capture().pulse_arrived(port, pulse);
}

bool ImageProgram::input_port_begun(uint8_t port) const {
  return motion_ != nullptr && port < 4 && motion_->capture().routed(port);
}

// A stop ends the run as a host-compiled sketch's crash or hang does: exit status 5 or 6.
void ImageProgram::stopped(const ImageStop& stop) {
  SketchStop report;
  report.cause = stop.kind == ImageStop::Kind::kNoProgress ? EscapeCause::kHung : EscapeCause::kCrashed;
  report.board = board_ != nullptr ? board_->name() : std::string();
  report.entry = SketchEntry::kFirmware;
  report.time_ns = stop.time_ns;
  report.what = stop.what;
  char pc[16];
  std::snprintf(pc, sizeof pc, "0x%08X", stop.pc);
  report.what += std::string(" (PC ") + pc + (stop.symbol.empty() ? "" : " in " + stop.symbol) + ")";
  report.backtrace = stop.backtrace;
  if (stop_listener_) stop_listener_(report);
}

ImageChip::HandlerCost ImageProgram::frame_cost() const {
  const ImageChip::HandlerCost tick = chip_.handler_cost(exception_of_irq(Flexio3::kIrq));
  const ImageChip::HandlerCost stages = chip_.handler_cost(exception_of_irq(kFrameStagesIrq));
  return {tick.entries, tick.instructions + stages.instructions, tick.first_entry_ns};
}

double ImageProgram::first_encoder_sample_s() const {
  SimTime first = -1;
  for (unsigned index = 0; index < 2 && motion_; ++index) {
    const SimTime at = motion_->enc(index).first_trigger_ns();
    if (at >= 0 && (first < 0 || at < first)) first = at;
  }
  return first < 0 ? -1.0 : to_seconds(first);
}

double ImageProgram::frame_isr_instructions() const {
  const ImageChip::HandlerCost cost = frame_cost();
  return cost.entries == 0 ? 0.0 : static_cast<double>(cost.instructions) / static_cast<double>(cost.entries);
}

// The frame count is the frame interrupt's entries; the load is its instructions against the
// frame's cycles at the core clock (one instruction per cycle).
StepdanceBoardStatsV1 ImageProgram::stats() const {
  StepdanceBoardStatsV1 stats{};
  const ImageChip::HandlerCost frame = frame_cost();
  stats.frames = static_cast<uint32_t>(frame.entries);
  stats.fault_name = "";
  stats.fault_detail = "";
  stats.load_budget_cycles = static_cast<uint32_t>(uint64_t{chip_.core_clock_hz()} * 40 / 1000000);
  stats.load_total_cycles = frame.instructions;
  stats.load_frames = frame.entries;
  return stats;
}

std::vector<std::pair<std::string, double>> ImageProgram::figures() const {
  const ImageChip::HandlerCost frame = frame_cost();
  return {{"instructions", static_cast<double>(chip_.instructions())},
          {"core_clock_hz", static_cast<double>(chip_.core_clock_hz())},
          {"frame_interrupts", static_cast<double>(frame.entries)},
          {"frame_interrupt_instructions_mean", frame_isr_instructions()},
          {"instructions_to_setup", setup_reached_ ? static_cast<double>(instructions_to_setup_) : -1.0},
          {"time_to_setup_s", setup_reached_ ? to_seconds(time_to_setup_ns_) : -1.0},
          {"frame_interrupt_first_s", first_entry_s(frame)},
          {"khz_interrupt_first_s", first_entry_s(chip_.handler_cost(exception_of_irq(kKhzTickIrq)))},
          {"encoder_sample_first_s", first_encoder_sample_s()}};
}

// ---- the peripherals' world: the SimBoard, at the board's time (the chip's) ----------------------

void ImageProgram::pin_config(SimTime, uint8_t pin, PinConfig config) {
  board_->set_pin_mode(pin, static_cast<int>(config));
}

void ImageProgram::pin_drive(SimTime, uint8_t pin, bool high) { board_->write_pin(pin, high); }

// An input port's DIR pin carries what the cable's last pulse left on it (the capture model
// knows); every other pin is the board's.
bool ImageProgram::pin_level(SimTime now_ns, uint8_t pin) {
  for (uint8_t port = 0; port < kMaxBoardPorts; ++port) {
    if (InputCapture::dir_pin(port) == pin) return motion_->capture().dir_line(port, now_ns);
  }
  return board_->pin_level(pin);
}

void ImageProgram::port_frame(uint8_t port, SimTime start_ns, const protocol::FrameWords& words, SimTime frame_ns) {
  board_->play_frame(port, start_ns, words, frame_ns);
}

int64_t ImageProgram::encoder_counts(SimTime, uint8_t index) { return board_->encoder_counts(index); }

uint16_t ImageProgram::analog_level(SimTime, uint8_t pin) { return board_->analog_level(pin); }

int ImageProgram::i2c_transfer(SimTime, uint8_t bus, uint32_t clock_hz, uint8_t address, const uint8_t* write,
                               size_t write_length, uint8_t* read, size_t read_length, SimTime& wire_ns) {
  board_->i2c().begin(bus, clock_hz);
  int64_t wire = 0;
  const int result = board_->i2c_transfer(bus, address, write, write_length, read, read_length, &wire);
  wire_ns = wire;
  return result;
}

size_t ImageProgram::serial_from_device(SimTime, const uint8_t* data, size_t length) {
  return board_->write_console(data, length);
}

size_t ImageProgram::serial_to_device(SimTime, uint8_t* data, size_t capacity) {
  size_t taken = 0;
  while (taken < capacity && board_->console().available() > 0)
    data[taken++] = static_cast<uint8_t>(board_->console().read());
  return taken;
}

// ---- what the image reports of itself (a debugger's calls) ---------------------------------------

void ImageProgram::call_reporter(const char* symbol, const std::function<void()>& callout) {
  uint32_t function = 0;
  if (chip_.stopped() || !chip_.symbols().find(symbol, function)) return;
  std::string error;
  if (!chip_.call_function(function, {ImageChip::kCalloutAddress | 1u, 0, 0, 0}, callout, error)) {
    std::fprintf(stderr, "stepdance: image board %s: %s: %s\n", board_ != nullptr ? board_->name().c_str() : "?",
                 symbol, error.c_str());
  }
}

std::string ImageProgram::image_string(uint32_t address) {
  std::string text;
  char c = 0;
  while (text.size() < 128 && chip_.read_memory(address + static_cast<uint32_t>(text.size()), &c, 1) && c != '\0')
    text += c;
  return text;
}

// The callout is CounterEmit(context, block, instance, name, value): R0–R3, then the 64-bit
// value on the stack at SP (AAPCS 5.5: 8-byte aligned, the first stacked argument).
void ImageProgram::read_counters(StepdanceCounterFnV1 emit, void* context) {
  call_reporter("stepdance_debug_counters", [&] {
    uint64_t value = 0;
    chip_.read_memory(chip_.read_register(UC_ARM_REG_SP), &value, sizeof value);
    const std::string block = image_string(chip_.read_register(UC_ARM_REG_R1));
    const std::string name = image_string(chip_.read_register(UC_ARM_REG_R3));
    emit(context, block.c_str(), chip_.read_register(UC_ARM_REG_R2), name.c_str(), value);
  });
}

// WarningEmit(context, source, reason, detail, count): count is the first stacked word.
void ImageProgram::read_warnings(StepdanceWarningFnV1 emit, void* context) {
  call_reporter("stepdance_debug_warnings", [&] {
    uint32_t count = 0;
    chip_.read_memory(chip_.read_register(UC_ARM_REG_SP), &count, sizeof count);
    const std::string source = image_string(chip_.read_register(UC_ARM_REG_R1));
    const std::string reason = image_string(chip_.read_register(UC_ARM_REG_R2));
    const std::string detail = image_string(chip_.read_register(UC_ARM_REG_R3));
    emit(context, source.c_str(), reason.c_str(), detail.c_str(), count);
  });
}

}  // namespace stepdance::sim::image
