// Stand-in SdFat: a slot with no card in it. Nothing allocates, as in the real library.
#include <SdFat.h>

bool FsVolume::remove(const char*) { return false; }
bool SdFs::begin(SdioConfig) { return mounted_ = false; }
bool FsFile::open(FsVolume*, const char*, oflag_t) { return open_ = false; }
int FsFile::read(void*, size_t) { return -1; }
size_t FsFile::write(const void*, size_t) { return 0; }
bool FsFile::close() {
  const bool was_open = open_;
  open_ = false;
  return was_open;
}
