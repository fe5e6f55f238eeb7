// POSIX calls GoogleTest references that newlib + rdimon lack; each fails cleanly with ENOSYS.
#include <errno.h>
#include <stddef.h>
#include <sys/stat.h>
#include <sys/types.h>

extern "C" {

char* getcwd(char*, size_t) {
  errno = ENOSYS;
  return nullptr;
}
int mkdir(const char*, mode_t) {
  errno = ENOSYS;
  return -1;
}
int chdir(const char*) {
  errno = ENOSYS;
  return -1;
}
int rmdir(const char*) {
  errno = ENOSYS;
  return -1;
}

}  // extern "C"
