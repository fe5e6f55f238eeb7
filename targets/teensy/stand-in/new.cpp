// The real core's operator new and delete (cores/teensy4/new.cpp): every form on malloc and free,
// all in one object. The build archives the stand-in core as Arduino archives the real one, so
// this object joins an image only when something needs one of its symbols.
#include <stddef.h>
#include <stdlib.h>

void* operator new(size_t size) { return malloc(size); }
void* operator new[](size_t size) { return malloc(size); }
void operator delete(void* pointer) noexcept { free(pointer); }
void operator delete[](void* pointer) noexcept { free(pointer); }
void operator delete(void* pointer, size_t) noexcept { free(pointer); }
void operator delete[](void* pointer, size_t) noexcept { free(pointer); }
