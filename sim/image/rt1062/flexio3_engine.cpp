// FLEXIO3's timers and shifters in FlexIO clocks: expiries, trigger edges, launches, the interrupt
// line and the model's own wake-ups (RM §50.4 functional description, §50.5.1 registers).
#include <algorithm>
#include <cstdint>
#include <limits>

#include "image/rt1062/flexio3.hpp"
#include "image/rt1062/flexio3_pins.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image {
namespace {

constexpr int64_t kNever = std::numeric_limits<int64_t>::max();
constexpr uint32_t kCtrlFlexen = 1u << 0;
constexpr uint32_t kSmodTransmit = 2u;
constexpr uint32_t kPinOutput = 3u;

// TIMCTL / TIMCFG fields (RM §50.5.1.9, §50.5.1.10).
uint32_t timod(uint32_t ctl) { return ctl & 3u; }
uint32_t trigger_select(uint32_t ctl) { return (ctl >> 24) & 0x3Fu; }
bool trigger_active_low(uint32_t ctl) { return (ctl >> 23) & 1u; }
bool trigger_internal(uint32_t ctl) { return (ctl >> 22) & 1u; }
uint32_t timer_pin_config(uint32_t ctl) { return (ctl >> 16) & 3u; }
uint32_t timena(uint32_t cfg) { return (cfg >> 8) & 7u; }
uint32_t timdis(uint32_t cfg) { return (cfg >> 12) & 7u; }
constexpr uint32_t kTimcfgModelled = 0x7700u;  // TIMDIS, TIMENA; TIMOUT/TIMDEC/TIMRST/TSTOP/TSTART 0

// SHIFTCTL fields (RM §50.5.1.5).
uint32_t shifter_timer(uint32_t ctl) { return (ctl >> 24) & 7u; }
uint32_t shifter_pin(uint32_t ctl) { return (ctl >> 8) & 0x1Fu; }
uint32_t shifter_pin_config(uint32_t ctl) { return (ctl >> 16) & 3u; }

// Baud mode: CMP[7:0] + 1 clocks per output toggle, a bit every two toggles, (CMP[15:8] + 1) / 2 bits.
int64_t bit_clocks(uint32_t cmp) { return 2 * static_cast<int64_t>((cmp & 0xFFu) + 1u); }
uint32_t baud_bits(uint32_t cmp) { return (((cmp >> 8) & 0xFFu) + 1u) / 2u; }

}  // namespace

Flexio3::Kind Flexio3::kind_of(uint32_t ctl, uint32_t cfg) {
  if ((cfg & ~kTimcfgModelled) != 0 || timer_pin_config(ctl) != 0) return Kind::kInvalid;
  const uint32_t mode = timod(ctl);
  const uint32_t enable = timena(cfg);
  const uint32_t disable = timdis(cfg);
  if (mode == 0) return Kind::kOff;
  if (mode == 3 && enable == 0 && disable == 0) return Kind::kFreeRunner;  // always on, never off
  if (mode == 3 && enable == 6 && disable == 2) return Kind::kOneShot;     // trigger rising, compare
  if (mode == 1 && enable == 6 && disable == 2) return Kind::kTransmitter;
  return Kind::kInvalid;
}

bool Flexio3::trigger_valid(unsigned n, uint32_t ctl) const {
  if (kind_of(ctl, timers_[n].cfg) == Kind::kFreeRunner) return true;
  // Internal trigger from another timer's output: TRGSEL = 4 × timer + 3 (RM §50.5.1.9).
  const uint32_t select = trigger_select(ctl);
  return trigger_internal(ctl) && (select & 3u) == 3u && select / 4u < kTimers && select / 4u != n;
}

int64_t Flexio3::now_clk() const { return clock_.cycles_at(chip_.now_ns()); }

