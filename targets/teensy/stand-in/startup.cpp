// Reset handler and start-up sequence of the CI firmware image, written from the i.MX RT1062
// reference manual (RM, IMXRT1060RM rev 3) and the ARMv7-M Architecture Reference Manual.
//
// The boot ROM reads the boot headers (boot_headers.cpp) and jumps to stand_in_reset_handler with
// the FlexRAM in its fused layout, the core on its boot clock and its own stack. From there:
//   1. FlexRAM banks as the linker script lays them out (ITCM banks for the code, the rest DTCM;
//      IOMUXC_GPR17/16/14, RM §11.4), stack pointer to the top of DTCM;
//   2. FPU on (CPACR), ITCM code and .data copied from flash, .bss zeroed      → stand_in_memory_ready
//   3. vector table in RAM (VTOR), fault handlers, interrupt priorities 128    → stand_in_vectors_ready
//   4. MPU regions (stack guard included) and caches → stand_in_memory_protection_ready
//   5. clocks: 600 MHz core, 150 MHz bus, PLL3 at 480 MHz → stand_in_clocks_ready
//   6. SysTick at 1 kHz, interrupts on → stand_in_systick_ready
//   7. ADC calibration → stand_in_analog_ready; the USB serial start hook → stand_in_usb_ready
//   8. C++ constructors (init_array) → stand_in_constructors_done; then main(): setup(), loop().
// Everything before the copy in step 2 runs from flash: it is in `.startup`, and loops there are
// written with volatile accesses so the compiler cannot turn them into memcpy/memset calls (which
// live in ITCM, not yet copied).
//
// The heap's system calls are here too, as the real core's startup.c holds _sbrk: the start-up
// object always links (the entry point is in it), so newlib, which comes after the core archive on
// the link line, finds them when an image allocates.
#include <stddef.h>
#include <stdint.h>

#include "stand_in_hooks.h"
#include "stand_in_registers.h"
#include "stand_in_startup.h"

extern void (*volatile stand_in_vectors_ram[176])();
int main();

extern "C" {

// Symbols of targets/teensy/ld/imxrt1062_sections.ld.
extern uint32_t _stack_top[];
extern uint32_t _itcm_start[], _itcm_end[], _itcm_load[];
extern uint32_t _data_start[], _data_end[], _data_load[];
extern uint32_t _bss_start[], _bss_end[];
extern uint32_t _flexram_bank_config[];
extern void (*_init_array_start[])();
extern void (*_init_array_end[])();

[[noreturn]] void stand_in_reset_handler();
[[noreturn]] void stand_in_start();

// Normally in crtbegin.o, which -nostartfiles leaves out; names this image to __aeabi_atexit.
void* __dso_handle = &__dso_handle;

// Static destructors are never run: the firmware never returns from main().
int __aeabi_atexit(void*, void (*)(void*), void*) { return 0; }

// Called if a pure virtual function is ever called through a half-built object.
[[noreturn]] void __cxa_pure_virtual() {
  for (;;) {
  }
}

}  // extern "C"

