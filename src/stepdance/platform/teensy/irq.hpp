// Interrupt plumbing of the Teensy backend: vectors, NVIC priorities, pending bits, context test.
//
// Priorities (NVIC, lower number = more urgent; the RT1062 implements 16 levels, multiples of 16).
// Teensyduino itself uses 32 for SysTick and 128 for most peripherals (USB included).
//
//   capture ISRs   0    DIR must be sampled within ~1 µs of a STEP edge
//   tick ISR      16    re-arms the output buffers after each hardware frame launch (~0.2 µs)
//   frame ISR     48    the five frame stages (up to tens of µs)
//   kHz ISR      144    buttons; below USB so it can never delay a frame or the USB stack
//   ADC ISRs     176    analog round robin
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

namespace stepdance::platform::teensy::irq {

constexpr uint8_t kCapturePriority = 0;
constexpr uint8_t kTickPriority = 16;
constexpr uint8_t kFramePriority = 48;
constexpr uint8_t kKilohertzPriority = 144;
constexpr uint8_t kAdcPriority = 176;

/// Points `irq` at `handler`, sets its priority and enables it. Context: loop.
void install(uint8_t irq, void (*handler)(), uint8_t priority);
/// Disables an interrupt and drops a pending request. Context: any.
void disable(uint8_t irq);
/// Requests an interrupt from software (used for the frame ISR). Context: any.
void pend(uint8_t irq);
/// Masks every interrupt of priority number `priority` or more (BASEPRI_MAX; never lowers a
/// level already set); more urgent ones keep running. Returns the previous BASEPRI for unmask().
/// `priority` must be a non-zero multiple of 16. Context: any.
uint32_t mask_from(uint8_t priority);
/// Restores the BASEPRI mask_from() returned. Context: any.
void unmask(uint32_t previous);
/// True in thread mode (the loop), false inside any exception handler. Context: any.
bool in_thread_mode();

}  // namespace stepdance::platform::teensy::irq

#endif  // __IMXRT1062__
