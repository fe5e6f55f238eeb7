// A simulated board: timers in virtual time, pin and port state, console, and the sketch's entry points.
#include "board/host/sim_board.hpp"

#include <algorithm>

#include "board/host/board_callbacks.hpp"
#include "kinds/board_registry.hpp"

namespace stepdance::sim {
namespace {

constexpr SimTime kKhzOffsetNs = 20 * kMicrosecond;  // half a frame after the frame tick
/// The simulated ADC converts every pin continuously at this period.
constexpr SimTime kAdcConversionNs = 100 * kMicrosecond;

}  // namespace

SimBoard::SimBoard(Scheduler& scheduler, BoardOptions options, std::unique_ptr<BoardLibrary> library)
    : scheduler_(scheduler),
      options_(std::move(options)),
      library_(std::move(library)),
      host_table_(std::make_unique<StepdanceHostV1>(BoardCallbacks::table())),
      frame_timer_(scheduler, &frame_tick, this),
      khz_timer_(scheduler, &khz_tick, this),
      encoder_sampler_(scheduler, &encoder_sample, this),
      loop_event_(*this),
      setup_event_(*this),
      console_(scheduler),
      storage_(options_.storage_dir),
      sd_timing_(options_.sd_card) {}

SimBoard::SimBoard(Scheduler& scheduler, BoardOptions options, std::unique_ptr<BoardFirmware> firmware,
                   const BoardDefinition& module)
    : SimBoard(scheduler, std::move(options), std::unique_ptr<BoardLibrary>()) {
  firmware_ = std::move(firmware);
  definition_ = &module;
}

SimBoard::~SimBoard() {
  scheduler_.cancel(loop_event_);
  scheduler_.cancel(setup_event_);
  frame_timer_.stop();
  khz_timer_.stop();
  encoder_sampler_.stop();
  library_.reset();  // the sketch's destructors may still call back: everything else is alive
  firmware_.reset();
}

bool SimBoard::attach(std::string& error) {
  if (firmware_) {
    // A firmware's ports are all wired: it drives and captures through its own peripherals.
    ports_.begin_all_inputs();
    firmware_->on_stop([this](const SketchStop& stop) { firmware_stopped(stop); });
    return firmware_->start(*this, error);
  }
  board_ = library_ ? library_->attach()(host_table_.get(), this) : nullptr;
  if (board_ == nullptr) {
    error = options_.name + ": the board library speaks another ABI version; rebuild the sketch";
    return false;
  }
  const char* selected = board_->board_name != nullptr ? board_->board_name : "";
  definition_ = find_board_named(selected);
  if (definition_ == nullptr) {
    definition_ = &kDriverModuleV1;
    error = options_.name + ": the sketch selects the board \"" + selected + "\", which the simulator does not know";
    return false;
  }
  return true;
}

void SimBoard::power_on(SimTime time_ns) {
  if (firmware_) {
    firmware_->power_on(time_ns);
    return;
  }
  scheduler_.schedule(setup_event_, time_ns);
}

// A firmware stopped for good (a fault, no progress): as a sketch's escape, the run ends here.
void SimBoard::firmware_stopped(const SketchStop& stop) {
  frozen_ = true;
  scheduler_.stop();
  if (stop_listener_) stop_listener_(stop);
}

// ---- entering the sketch ----------------------------------------------------------------------

template <typename Call>
void SimBoard::enter(SketchEntry entry, Call call) {
  if (frozen_) return;
  int code = 0;
  {
    EntryMonitor::Scope running(*this, entry, board_->escape, &library_->code());
    code = call();
  }
  // A hang the watchdog could not stop inside the entry is stopped now, not forgotten.
  if (code == 0 && EntryMonitor::adopt_unreached_hang()) code = 1;
  if (code != 0) escaped(entry);
}

void SimBoard::escaped(SketchEntry entry) {
  frozen_ = true;
  frame_timer_.stop();
  khz_timer_.stop();
  encoder_sampler_.stop();
  scheduler_.cancel(loop_event_);
  const EscapeRecord record = EntryMonitor::take_record();
  if (record.cause == EscapeCause::kRunOver) return;  // the run ended while the sketch waited
  scheduler_.stop();
  if (stop_listener_)
    stop_listener_(describe_stop(record, name(), entry, scheduler_.now(), library_.get(), options_.board_source));
}

void SimBoard::SetupEvent::fire(Event& event, Scheduler& scheduler) {
  SimBoard& board = static_cast<SetupEvent&>(event).owner;
  board.enter(SketchEntry::kSetup, [&] { return board.board_->run_setup(scheduler.now()); });
  if (!board.frozen_) scheduler.schedule(board.loop_event_, scheduler.now());
}

void SimBoard::LoopEvent::fire(Event& event, Scheduler& scheduler) {
  SimBoard& board = static_cast<LoopEvent&>(event).owner;
  const SimTime started = event.time();
  board.i2c_.begin_loop_pass();
  board.enter(SketchEntry::kLoop, [&] { return board.board_->run_loop(scheduler.now()); });
  board.i2c_.end_loop_pass();
  if (board.frozen_) return;
  board.i2c_.count_loop_pass();
  const SimTime next = started + board.options_.loop_period_ns;
  scheduler.schedule(event, next > scheduler.now() ? next : scheduler.now());
}

// ---- timers -------------------------------------------------------------------------------------

SimTime SimBoard::next_aligned(SimTime offset_ns, SimTime period_ns) const {
  const SimTime now = scheduler_.now();
  if (now < offset_ns) return offset_ns;
  return offset_ns + ((now - offset_ns) / period_ns + 1) * period_ns;
}

int SimBoard::start_timer(int timer_id, uint32_t period_us) {
  if (period_us == 0) return static_cast<int>(Status::kBadArgument);
  const SimTime period = SimTime{period_us} * kMicrosecond;
  if (timer_id == STEPDANCE_TIMER_FRAME) {
    const SimTime first_tick = next_aligned(options_.frame_phase_ns, period);
    frame_timer_.start(first_tick, period);
    if (options_.encoder_sample_phase_ns) {  // the first sample instant after the first tick
      const SimTime phase = *options_.encoder_sample_phase_ns % period;
      encoders_sampled_ = false;
      encoder_sampler_.start(first_tick + 1 + ((phase - (first_tick + 1) % period) + period) % period, period);
    }
  } else if (timer_id == STEPDANCE_TIMER_KHZ) {
    khz_timer_.start(next_aligned(options_.khz_phase_ns.value_or(options_.frame_phase_ns + kKhzOffsetNs), period),
                     period);
  } else {
    return static_cast<int>(Status::kBadArgument);
  }
  return static_cast<int>(Status::kOk);
}

void SimBoard::stop_timers() {
  frame_timer_.stop();
  encoder_sampler_.stop();
  encoders_sampled_ = false;
  khz_timer_.stop();
}

void SimBoard::frame_tick(void* context, SimTime time) {
  auto& board = *static_cast<SimBoard*>(context);
  board.ports_.play_queued(time, board.frame_timer_.period_ns(), board.end_ns_);
  if (board.tick_listener_) board.tick_listener_(time);
  board.in_isr_ = true;
  board.enter(SketchEntry::kFrameTick, [&] { return board.board_->run_frame_tick(time); });
  board.in_isr_ = false;
}

void SimBoard::khz_tick(void* context, SimTime time) {
  auto& board = *static_cast<SimBoard*>(context);
  board.in_isr_ = true;
  board.enter(SketchEntry::kKhzTick, [&] { return board.board_->run_khz_tick(time); });
  board.in_isr_ = false;
}

void SimBoard::play_frame(uint8_t port, SimTime start_ns, const protocol::FrameWords& words, SimTime frame_ns) {
  // A firmware's frame clock is its ports' launches: the first port of each launch is the tick
  // the frame listener (the machine's pen sampling) is told of, as a host board's frame timer is.
  if (tick_listener_ && start_ns != last_played_tick_ns_) {
    last_played_tick_ns_ = start_ns;
    tick_listener_(start_ns);
  }
  ports_.play(port, start_ns, words, frame_ns, end_ns_);
}

// The rest of the world runs for the delay, but never past the run's end: a sketch waiting
// there (`while (1) delay(1000);`) is left in its delay when the run ends (see BoardCallbacks).
void SimBoard::delay(SimTime duration_ns) {
  if (in_isr_) {
    ++delays_in_isr_;
    return;
  }
  const SimTime wanted = scheduler_.now() + (duration_ns > 0 ? duration_ns : 0);
  scheduler_.run_until(std::min(wanted, end_ns_));
  EntryMonitor::note_progress();
}

bool SimBoard::run_is_over() const { return scheduler_.stopped() || scheduler_.now() >= end_ns_; }

// ---- storage: loop only; a slow card holds the loop while frames run on -----------------------

bool SimBoard::storage_refused_in_isr() {
  if (!in_isr_) return false;
  ++storage_calls_in_isr_;
  return true;
}

int SimBoard::storage_write(int handle, const uint8_t* data, size_t length) {
  if (storage_refused_in_isr()) return static_cast<int>(Status::kIoError);
  const SdCardTiming::Write outcome = sd_timing_.write(length);
  if (outcome.fails) return static_cast<int>(Status::kIoError);
  delay(outcome.duration);
  return static_cast<int>(storage_.write(handle, data, length));
}

int SimBoard::storage_read(int handle, uint8_t* data, size_t length, size_t* read) {
  *read = 0;
  if (storage_refused_in_isr()) return static_cast<int>(Status::kIoError);
  delay(sd_timing_.read(length));
  return static_cast<int>(storage_.read(handle, data, length, *read));
}

// ---- ports --------------------------------------------------------------------------------------

// The ports count the pulse; the program hears it: a firmware through its capture peripheral, a
// sketch through its capture ISR.
void SimBoard::capture(uint8_t port, const ArrivingPulse& pulse) {
  const std::optional<protocol::CapturedPulse> seen = ports_.capture(port, pulse);
  if (!seen) return;
  const protocol::CapturedPulse& captured = *seen;
  if (firmware_) {
    firmware_->pulse_arrived(port, pulse);
    return;
  }
  const StepdanceCapturedPulseV1 delivered{captured.rise_ticks, captured.fall_ticks,
                                           captured.dir_high ? uint8_t{1} : uint8_t{0}, captured.extra_periods};
  in_isr_ = true;
  enter(SketchEntry::kCapture, [&] { return board_->deliver_pulse(scheduler_.now(), port, &delivered); });
  in_isr_ = false;
}

// ---- encoders, ADC, pins ------------------------------------------------------------------------

void SimBoard::connect_encoder(uint8_t index, Source<int64_t> counts) { encoders_.at(index) = std::move(counts); }

int64_t SimBoard::encoder_counts(uint8_t index) const { return encoders_.at(index) ? encoders_[index](now()) : 0; }

// The sample clock's instant: both encoders' counts latched now, as the ENC hold registers are.
void SimBoard::encoder_sample(void* context, SimTime) {
  auto& board = *static_cast<SimBoard*>(context);
  for (uint8_t index = 0; index < 2; ++index) board.encoder_samples_[index] = board.encoder_counts(index);
  board.encoders_sampled_ = true;
}

int64_t SimBoard::encoder_counts_seen(uint8_t index) const {
  return encoders_sampled_ ? encoder_samples_.at(index) : encoder_counts(index);
}

int32_t SimBoard::read_quadrature(uint8_t index) {
  return static_cast<int32_t>(encoder_counts_seen(index) + encoder_offsets_[index]);
}

void SimBoard::write_quadrature(uint8_t index, int32_t count) {
  encoder_offsets_[index] = count - encoder_counts_seen(index);
}

uint16_t SimBoard::analog_level(uint8_t pin) const {
  if (pin >= kPins || !adcs_[pin].value) return 0;
  return adcs_[pin].value(now());
}

void SimBoard::connect_adc(uint8_t pin, Source<uint16_t> value) { adcs_.at(pin).value = std::move(value); }

uint32_t SimBoard::adc_samples(uint8_t pin) const {
  const AdcState& adc = adcs_[pin];
  if (!adc.begun) return 0;
  return static_cast<uint32_t>(1 + (scheduler_.now() - adc.begun_at) / kAdcConversionNs);
}

// Safe state on the hardware: frames stop (the board already stopped its timers) and every
// driver's ENABLE is driven high.
void SimBoard::enter_safe_state() {
  safe_state_ = true;
  const BoardDefinition& board = definition();
  for (uint8_t port = 0; port < board.output_port_count; ++port) {
    const uint8_t enable = board.output_ports[port].enable;
    if (enable == kNoPin) continue;
    pins_.drive_high(enable, now());
  }
}

// ---- readouts ------------------------------------------------------------------------------------

std::vector<SimBoard::BlockCounter> SimBoard::counters() const {
  std::vector<BlockCounter> out;
  const StepdanceCounterFnV1 emit = [](void* context, const char* block, uint32_t instance, const char* name,
                                       uint64_t value) {
    static_cast<std::vector<BlockCounter>*>(context)->push_back(
        {std::string(block) + "#" + std::to_string(instance), name, value});
  };
  if (firmware_) firmware_->read_counters(emit, &out);
  if (board_ != nullptr) board_->read_counters(emit, &out);
  return out;
}

std::vector<SimBoard::BoardWarning> SimBoard::warnings() const {
  std::vector<BoardWarning> out;
  const StepdanceWarningFnV1 emit = [](void* context, const char* source, const char* reason, const char* detail,
                                       uint32_t count) {
    static_cast<std::vector<BoardWarning>*>(context)->push_back(
        {std::string(source) + ": " + reason, std::string(detail), count});
  };
  if (firmware_) firmware_->read_warnings(emit, &out);
  if (board_ != nullptr) board_->read_warnings(emit, &out);
  add_storage_warnings(out);
  return out;
}

// What the card refused to a runaway sketch (board_storage.hpp's limits), told as warnings are.
void SimBoard::add_storage_warnings(std::vector<BoardWarning>& out) const {
  if (storage_.refused_writes() != 0) {
    out.push_back({"SD card: full",
                   "the card takes " + std::to_string(BoardStorage::kWriteLimitBytes >> 20) + " MiB written per run; " +
                       std::to_string(storage_.refused_write_bytes()) + " bytes refused",
                   storage_.refused_writes()});
  }
  if (storage_.refused_opens() != 0) {
    out.push_back({"SD card: too many open files",
                   "at most " + std::to_string(BoardStorage::kMaxOpenFiles) + " files open at once",
                   storage_.refused_opens()});
  }
}

uint64_t SimBoard::port_counter(const std::string& block_class, uint8_t port, const std::string& name) const {
  const std::vector<BlockCounter> all = counters();
  const std::string prefix = block_class + "#";
  for (const BlockCounter& candidate : all) {
    if (candidate.block.rfind(prefix, 0) != 0 || candidate.name != "port" || candidate.value != port) continue;
    for (const BlockCounter& counter : all) {
      if (counter.block == candidate.block && counter.name == name) return counter.value;
    }
  }
  return 0;
}

StepdanceBoardStatsV1 SimBoard::stats() const {
  StepdanceBoardStatsV1 stats{};
  if (firmware_) return firmware_->stats();
  if (board_ != nullptr) board_->read_stats(&stats);
  return stats;
}

}  // namespace stepdance::sim
