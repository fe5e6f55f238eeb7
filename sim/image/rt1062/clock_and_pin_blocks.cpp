// Registration of the clock, pin and time blocks.
#include "image/rt1062/clock_and_pin_blocks.hpp"

#include <vector>

namespace stepdance::sim::image::rt1062 {

ClockAndPinBlocks::ClockAndPinBlocks(ChipContext& context, BoardIo& world, TeensyModel model)
    : ccm_analog(context),
      tempmon(Ocotp::kAna1),
      ccm(context, ccm_analog),
      gpio(context, world, model, iomuxc, gpr),
      gpt1(1, context, ccm),
      gpt2(2, context, ccm),
      pit(context, ccm),
      adc1(0, context, ccm, world, model),
      adc2(1, context, ccm, world, model),
      snvs(context) {
  analog_window.add(ccm_analog);
  analog_window.add(pmu);
  analog_window.add(tempmon);
}

namespace {

bool overlaps_any(const PeripheralBus& bus, const Peripheral& block) {
  const uint64_t begin = block.base(), end = begin + block.size_bytes();
  for (const Peripheral* other : bus.blocks()) {
    if (begin < uint64_t{other->base()} + other->size_bytes() && other->base() < end) return true;
  }
  return false;
}

}  // namespace

std::unique_ptr<ClockAndPinBlocks> add_clock_and_pin_blocks(PeripheralBus& bus, ChipContext& context, BoardIo& world,
                                                            TeensyModel model) {
  auto blocks = std::make_unique<ClockAndPinBlocks>(context, world, model);
  std::vector<Peripheral*> all = {&blocks->ccm,      &blocks->analog_window, &blocks->dcdc,  &blocks->iomuxc,
                                  &blocks->gpr,      &blocks->gpt1,          &blocks->gpt2,  &blocks->pit,
                                  &blocks->adc1,     &blocks->adc2,          &blocks->ocotp, &blocks->snvs,
                                  &blocks->flexspi1, &blocks->flexspi2};
  for (QuadTimer& timer : blocks->quad_timers) all.push_back(&timer);
  for (unsigned n = 1; n <= 9; ++n) all.push_back(&blocks->gpio.port(n));
  for (const Peripheral* block : all) {
    if (overlaps_any(bus, *block)) return nullptr;  // checked first: the bus is left as it was
  }
  for (Peripheral* block : all) bus.add(*block);
  Ccm* ccm = &blocks->ccm;
  bus.set_gate_query([ccm](ClockGate gate) { return ccm->gate_on(gate); });
  return blocks;
}

}  // namespace stepdance::sim::image::rt1062
