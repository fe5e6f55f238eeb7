// Stand-in SdFat: a slot with no card in it. Nothing allocates, as in the real library.
#include <SdFat.h>

bool FsVolume::begin(FsBlockDevice*) { return mounted_ = false; }
bool FsVolume::remove(const char*) { return false; }
bool SdioCard::begin(SdioConfig) { return false; }
bool SdioCard::isBusy() { return false; }
uint8_t SdioCard::errorCode() const { return 0x17; }  // any non-zero code: no card answered
bool DedicatedSpiCard::isBusy() { return false; }
uint8_t DedicatedSpiCard::errorCode() const { return 0x17; }
bool SdFs::begin(SdioConfig config) {
  card_ = card_factory_.newCard(config);
  return card_ != nullptr && FsVolume::begin(card_);
}
bool FsFile::open(FsVolume*, const char*, oflag_t) { return open_ = false; }
int FsFile::read(void*, size_t) { return -1; }
size_t FsFile::write(const void*, size_t) { return 0; }
bool FsFile::close() {
  const bool was_open = open_;
  open_ = false;
  return was_open;
}
