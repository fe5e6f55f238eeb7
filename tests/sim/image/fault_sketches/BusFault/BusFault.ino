// Fault fixture for image boards: a register read from a block whose clock gate is off, which
// the i.MX RT1062 answers with a bus error (reference manual 14.5 "clock gating"): a BusFault.
#include <stdint.h>

volatile uint32_t sink;

// GPT1's bus clock is CCM_CCGR1 CG10 (RM 14.7.22); GPT1_CR is at 0x401EC000 (RM 52.7.1).
__attribute__((noinline)) void read_gated_timer() {
  volatile uint32_t& ccgr1 = *reinterpret_cast<volatile uint32_t*>(0x400FC06Cu);
  ccgr1 = ccgr1 & ~(3u << 20);
  sink = *reinterpret_cast<volatile uint32_t*>(0x401EC000u);
}

void setup() { read_gated_timer(); }
void loop() {}
