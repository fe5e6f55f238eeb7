// Boot headers, vector table and reset handler of the CI firmware image (a size check, not bootable).
//
// The layout follows the i.MX RT1062 boot flow from FlexSPI NOR (reference manual, chapter 9
// "System Boot"): a FlexSPI configuration block at 0x60000000, the image vector table (IVT) at
// 0x60001000 naming the entry point, then the program. Our configuration block is all zeros,
// where a real image carries the parameters of the board's flash chip, so the boot ROM would
// refuse this image: it exists to make the flash and RAM figures of the link realistic.
//
// The heap's system calls are here too, as the real core's startup.c holds _sbrk: the start-up
// object always links (the entry point is in it), so newlib, which comes after the core archive on
// the link line, finds them when an image allocates.
#include <stddef.h>
#include <stdint.h>

extern void (*volatile stand_in_vectors_ram[176])();
int main();

extern "C" {

// Symbols of targets/teensy/ld/imxrt1062_sections.ld.
extern uint32_t _stack_top[];
extern uint32_t _itcm_start[], _itcm_end[], _itcm_load[];
extern uint32_t _data_start[], _data_end[], _data_load[];
extern uint32_t _bss_start[], _bss_end[];
extern uint32_t _flash_image_start[], _flash_image_length[];
extern void (*_init_array_start[])();
extern void (*_init_array_end[])();

[[noreturn]] void stand_in_reset_handler();
[[noreturn]] void stand_in_start();
void stand_in_unused_handler();

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

namespace {

/// Image vector table (reference manual 9.7.1.1), eight 32-bit words.
struct ImageVectorTable {
  uint32_t header;  // tag 0xD1, length 32 (big-endian), version 0x41
  const void* entry;
  uint32_t reserved1;
  const void* device_configuration_data;
  const void* boot_data;
  const void* self;
  const void* command_sequence_file;
  uint32_t reserved2;
};

/// Boot data (reference manual 9.7.1.2): where the image starts, how long it is, plugin flag.
struct BootData {
  const void* start;
  const void* length;
  uint32_t plugin;
  uint32_t reserved;
};

__attribute__((section(".flexspi_config"), used)) const uint32_t kFlexSpiConfigPlaceholder[128] = {};

__attribute__((section(".boot_data"), used)) const BootData kBootData = {
    _flash_image_start,
    _flash_image_length,  // a length the linker script defines as an absolute symbol
    0,
    0,
};

__attribute__((section(".image_vector_table"), used)) const ImageVectorTable kImageVectorTable = {
    0x412000D1u, reinterpret_cast<const void*>(&stand_in_reset_handler), 0, nullptr, &kBootData,
    &kImageVectorTable, nullptr, 0,
};

volatile uint32_t& reg(uintptr_t address) { return *reinterpret_cast<volatile uint32_t*>(address); }

constexpr uintptr_t kCpacr = 0xE000ED88u;       // Coprocessor Access Control (ARMv7-M ARM B3.2.20)
constexpr uint32_t kCp10Cp11Full = 0xFu << 20;  // full access to CP10 and CP11: the FPU
constexpr uintptr_t kVtor = 0xE000ED08u;        // Vector Table Offset Register (B3.2.5)

__attribute__((section(".startup"))) void copy_words(uint32_t* to, uint32_t* end, const uint32_t* from) {
  while (to < end) *to++ = *from++;
}

}  // namespace

extern "C" void stand_in_unused_handler() {
  for (;;) {
  }
}

// The boot ROM jumps here from the IVT with its own stack: move to ours before any C++ runs.
extern "C" __attribute__((naked, section(".startup"))) void stand_in_reset_handler() {
  __asm__ volatile(
      "ldr r0, =_stack_top\n\t"
      "mov sp, r0\n\t"
      "b stand_in_start");
}

// `used`: only the reset handler's assembly names it, which link-time optimisation cannot see.
extern "C" __attribute__((section(".startup"), used)) void stand_in_start() {
  reg(kCpacr) |= kCp10Cp11Full;
  __asm__ volatile("dsb\n\tisb" ::: "memory");

  copy_words(_itcm_start, _itcm_end, _itcm_load);
  copy_words(_data_start, _data_end, _data_load);
  for (uint32_t* word = _bss_start; word < _bss_end;) *word++ = 0;

  for (auto& vector : stand_in_vectors_ram) vector = &stand_in_unused_handler;
  reg(kVtor) = static_cast<uint32_t>(reinterpret_cast<uintptr_t>(stand_in_vectors_ram));

  for (auto* constructor = _init_array_start; constructor < _init_array_end; ++constructor) {
    (*constructor)();
  }
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
