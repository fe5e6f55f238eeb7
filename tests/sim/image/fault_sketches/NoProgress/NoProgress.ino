// Fault fixture for image boards: interrupts off, then a loop nothing can ever leave.
__attribute__((noinline)) void wait_forever() {
  __asm__ volatile("cpsid i");
  for (;;) {
  }
}

void setup() { wait_forever(); }
void loop() {}
