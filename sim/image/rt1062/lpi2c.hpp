// LPI2C1 and LPI2C3 masters as Teensyduino 1.59's Wire drives them (QWIIC0 = Wire on LPI2C1,
// pins 18/19; QWIIC1 = Wire1 on LPI2C3, pins 17/16). RM chapter 47 (LPI2C), registers §47.4.
#pragma once

#include <cstdint>
#include <deque>
#include <vector>

#include "image/chip/board_io.hpp"
#include "image/chip/chip_context.hpp"
#include "image/chip/peripheral.hpp"
#include "image/chip/peripheral_bus.hpp"
#include "kernel/scheduler/event.hpp"

namespace stepdance::sim::image {

/// One LPI2C master, 32-bit registers. The command words written to MTDR go through a 4-word
/// transmit FIFO and leave it at the bus's pace (SCL period from MCCR0, MCFGR1 PRESCALE and the
/// LPI2C clock root): START + address 10 bit times, a data byte 9, RECEIVE 9 per byte, STOP 1.
/// One START's worth of commands (a segment) becomes one BoardIo::i2c_transfer: a write segment
/// once its address is out and its end is known (its STOP or the next START is in the FIFO), or
/// when its last byte has gone out and nothing follows (Wire's endTransmission(false) waits
/// there); a read segment when its RECEIVE starts, its bytes then arriving in the receive FIFO
/// one byte time apart. A NACK sets NDF and halts the FIFO where the hardware stops: after the
/// address for an address NACK (the data still queued), after the data for a data NACK; it stays
/// halted until software clears NDF or resets the FIFOs, as Wire expects. A bus error sets ALF, a
/// timeout PLTF. So Wire's write-then-read (a repeated START) reaches the world as two transfers,
/// a write and a read.
/// Refused (kUnmodelled): slave registers, interrupt and DMA enables, MCFGR1 options other than
/// PRESCALE, high-speed and expect-NACK commands, non-32-bit accesses.
class Lpi2c final : public Peripheral {
 public:
  /// `instance` 1 (QWIIC0, bus 0) or 3 (QWIIC1, bus 1). Context: board construction.
  Lpi2c(unsigned instance, const PeripheralBus& bus, ChipContext& chip, BoardIo& io);
  ~Lpi2c() override;
  Lpi2c(const Lpi2c&) = delete;
  Lpi2c& operator=(const Lpi2c&) = delete;

  const char* name() const override { return instance_ == 1 ? "LPI2C1" : "LPI2C3"; }
  uint32_t base() const override { return 0x403F0000u + 0x4000u * (instance_ - 1); }  // RM §2.3
  uint32_t size_bytes() const override { return 0x4000u; }
  /// CCM_CCGR2 CG3 lpi2c1, CG5 lpi2c3 (RM §14.7.23).
  ClockGate gate() const override { return {2, static_cast<int8_t>(instance_ == 1 ? 3 : 5)}; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

  /// The SCL frequency the registers give now, in Hz (0 if the clock root cannot be read).
  uint32_t scl_hz() const;

 private:
  struct Command {
    uint16_t word;      // MTDR: CMD 10:8, DATA 7:0
    SimTime queued_ns;  // when it was written
  };
  struct Segment {
    bool open = false;
    bool executed = false;
    uint8_t address = 0;
    bool is_read = false;
    std::vector<uint8_t> written;
    size_t prefetched = 0;  // TRANSMITs still in the FIFO whose bytes went with the transfer
  };
  struct Wake : Event {
    explicit Wake(Lpi2c& model) : Event(&fire), owner(model) {}
    static void fire(Event& event, Scheduler& scheduler);
    Lpi2c& owner;
  };

  // ---- registers (lpi2c.cpp) ----
  Access write_mcr(uint32_t value);
  uint32_t msr() const;
  void reset_master();
  // ---- the command engine (lpi2c_master.cpp) ----
  void advance(SimTime now_ns);
  bool step(SimTime now_ns);
  SimTime duration_ns(uint16_t word) const;
  void apply(uint16_t word, SimTime at_ns);
  int execute(SimTime at_ns, size_t read_length);
  void execute_known_write(SimTime at_ns);
  void schedule_wake(SimTime now_ns);

  unsigned instance_;
  const PeripheralBus& bus_;
  ChipContext& chip_;
  BoardIo& io_;
  Wake wake_;
  uint32_t mcr_ = 0, flags_ = 0, mcfgr_[4] = {}, mccr0_ = 0, mccr1_ = 0, mfcr_ = 0, mdmr_ = 0;
  std::deque<Command> tx_;
  std::deque<std::pair<SimTime, uint8_t>> rx_;  // received bytes and their arrival times
  bool head_started_ = false;
  SimTime head_start_ns_ = 0;
  SimTime line_free_ns_ = 0;  // when the bus finishes what it is doing
  bool halted_ = false;       // after a NACK, until NDF is cleared or the FIFO reset
  bool bus_busy_ = false;     // between a START and its STOP
  Segment segment_;
};

}  // namespace stepdance::sim::image
