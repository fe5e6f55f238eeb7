// The real core's heap and the newlib system calls behind it, for an image that allocates (the
// SD library does). Teensyduino gives malloc the free part of RAM2 (OCRAM); the model is a fixed
// arena there. Only an image that calls malloc or operator new links any of this, and the build's
// no-heap check then rejects that image: these exist so the link completes and the check can see it.
#include <stddef.h>
#include <stdint.h>

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
