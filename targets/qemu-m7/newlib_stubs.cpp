// POSIX calls GoogleTest references that newlib + rdimon lack; each fails cleanly with ENOSYS.
#include <errno.h>
#include <sys/stat.h>
#include <sys/types.h>

extern "C" {

// Used by GoogleTest only to create the directory of an XML/JSON report, which we never request.
int mkdir(const char*, mode_t) {
  errno = ENOSYS;
  return -1;
}

}  // extern "C"
