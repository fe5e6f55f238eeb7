// Loading a firmware ELF: what goes where, the names, and clear errors for what is not an image.
#include <elf.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

#include "fixture.hpp"
#include "image/cpu/elf_image.hpp"

namespace stepdance::sim::image::testing {
namespace {

std::vector<char> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string write_temporary(const std::string& name, const std::vector<char>& bytes) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return path;
}

TEST(ElfImage, ReadsSegmentsByLoadAddressAndTheSymbols) {
  ElfImage image;
  std::string error;
  ASSERT_TRUE(image.load(fixture_path("fault_undefined"), error)) << error;
  EXPECT_EQ(image.entry & 0xFF000000u, 0x60000000u);  // the reset path in flash
  bool text_in_flash = false;
  for (const ElfSegment& segment : image.segments) text_in_flash |= segment.physical_address == 0x60000000u;
  EXPECT_TRUE(text_in_flash);
  uint32_t address = 0;
  ASSERT_TRUE(image.symbols.find("undefined_here", address));
  EXPECT_EQ(image.symbols.describe(address + 2), "undefined_here+0x2");
  EXPECT_EQ(image.symbols.function_name(address), "undefined_here");
}

TEST(ElfImage, DemanglesCppNames) {
  ElfSymbols symbols;
  symbols.add({0x60001000, 0x40, true, "_Z5setupv"});
  symbols.add({0x60001040, 0x20, true, "_ZN9stepdance6Engine9run_frameEv"});
  symbols.sort();
  EXPECT_EQ(symbols.describe(0x60001012), "setup()+0x12");
  EXPECT_EQ(symbols.function_name(0x60001044), "stepdance::Engine::run_frame()");
  EXPECT_EQ(symbols.describe(0x60002000), "");  // beyond every sized function
}

TEST(ElfImage, RefusesWhatIsNotAnArmExecutable) {
  ElfImage image;
  std::string error;
  EXPECT_FALSE(image.load(write_temporary("not_elf.bin", {'h', 'e', 'l', 'l', 'o'}), error));
  EXPECT_NE(error.find("too short to be an ELF file"), std::string::npos) << error;
  std::vector<char> text(64, 'x');
  EXPECT_FALSE(image.load(write_temporary("text.bin", text), error));
  EXPECT_NE(error.find("not an ELF file"), std::string::npos) << error;
  EXPECT_FALSE(image.load("/proc/self/exe", error));  // this test program: a 64-bit host ELF
  EXPECT_NE(error.find("not a 32-bit ELF"), std::string::npos) << error;
  EXPECT_FALSE(image.load(::testing::TempDir() + "no_such_file.elf", error));
  EXPECT_NE(error.find("cannot be opened"), std::string::npos) << error;
}

TEST(ElfImage, FlashBeyondTheImageReadsErased) {
  Scheduler scheduler;
  ImageChip chip(scheduler, TeensyModel::kTeensy41);
  std::string error;
  ASSERT_TRUE(chip.load(fixture_path("fault_undefined"), error)) << error;
  uint32_t word = 0;
  ASSERT_TRUE(chip.read_memory(0x607FFFFC, &word, 4));  // the last word of the 4.1's 8 MB
  EXPECT_EQ(word, 0xFFFFFFFFu);
  EXPECT_FALSE(chip.read_memory(0x60800000, &word, 4));  // past the flash
  ASSERT_TRUE(chip.read_memory(0x20000000, &word, 4));   // RAM starts zeroed
  EXPECT_EQ(word, 0u);
}

TEST(ElfImage, TheChipRefusesASegmentOutsideItsMemoriesAndLoadsNothing) {
  std::vector<char> bytes = read_file(fixture_path("fault_undefined"));
  ASSERT_GT(bytes.size(), sizeof(Elf32_Ehdr));
  Elf32_Ehdr header;
  std::memcpy(&header, bytes.data(), sizeof header);
  Elf32_Phdr segment;
  std::memcpy(&segment, bytes.data() + header.e_phoff, sizeof segment);
  segment.p_paddr = 0x30000000;  // no memory there
  std::memcpy(bytes.data() + header.e_phoff, &segment, sizeof segment);
  Scheduler scheduler;
  ImageChip chip(scheduler, TeensyModel::kTeensy40);
  std::string error;
  EXPECT_FALSE(chip.load(write_temporary("moved.elf", bytes), error));
  EXPECT_NE(error.find("a segment at 0x30000000"), std::string::npos) << error;
  EXPECT_NE(error.find("outside the flash (2 MB)"), std::string::npos) << error;
  chip.power_on(0);  // nothing loaded: a bad-image stop, not a run
  ASSERT_NE(chip.stop_report(), nullptr);
  EXPECT_EQ(chip.stop_report()->kind, ImageStop::Kind::kBadImage);
}

}  // namespace
}  // namespace stepdance::sim::image::testing