void Flexio3::advance() {
  if (!(ctrl_ & kCtrlFlexen) || clock_.hz == 0) return;
  const int64_t limit = now_clk();
  for (;;) {
    int best = -1;
    for (unsigned n = 0; n < kTimers; ++n) {
      const Timer& timer = timers_[n];
      if (!timer.running || timer.next_clk > limit) continue;
      // At equal clocks a one-shot ends before a free runner's edge may start it again.
      const bool earlier = best < 0 || timer.next_clk < timers_[best].next_clk ||
                           (timer.next_clk == timers_[best].next_clk &&
                            kind_of(timers_[best].ctl, timers_[best].cfg) == Kind::kFreeRunner);
      if (earlier) best = static_cast<int>(n);
    }
    if (best < 0) return;
    expire(static_cast<unsigned>(best));
  }
}

void Flexio3::expire(unsigned n) {
  Timer& timer = timers_[n];
  timstat_ |= 1u << n;  // TSF: the counter reached zero and decremented (RM §50.5.1.6)
  if (kind_of(timer.ctl, timer.cfg) != Kind::kFreeRunner) {
    timer.running = false;  // disabled on compare
    return;
  }
  const int64_t clk = timer.next_clk;
  timer.output = !timer.output;
  timer.next_clk = clk + (timer.cmp & 0xFFFFu) + 1;
  edge(n, timer.output, clk);
}

void Flexio3::enable_timer(unsigned n, int64_t clk) {
  Timer& timer = timers_[n];
  if (kind_of(timer.ctl, timer.cfg) != Kind::kFreeRunner) {
    timer.running = false;
    timer.armed_clk = clk;  // waits for its trigger
    return;
  }
  if (!(ctrl_ & kCtrlFlexen)) return;  // starts when FLEXEN is set
  // The output is logic one from enable (TIMOUT 0): a rising edge now (RM §50.5.1.10).
  timer.running = true;
  timer.output = true;
  timer.next_clk = clk + (timer.cmp & 0xFFFFu) + 1;
  edge(n, true, clk);
}

void Flexio3::start_free_runners(int64_t clk) {
  for (unsigned n = 0; n < kTimers; ++n) {
    if (timod(timers_[n].ctl) != 0) enable_timer(n, clk);
  }
}

void Flexio3::edge(unsigned source, bool rising, int64_t clk) {
  Launch launch;
  bool launched = false;
  for (unsigned n = 0; n < kTimers; ++n) {
    Timer& timer = timers_[n];
    const Kind kind = kind_of(timer.ctl, timer.cfg);
    if ((kind != Kind::kOneShot && kind != Kind::kTransmitter) || timer.running) continue;
    if (trigger_select(timer.ctl) / 4u != source || trigger_active_low(timer.ctl) == rising) continue;
    if (clk < timer.armed_clk) continue;
    timer.running = true;
    const int64_t span = kind == Kind::kOneShot
                             ? static_cast<int64_t>(timer.cmp & 0xFFFFu) + 1
                             : (static_cast<int64_t>((timer.cmp >> 8) & 0xFFu) + 1) * ((timer.cmp & 0xFFu) + 1);
    timer.next_clk = clk + span;
    if (kind == Kind::kTransmitter) {
      launch_shifters(n, clk, launch);
      launched = true;
    }
  }
  if (!launched) return;
  ++launches_;
  emit(launch, clk, timers_[source]);
}

void Flexio3::launch_shifters(unsigned timer, int64_t, Launch& launch) {
  for (unsigned s = 0; s < kShifters; ++s) {
    const Shifter& shifter = shifters_[s];
    if ((shifter.ctl & 7u) != kSmodTransmit || shifter_timer(shifter.ctl) != timer) continue;
    const uint32_t bit = 1u << s;
    if (shiftstat_ & bit) shifterr_ |= bit;  // SEF: loaded while SHIFTBUF was empty (RM §50.5.1.5)
    shiftstat_ |= bit;                       // SSF: SHIFTBUF moved into the shifter
    if (shifter_pin_config(shifter.ctl) != kPinOutput) continue;
    const PortLine line = output_port_line(flexio3_teensy_pin(model_, static_cast<uint8_t>(shifter_pin(shifter.ctl))));
    if (line.port == kNoFlexioRoute) continue;  // refused when SHIFTCTL was written
    const uint32_t word = frame_word(timers_[timer], shifter.buf);
    (line.is_dir ? launch.dir : launch.step)[line.port] = word;
    launch.ports = static_cast<uint8_t>(launch.ports | (1u << line.port));
  }
}

