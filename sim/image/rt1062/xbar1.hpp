// XBARA1: the crossbar that routes pads (IOMUX_XBAR_INOUTnn) to peripheral inputs such as the
// ENC phase inputs, and peripherals' trigger pulses (PIT_TRIGGERn) to others (ENC TRIGGER). RM chapter 61 (XBAR),
// registers §61.4; input and output numbers from RM chapter 4 (XBAR1 input and output assignments), as regs_xbar.hpp
// cites them.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "image/chip/peripheral.hpp"

namespace stepdance::sim::image {

/// XBARA1 at 0x403BC000, gate CCM_CCGR2 CG11. SELn (16 bits at 2n, n = 0..65) selects the input
/// of output 2n (bits 6:0) and 2n+1 (bits 14:8); bits 7 and 15 are reserved (read 0). CTRL0/1
/// (edge detection, DMA and interrupt requests) are stored only while their enables stay 0.
class Xbar1 final : public Peripheral {
 public:
  static constexpr unsigned kOutputs = 132;
  /// Input of PIT_TRIGGER0; PIT_TRIGGERn is this + n (RM chapter 4, XBAR1 input assignments).
  static constexpr uint8_t kInputPitTrigger0 = 56;
  /// Called after every SELn write (the ENC models re-check their phase routing).
  using Listener = std::function<void()>;

  const char* name() const override { return "XBARA1"; }
  uint32_t base() const override { return 0x403BC000u; }  // RM §2.3
  uint32_t size_bytes() const override { return 0x4000u; }
  ClockGate gate() const override { return {2, 11}; }  // RM §14.7.23, CCM_CCGR2 CG11 xbar1
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

  /// The input (0..127) output `output` selects (0 = logic low after reset). Context: any.
  uint8_t input_of(unsigned output) const { return output < kOutputs ? select_[output] : 0; }
  void add_listener(Listener listener) { listeners_.push_back(std::move(listener)); }

  /// A peripheral's trigger pulse on input `input` (0..127): every output that selects it passes
  /// the rising edge on to the block behind it, at once (the XBAR is combinational; RM §61.1).
  /// Context: the model event that makes the pulse.
  void pulse(uint8_t input) const;
  /// Calls `listener` for each rising edge passed on to output `output` (the block behind it
  /// registers, e.g. ENCn TRIGGER). Context: board construction.
  void on_output_edge(unsigned output, Listener listener) { edge_listeners_.push_back({output, std::move(listener)}); }

 private:
  struct EdgeListener {
    unsigned output;
    Listener listener;
  };
  uint8_t select_[kOutputs] = {};
  uint16_t ctrl_[2] = {};
  std::vector<Listener> listeners_;
  std::vector<EdgeListener> edge_listeners_;
};

}  // namespace stepdance::sim::image
