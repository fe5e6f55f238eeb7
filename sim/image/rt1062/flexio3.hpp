// FLEXIO3 as the Teensy backend drives it: a free-running frame clock, triggered one-shot timers
// (tick marker, commit guard), and transmit shifters whose words become the output ports' frames.
// RM chapter 50 (FlexIO), registers §50.5.1.
#pragma once

#include <cstdint>

#include "image/chip/board_io.hpp"
#include "image/chip/chip_context.hpp"
#include "image/chip/peripheral.hpp"
#include "image/chip/peripheral_bus.hpp"
#include "image/rt1062/clock_domain.hpp"
#include "image/rt1062/teensy_model.hpp"
#include "kernel/scheduler/event.hpp"

namespace stepdance::sim::image {

/// FLEXIO3 at 0x42020000 (RM §2.3 memory map, AHB), clock gate CCM_CCGR7 CG6, interrupt 156.
///
/// What is modelled (anything else is refused as kUnmodelled when it is written):
///  - timers in three shapes: a free runner (16-bit, TIMENA always, TIMDIS never: its output is
///    high from enable and toggles every TIMCMP + 1 clocks); a one-shot (16-bit, enabled on a
///    trigger edge, disabled on compare: TIMCMP + 1 clocks); a transmitter (dual 8-bit baud,
///    enabled on a trigger edge, disabled on compare: (CMP[15:8] + 1) × (CMP[7:0] + 1) clocks,
///    one bit every 2 × (CMP[7:0] + 1) clocks). Triggers are other timers' outputs (TRGSRC
///    internal, TRGSEL = 4n + 3), either polarity. A timer's TIMSTAT flag sets when it expires.
///  - transmit shifters (SMOD 2, SHIFTCFG 0) with their pin an output (PINCFG 3): they load
///    SHIFTBUF when their timer is enabled and shift it out LSB first, bit n during the timer's
///    n-th bit time. SHIFTSTAT (buffer empty) and SHIFTERR (loaded while empty) as in §50.5.1.
///  - each launch becomes BoardIo::port_frame for the output port whose STEP or DIR pin the
///    shifter's FlexIO3 pin reaches (flexio3_pins.hpp), at the launch time, with bit n = the
///    pin's level in microsecond n of the frame (after the last bit the line is low).
///
/// Time: FlexIO clocks (the FLEXIO2/3 clock root, read from the CCM when FLEXEN is set) counted
/// from that moment; flags are brought up to date at every access, and a scheduler event wakes
/// the model at each launch and at each expiry of a timer with its interrupt enabled.
/// Context: the simulator thread (register accesses and scheduler events).
class Flexio3 final : public Peripheral {
 public:
  static constexpr uint32_t kBase = 0x42020000u;  // RM §2.3, FLEXIO3
  static constexpr unsigned kIrq = 156;           // RM §4.3 table 4-2, FLEXIO3
  static constexpr unsigned kTimers = 8;          // RM §50.1.1: FlexIO2/3 have 8 timers, 8 shifters
  static constexpr unsigned kShifters = 8;

  Flexio3(const PeripheralBus& bus, ChipContext& chip, BoardIo& io, TeensyModel model);
  ~Flexio3() override;
  Flexio3(const Flexio3&) = delete;
  Flexio3& operator=(const Flexio3&) = delete;

  const char* name() const override { return "FLEXIO3"; }
  uint32_t base() const override { return kBase; }
  uint32_t size_bytes() const override { return 0x4000u; }
  ClockGate gate() const override { return {7, 6}; }  // RM §14.7.28, CCM_CCGR7 CG6 flexio3
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

  /// Frame-clock rising edges that launched at least one transmitter since reset. Context: any.
  uint64_t launches() const { return launches_; }
  /// The FlexIO clock the model counts with (0 until FLEXEN was set), in Hz. Context: any.
  uint32_t clock_hz() const { return clock_.hz; }

 private:
  enum class Kind : uint8_t { kOff, kFreeRunner, kOneShot, kTransmitter, kInvalid };

  struct Timer {
    uint32_t ctl = 0;  // TIMCTLn
    uint32_t cfg = 0;  // TIMCFGn
    uint32_t cmp = 0;  // TIMCMPn
    bool running = false;
    bool output = false;    // a free runner's output level
    int64_t next_clk = 0;   // clock of its next expiry (when running)
    int64_t armed_clk = 0;  // trigger edges at or after this clock enable it
  };
  struct Shifter {
    uint32_t ctl = 0;  // SHIFTCTLn
    uint32_t cfg = 0;  // SHIFTCFGn
    uint32_t buf = 0;  // SHIFTBUFn
  };
  /// The words of the ports launched at one edge.
  struct Launch {
    uint32_t step[4] = {};
    uint32_t dir[4] = {};
    uint8_t ports = 0;
  };
  struct Wake : Event {
    explicit Wake(Flexio3& model) : Event(&fire), owner(model) {}
    static void fire(Event& event, Scheduler& scheduler);
    Flexio3& owner;
  };

  // ---- registers (flexio3.cpp) ----
  Access read_register(uint32_t offset, uint32_t& value);
  Access write_register(uint32_t offset, uint32_t value);
  Access write_ctrl(uint32_t value);
  Access write_timctl(unsigned n, uint32_t value);
  Access write_timcfg(unsigned n, uint32_t value);
  Access write_shiftctl(unsigned n, uint32_t value);
  Access write_shiftbuf(unsigned n, uint32_t value);
  Access access_buffer_alias(uint32_t offset, bool is_write, uint32_t& value);
  void reset_registers();

  // ---- timers and shifters (flexio3_engine.cpp) ----
  static Kind kind_of(uint32_t ctl, uint32_t cfg);
  bool trigger_valid(unsigned n, uint32_t ctl) const;
  int64_t now_clk() const;
  void advance();
  void expire(unsigned n);
  void enable_timer(unsigned n, int64_t clk);
  void start_free_runners(int64_t clk);
  void edge(unsigned source, bool rising, int64_t clk);
  void launch_shifters(unsigned timer, int64_t clk, Launch& launch);
  uint32_t frame_word(const Timer& timer, uint32_t loaded) const;
  void emit(const Launch& launch, int64_t clk, const Timer& source);
  bool edge_matters(unsigned source, bool rising) const;
  void settle();

  const PeripheralBus& bus_;
  ChipContext& chip_;
  BoardIo& io_;
  TeensyModel model_;
  Wake wake_;
  ClockDomain clock_;
  uint32_t ctrl_ = 0;       // CTRL
  uint32_t shiftstat_ = 0;  // SHIFTSTAT
  uint32_t shifterr_ = 0;   // SHIFTERR
  uint32_t timstat_ = 0;    // TIMSTAT
  uint32_t shiftsien_ = 0;  // SHIFTSIEN
  uint32_t shifteien_ = 0;  // SHIFTEIEN
  uint32_t timien_ = 0;     // TIMIEN
  Timer timers_[kTimers];
  Shifter shifters_[kShifters];
  bool irq_high_ = false;
  uint64_t launches_ = 0;
};

}  // namespace stepdance::sim::image