uint32_t Flexio3::frame_word(const Timer& timer, uint32_t loaded) const {
  // Bit n of the frame word: the pin's level in the middle of microsecond n. The shifter shows
  // bit k of what it loaded during its timer's k-th bit time, then the line is low.
  const int64_t per_bit = bit_clocks(timer.cmp);
  const uint32_t bits = baud_bits(timer.cmp);
  uint32_t word = 0;
  for (uint32_t n = 0; n < 32; ++n) {
    const int64_t sample_clk = (static_cast<int64_t>(2 * n + 1) * clock_.hz) / 2000000;
    const int64_t index = sample_clk / per_bit;
    if (index < bits && index < 32 && ((loaded >> index) & 1u)) word |= 1u << n;
  }
  return word;
}

void Flexio3::emit(const Launch& launch, int64_t clk, const Timer& source) {
  const SimTime start_ns = clock_.time_of(clk);
  const SimTime frame_ns = clock_.duration_ns(2 * (static_cast<int64_t>(source.cmp & 0xFFFFu) + 1));
  for (uint8_t port = 0; port < 4; ++port) {
    if (!(launch.ports & (1u << port))) continue;
    io_.port_frame(port, start_ns, protocol::FrameWords{launch.step[port], launch.dir[port]}, frame_ns);
  }
  if (launch.ports != 0) chip_.stop_cpu_run();
}

bool Flexio3::edge_matters(unsigned source, bool rising) const {
  for (unsigned n = 0; n < kTimers; ++n) {
    const Timer& timer = timers_[n];
    const Kind kind = kind_of(timer.ctl, timer.cfg);
    if (kind != Kind::kOneShot && kind != Kind::kTransmitter) continue;
    if (trigger_select(timer.ctl) / 4u != source || trigger_active_low(timer.ctl) == rising) continue;
    if (kind == Kind::kTransmitter || (timien_ & (1u << n))) return true;
  }
  return false;
}

void Flexio3::settle() {
  const bool high = (timstat_ & timien_) != 0 || (shiftstat_ & shiftsien_) != 0 || (shifterr_ & shifteien_) != 0;
  if (high != irq_high_) {
    irq_high_ = high;
    chip_.set_irq_level(kIrq, high);
  }
  int64_t next = kNever;
  if ((ctrl_ & kCtrlFlexen) && clock_.hz != 0) {
    for (unsigned n = 0; n < kTimers; ++n) {
      const Timer& timer = timers_[n];
      if (!timer.running || timer.next_clk >= next) continue;
      if (timien_ & (1u << n)) {
        next = timer.next_clk;
      } else if (kind_of(timer.ctl, timer.cfg) == Kind::kFreeRunner) {
        // Its next edge, or the one after (the other polarity), if that edge starts a timer
        // that launches frames or interrupts.
        if (edge_matters(n, !timer.output)) {
          next = timer.next_clk;
        } else if (edge_matters(n, timer.output)) {
          next = std::min(next, timer.next_clk + (timer.cmp & 0xFFFFu) + 1);
        }
      }
    }
  }
  if (next == kNever) {
    chip_.scheduler().cancel(wake_);
  } else if (!wake_.scheduled() || wake_.time() != clock_.time_of(next)) {
    chip_.scheduler().schedule(wake_, clock_.time_of(next));
  }
}

}  // namespace stepdance::sim::image
