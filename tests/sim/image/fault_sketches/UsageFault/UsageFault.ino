// Fault fixture for image boards: an integer division by zero with the divide-by-zero trap on
// (SCB_CCR.DIV_0_TRP, ARMv7-M Architecture Reference Manual B3.2.8): a UsageFault.
#include <stdint.h>

volatile int divisor = 0;
volatile int quotient;

__attribute__((noinline)) void divide_by_zero() { quotient = 100 / divisor; }

void setup() {
  volatile uint32_t& ccr = *reinterpret_cast<volatile uint32_t*>(0xE000ED14u);
  ccr = ccr | (1u << 4);
  divide_by_zero();
}
void loop() {}
