// Teensy 4.0 / 4.1 pinout (fact source: PJRC teensy4/core_pins.h, tag 1.59).
#include "image/rt1062/teensy_pins.hpp"

#include "image/rt1062/pads.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

struct PinPad {
  PadBank bank;
  int8_t n;
};
using B = PadBank;

// Pins 0..33: the same pads on both boards.
constexpr PinPad kCommon[34] = {
    {B::kAdB0, 3},  {B::kAdB0, 2},  {B::kEmc, 4},   {B::kEmc, 5},  {B::kEmc, 6},    // 0-4
    {B::kEmc, 8},   {B::kB0, 10},   {B::kB1, 1},    {B::kB1, 0},   {B::kB0, 11},    // 5-9
    {B::kB0, 0},    {B::kB0, 2},    {B::kB0, 1},    {B::kB0, 3},   {B::kAdB1, 2},   // 10-14
    {B::kAdB1, 3},  {B::kAdB1, 7},  {B::kAdB1, 6},  {B::kAdB1, 1}, {B::kAdB1, 0},   // 15-19
    {B::kAdB1, 10}, {B::kAdB1, 11}, {B::kAdB1, 8},  {B::kAdB1, 9}, {B::kAdB0, 12},  // 20-24
    {B::kAdB0, 13}, {B::kAdB1, 14}, {B::kAdB1, 15}, {B::kEmc, 32}, {B::kEmc, 31},   // 25-29
    {B::kEmc, 37},  {B::kEmc, 36},  {B::kB0, 12},   {B::kEmc, 7},                   // 30-33
};
// Teensy 4.0 pins 34..39: the SD pads underneath.
constexpr PinPad kTeensy40[6] = {{B::kSdB0, 3}, {B::kSdB0, 2}, {B::kSdB0, 1},
                                 {B::kSdB0, 0}, {B::kSdB0, 5}, {B::kSdB0, 4}};
// Teensy 4.1 pins 34..54: edge pins 34..41, the SD socket 42..47, the memory pads 48..54.
constexpr PinPad kTeensy41[21] = {
    {B::kB1, 13},  {B::kB1, 12},  {B::kB1, 2},   {B::kB1, 3},   {B::kAdB1, 12}, {B::kAdB1, 13},  // 34-39
    {B::kAdB1, 4}, {B::kAdB1, 5},                                                                // 40-41
    {B::kSdB0, 3}, {B::kSdB0, 2}, {B::kSdB0, 1}, {B::kSdB0, 0}, {B::kSdB0, 5},  {B::kSdB0, 4},   // 42-47
    {B::kEmc, 24}, {B::kEmc, 27}, {B::kEmc, 28}, {B::kEmc, 22}, {B::kEmc, 26},  {B::kEmc, 25},   // 48-53
    {B::kEmc, 29},                                                                               // 54
};

}  // namespace

uint8_t highest_pin(TeensyModel model) { return model == TeensyModel::kTeensy40 ? 39 : 54; }

int teensy_pin_pad(TeensyModel model, uint8_t pin) {
  if (pin > highest_pin(model)) return -1;
  const PinPad& p = pin < 34                          ? kCommon[pin]
                    : model == TeensyModel::kTeensy40 ? kTeensy40[pin - 34]
                                                      : kTeensy41[pin - 34];
  return pad_index(p.bank, p.n);
}

int pad_teensy_pin(TeensyModel model, int pad) {
  for (uint8_t pin = 0; pin <= highest_pin(model); ++pin) {
    if (teensy_pin_pad(model, pin) == pad) return pin;
  }
  return -1;
}

}  // namespace stepdance::sim::image::rt1062
