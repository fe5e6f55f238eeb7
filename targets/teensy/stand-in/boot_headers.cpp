// Boot headers of the CI firmware image: what the i.MX RT1062 boot ROM reads from the QSPI flash on
// FlexSPI before it runs anything (RM chapter 9 "System Boot", §9.6.3 FlexSPI NOR boot, §9.7 program
// image). Three parts, placed by the linker script:
//   0x60000000  FlexSPI NOR configuration block (512 bytes, RM Tables 9-15 and 9-16): how to talk
//               to the board's flash chip — quad-SPI fast read (0xEB) for execute-in-place;
//   0x60001000  image vector table (IVT, §9.7.1.1) naming the entry point (stand_in_reset_handler);
//   after it    boot data (§9.7.1.2): where the image starts and how long it is.
// The flash chip facts (quad pads, commands, 256-byte pages, 4 KB sectors, 64 KB blocks, size) are
// those of the Teensy 4.0's 2 MB and the Teensy 4.1's 8 MB chip. No device configuration data (DCD)
// and no signature (CSF): the image is not a HAB-signed image.
#include <stdint.h>

extern "C" {
extern uint32_t _flash_image_start[], _flash_image_length[];
void stand_in_reset_handler();
}

namespace {

// ---- FlexSPI look-up table instructions (RM §27 FlexSPI, "Programmable Sequence Engine") ----------
// Each instruction is 16 bits: OPCODE 15:10, NUM_PADS 9:8 (0 = 1 pad, 2 = 4 pads), OPERAND 7:0.
// Two instructions per 32-bit word, the first in the low half; a sequence is four words.
enum Opcode : uint16_t { kCmdSdr = 0x01, kRaddrSdr = 0x02, kWriteSdr = 0x08, kReadSdr = 0x09, kDummySdr = 0x0C };
enum Pads : uint16_t { kOnePad = 0, kFourPads = 2 };

constexpr uint32_t lut(Opcode opcode, Pads pads, uint8_t operand) {
  return static_cast<uint32_t>(opcode) << 10 | static_cast<uint32_t>(pads) << 8 | operand;
}
constexpr uint32_t lut_pair(uint32_t first, uint32_t second) { return first | second << 16; }

/// The FlexSPI NOR configuration block, RM Table 9-15 (common FlexSPI part, 448 bytes) followed by
/// Table 9-16 (serial NOR part, 64 bytes).
struct FlexSpiNorConfig {
  uint32_t tag;                        // 0x000 "FCFB"
  uint32_t version;                    // 0x004 'V' major minor bugfix
  uint32_t reserved0;                  // 0x008
  uint8_t read_sample_clock_source;    // 0x00C 1 = loopback from the DQS pad
  uint8_t cs_hold_time;                // 0x00D serial clock cycles
  uint8_t cs_setup_time;               // 0x00E serial clock cycles
  uint8_t column_address_width;        // 0x00F 0 for serial NOR
  uint32_t device_mode_words[3];       // 0x010 device mode configuration: off
  uint32_t config_command_words[9];    // 0x01C configuration commands: off
  uint32_t controller_misc_option;     // 0x040
  uint8_t device_type;                 // 0x044 1 = serial NOR
  uint8_t serial_flash_pad_type;       // 0x045 4 = quad
  uint8_t serial_clock_frequency;      // 0x046 ROM frequency code
  uint8_t lut_custom_sequence_enable;  // 0x047
  uint32_t reserved1[2];               // 0x048
  uint32_t flash_a1_size_bytes;        // 0x050
  uint32_t flash_other_sizes[3];       // 0x054 A2, B1, B2: no second chip
  uint32_t pad_overrides[4];           // 0x060 CS, SCLK, data, DQS pad settings: ROM defaults
  uint32_t timeout_ms;                 // 0x070
  uint32_t command_interval;           // 0x074
  uint32_t data_valid_time;            // 0x078
  uint32_t busy_offset_polarity;       // 0x07C status bit 0 (WIP), 1 = busy
  uint32_t lookup_table[64];           // 0x080 16 sequences of 4 words
  uint32_t lut_custom_sequence[12];    // 0x180
  uint32_t reserved2[4];               // 0x1B0
  uint32_t page_size_bytes;            // 0x1C0 serial NOR part
  uint32_t sector_size_bytes;          // 0x1C4
  uint32_t ip_command_clock;           // 0x1C8 ipCmdSerialClkFreq (byte), 1 = 30 MHz
  uint32_t reserved3;                  // 0x1CC
  uint32_t block_size_bytes;           // 0x1D0
  uint32_t reserved4[11];              // 0x1D4
};
static_assert(sizeof(FlexSpiNorConfig) == 512, "RM Tables 9-15 and 9-16: 512 bytes");

// Look-up table sequences the ROM uses (index × 4 words): 0 read, 1 read status, 3 write enable,
// 5 sector erase, 8 block erase, 9 page program, 11 chip erase (RM §9.6.3, "LUT sequence index").
constexpr int kSeqRead = 0 * 4, kSeqReadStatus = 1 * 4, kSeqWriteEnable = 3 * 4, kSeqEraseSector = 5 * 4,
              kSeqEraseBlock = 8 * 4, kSeqPageProgram = 9 * 4, kSeqChipErase = 11 * 4;

constexpr FlexSpiNorConfig make_config(uint32_t flash_bytes) {
  FlexSpiNorConfig c{};
  c.tag = 0x42464346u;      // "FCFB" read as a little-endian word
  c.version = 0x56010000u;  // V1.0.0
  c.read_sample_clock_source = 1;
  c.cs_hold_time = 3;
  c.cs_setup_time = 3;
  c.device_type = 1;
  c.serial_flash_pad_type = 4;
  c.serial_clock_frequency = 8;
  c.flash_a1_size_bytes = flash_bytes;
  // Quad I/O fast read: command 0xEB on one pad, 24-bit address and 6 dummy cycles on four, data on four.
  c.lookup_table[kSeqRead] = lut_pair(lut(kCmdSdr, kOnePad, 0xEB), lut(kRaddrSdr, kFourPads, 24));
  c.lookup_table[kSeqRead + 1] = lut_pair(lut(kDummySdr, kFourPads, 6), lut(kReadSdr, kFourPads, 4));
  c.lookup_table[kSeqReadStatus] = lut_pair(lut(kCmdSdr, kOnePad, 0x05), lut(kReadSdr, kOnePad, 4));
  c.lookup_table[kSeqWriteEnable] = lut(kCmdSdr, kOnePad, 0x06);
  c.lookup_table[kSeqEraseSector] = lut_pair(lut(kCmdSdr, kOnePad, 0x20), lut(kRaddrSdr, kOnePad, 24));
  c.lookup_table[kSeqEraseBlock] = lut_pair(lut(kCmdSdr, kOnePad, 0xD8), lut(kRaddrSdr, kOnePad, 24));
  c.lookup_table[kSeqPageProgram] = lut_pair(lut(kCmdSdr, kOnePad, 0x02), lut(kRaddrSdr, kOnePad, 24));
  c.lookup_table[kSeqPageProgram + 1] = lut(kWriteSdr, kOnePad, 4);
  c.lookup_table[kSeqChipErase] = lut(kCmdSdr, kOnePad, 0x60);
  c.page_size_bytes = 256;
  c.sector_size_bytes = 4096;
  c.ip_command_clock = 1;
  c.block_size_bytes = 64 * 1024;
  return c;
}

#if defined(ARDUINO_TEENSY40)
constexpr uint32_t kFlashChipBytes = 2u * 1024 * 1024;
#else
constexpr uint32_t kFlashChipBytes = 8u * 1024 * 1024;
#endif

/// Image vector table (RM §9.7.1.1), eight 32-bit words.
struct ImageVectorTable {
  uint32_t header;  // tag 0xD1, length 32 (big-endian), version 0x41 (or 0x40..0x45)
  const void* entry;
  uint32_t reserved1;
  const void* device_configuration_data;
  const void* boot_data;
  const void* self;
  const void* command_sequence_file;
  uint32_t reserved2;
};

/// Boot data (RM §9.7.1.2): where the image starts, how long it is, plugin flag.
struct BootData {
  const void* start;
  const void* length;
  uint32_t plugin;
  uint32_t reserved;
};

}  // namespace

// Named (extern "C") so the linker script can keep them: an archived core joins only what is named.
extern "C" {

extern const FlexSpiNorConfig stand_in_flexspi_config;
__attribute__((section(".flexspi_config"), used)) const FlexSpiNorConfig stand_in_flexspi_config =
    make_config(kFlashChipBytes);

extern const BootData stand_in_boot_data;
__attribute__((section(".boot_data"), used)) const BootData stand_in_boot_data = {
    _flash_image_start,
    _flash_image_length,  // a length the linker script defines as an absolute symbol
    0,
    0,
};

extern const ImageVectorTable stand_in_image_vector_table;
__attribute__((section(".image_vector_table"), used)) const ImageVectorTable stand_in_image_vector_table = {
    0x412000D1u,
    reinterpret_cast<const void*>(&stand_in_reset_handler),
    0,
    nullptr,
    &stand_in_boot_data,
    &stand_in_image_vector_table,
    nullptr,
    0,
};

}  // extern "C"
