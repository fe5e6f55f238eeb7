// Reset and fault vectors for the Cortex-M7 of QEMU's mps2-an500: FPU on, RAM set up, then main().
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

extern "C" {

int main(int argc, char** argv);
void initialise_monitor_handles(void);
void __libc_init_array(void);

extern uint32_t __stack_top[];
extern uint32_t __data_start[], __data_end[], __data_load[];
extern uint32_t __bss_start[], __bss_end[];

// Normally in crti.o / crtbegin.o, which -nostartfiles leaves out: __libc_init_array calls
// _init, and static destructors registered with __cxa_atexit name this image's __dso_handle.
void _init(void) {}
void _fini(void) {}
void* __dso_handle = &__dso_handle;

[[noreturn]] void reset_handler(void);
[[noreturn]] void fault_handler(void);

}  // extern "C"

namespace {

volatile uint32_t& reg(uintptr_t address) { return *reinterpret_cast<volatile uint32_t*>(address); }

constexpr uintptr_t kCpacr = 0xE000ED88u;       // Coprocessor Access Control (ARMv7-M ARM B3.2.20)
constexpr uint32_t kCp10Cp11Full = 0xFu << 20;  // full access to CP10 and CP11: the FPU
constexpr uintptr_t kCfsr = 0xE000ED28u;        // Configurable Fault Status Register
constexpr uintptr_t kHfsr = 0xE000ED2Cu;        // HardFault Status Register
constexpr uintptr_t kIcsr = 0xE000ED04u;        // Interrupt Control and State (VECTACTIVE in 8:0)

}  // namespace

extern "C" void reset_handler(void) {
  // Nothing before this store may touch a floating-point register.
  reg(kCpacr) |= kCp10Cp11Full;
  __asm__ volatile("dsb\n\tisb" ::: "memory");

  for (uint32_t *from = __data_load, *to = __data_start; to < __data_end;) *to++ = *from++;
  for (uint32_t* word = __bss_start; word < __bss_end;) *word++ = 0;

  initialise_monitor_handles();
  __libc_init_array();
  char program[] = "qemu-m7";
  char* argv[] = {program, nullptr};
  exit(main(1, argv));
}

extern "C" void fault_handler(void) {
  // Reported over semihosting, so a crash fails the run at once instead of hanging until timeout.
  printf("\nFAULT: exception %lu, CFSR=0x%08lx HFSR=0x%08lx\n", static_cast<unsigned long>(reg(kIcsr) & 0x1FFu),
         static_cast<unsigned long>(reg(kCfsr)), static_cast<unsigned long>(reg(kHfsr)));
  fflush(stdout);
  _Exit(3);
}

using Vector = void (*)(void);

// The vector table: the initial stack pointer, then reset and the system exceptions; the
// images here enable no peripheral interrupt, so any other exception is a fault.
__attribute__((section(".vectors"), used)) const Vector vector_table[16] = {
    reinterpret_cast<Vector>(__stack_top),
    reset_handler,
    fault_handler,  // NMI
    fault_handler,  // HardFault
    fault_handler,  // MemManage
    fault_handler,  // BusFault
    fault_handler,  // UsageFault
    nullptr,
    nullptr,
    nullptr,
    nullptr,
    fault_handler,  // SVCall
    fault_handler,  // DebugMonitor
    nullptr,
    fault_handler,  // PendSV
    fault_handler,  // SysTick
};
