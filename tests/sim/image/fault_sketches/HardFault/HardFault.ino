// Fault fixture for image boards: a breakpoint instruction with no debugger attached, which the
// Cortex-M7 escalates to a HardFault (ARMv7-M Architecture Reference Manual C1.4, B1.5.14).
__attribute__((noinline)) void hit_breakpoint() { __asm__ volatile("bkpt #0"); }

void setup() { hit_breakpoint(); }
void loop() {}