// ---- 1. Reset: FlexRAM and stack ------------------------------------------------------------------
// Assembly, because nothing may touch the stack before the FlexRAM holds it. GPR17 gives each 32 KB
// bank its role (2 bits per bank: 11 ITCM, 10 DTCM; _flexram_bank_config from the linker script),
// GPR16 makes GPR17 the source of the layout (FLEXRAM_BANK_CFG_SEL) with both TCMs enabled, keeping
// CM7_INIT_VTOR (bits 31:7), and GPR14 opens the 512 KB ITCM and DTCM address windows (size code
// 0xA). RM §11.4 (IOMUXC_GPR_GPR14/16/17), RM §30 (FlexRAM).
extern "C" __attribute__((naked, section(".startup"))) void stand_in_reset_handler() {
  __asm__ volatile(
      "ldr r0, =0x400AC000\n\t"  // IOMUXC_GPR
      "ldr r1, =_flexram_bank_config\n\t"
      "str r1, [r0, #0x44]\n\t"  // GPR17 = bank roles
      "ldr r1, [r0, #0x40]\n\t"
      "orr r1, r1, #7\n\t"  // GPR16 |= INIT_ITCM_EN | INIT_DTCM_EN | FLEXRAM_BANK_CFG_SEL
      "str r1, [r0, #0x40]\n\t"
      "ldr r1, [r0, #0x38]\n\t"
      "bic r1, r1, #0x00FF0000\n\t"
      "orr r1, r1, #0x00AA0000\n\t"  // GPR14: CM7_CFGDTCMSZ = CM7_CFGITCMSZ = 0xA (512 KB)
      "str r1, [r0, #0x38]\n\t"
      "dsb\n\t"
      "isb\n\t"
      "ldr r0, =_stack_top\n\t"
      "mov sp, r0\n\t"
      "b stand_in_start\n\t"
      ".ltorg");  // the constants right here: ldr reaches only 4 KB, and LTO may put more code after
}

namespace {

using stand_in::reg32;

// ---- 2. Memory ------------------------------------------------------------------------------------
__attribute__((section(".startup"), noinline)) void copy_words(uint32_t* to, uint32_t* end, const uint32_t* from) {
  volatile uint32_t* target = to;
  while (target < end) *target++ = *from++;
}

__attribute__((section(".startup"), noinline)) void zero_words(uint32_t* to, uint32_t* end) {
  volatile uint32_t* target = to;
  while (target < end) *target++ = 0;
}

// ---- 3. Vectors -----------------------------------------------------------------------------------
constexpr int kExceptionCount = 16;                 // Cortex-M7 system exceptions before the first interrupt
constexpr int kInterruptCount = 160;                // i.MX RT1062 interrupts, RM chapter 4
constexpr uint8_t kDefaultInterruptPriority = 128;  // as Teensyduino: half way, below SysTick (32)

__attribute__((section(".startup"), noinline)) void install_vectors() {
  for (int i = 0; i < kExceptionCount + kInterruptCount; ++i) stand_in_vectors_ram[i] = &stand_in_unused_handler;
  stand_in_vectors_ram[3] = &stand_in_hard_fault;  // ARMv7-M ARM §B1.5.2 exception numbers
  stand_in_vectors_ram[4] = &stand_in_mem_manage_fault;
  stand_in_vectors_ram[5] = &stand_in_bus_fault;
  stand_in_vectors_ram[6] = &stand_in_usage_fault;
  stand_in_vectors_ram[15] = &stand_in_systick_isr;
  volatile uint8_t* priority = reinterpret_cast<volatile uint8_t*>(stand_in::nvic::kIpr0);
  for (int irq = 0; irq < kInterruptCount; ++irq) priority[irq] = kDefaultInterruptPriority;
  stand_in::barrier();
  reg32(stand_in::scb::kVtor) = static_cast<uint32_t>(reinterpret_cast<uintptr_t>(stand_in_vectors_ram));
  // MemManage, BusFault and UsageFault get their own handlers instead of escalating to HardFault.
  reg32(stand_in::scb::kShcsr) |= stand_in::scb::kShcsrFaultsEnabled;
  stand_in::barrier();
}

__attribute__((section(".startup"), noinline)) void run_constructors() {
  for (auto* constructor = _init_array_start; constructor < _init_array_end; ++constructor) (*constructor)();
}

}  // namespace

// ---- Markers (stand_in_startup.h): empty, never inlined, so each stays a call at its own address --
#define STAND_IN_MARKER(name) \
  extern "C" __attribute__((section(".startup"), noinline, used)) void name() { __asm__ volatile(""); }
STAND_IN_MARKER(stand_in_memory_ready)
STAND_IN_MARKER(stand_in_vectors_ready)
STAND_IN_MARKER(stand_in_memory_protection_ready)
STAND_IN_MARKER(stand_in_clocks_ready)
STAND_IN_MARKER(stand_in_systick_ready)
STAND_IN_MARKER(stand_in_analog_ready)
STAND_IN_MARKER(stand_in_usb_ready)
STAND_IN_MARKER(stand_in_constructors_done)
#undef STAND_IN_MARKER

// ---- Fault handlers: a loop at the handler's own symbol, in flash, so a stopped core names the fault
#define STAND_IN_PARKING_HANDLER(name) \
  extern "C" __attribute__((naked, section(".startup"), used)) void name() { __asm__ volatile("b " #name); }
STAND_IN_PARKING_HANDLER(stand_in_hard_fault)
STAND_IN_PARKING_HANDLER(stand_in_mem_manage_fault)
STAND_IN_PARKING_HANDLER(stand_in_bus_fault)
STAND_IN_PARKING_HANDLER(stand_in_usage_fault)
STAND_IN_PARKING_HANDLER(stand_in_unused_handler)
#undef STAND_IN_PARKING_HANDLER

/// The USB serial driver's start (stand_in_hooks.h); this default, for an image without one, does
/// nothing.
extern "C" __attribute__((weak)) void stand_in_usb_serial_start() {}

// `used`: only the reset handler's assembly names it, which link-time optimisation cannot see.
extern "C" __attribute__((section(".startup"), used)) void stand_in_start() {
  // 2. The FPU first: any later code may use floating-point registers (ARMv7-M ARM §B3.2.20).
  reg32(stand_in::scb::kCpacr) |= stand_in::scb::kCpacrFpuFull;
  stand_in::barrier();
  // Analog bandgap: bias currents from the bandgap, not the self-bias circuit (RM, PMU_MISC0).
  reg32(stand_in::pmu::kMisc0Set) = stand_in::pmu::kMisc0RefTopSelfBiasOff;
  copy_words(_itcm_start, _itcm_end, _itcm_load);
  copy_words(_data_start, _data_end, _data_load);
  zero_words(_bss_start, _bss_end);
  stand_in::barrier();
  stand_in_memory_ready();

  install_vectors();
  stand_in_vectors_ready();
  stand_in_memory_protection_start();
  stand_in_memory_protection_ready();
  stand_in_clocks_start();
  stand_in_clocks_ready();
  stand_in_systick_start();
  __asm__ volatile("cpsie i" ::: "memory");  // PRIMASK = 0 (ARMv7-M ARM §B5.2.1 CPS)
  stand_in_systick_ready();
  stand_in_analog_start();
  stand_in_analog_ready();
  stand_in_usb_serial_start();
  stand_in_usb_ready();

  run_constructors();
  stand_in_constructors_done();
  main();
  for (;;) {
  }
}

// ---- The real core's heap and the newlib system calls behind it --------------------------------
// For an image that allocates (the SD library does). Teensyduino gives malloc the free part of RAM2
// (OCRAM); the model is a fixed arena there. Only an image that calls malloc or operator new links
// any of this, and the build's no-heap check then rejects that image: these exist so the link
// completes and the check can see it.

namespace {
constexpr size_t kHeapBytes = 16 * 1024;
alignas(8) __attribute__((section(".bss.dma"))) char heap_arena[kHeapBytes];
size_t heap_used = 0;
}  // namespace

extern "C" {

void* _sbrk(ptrdiff_t increment) {
  const ptrdiff_t next = static_cast<ptrdiff_t>(heap_used) + increment;
  if (next < 0 || static_cast<size_t>(next) > kHeapBytes) return reinterpret_cast<void*>(-1);
  char* previous = heap_arena + heap_used;
  heap_used = static_cast<size_t>(next);
  return previous;
}

[[noreturn]] void _exit(int) {
  for (;;) {
  }
}

int _kill(int, int) { return -1; }
int _getpid() { return 1; }

}  // extern "C"
