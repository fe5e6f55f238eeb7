// Reading a firmware ELF: headers (System V ABI, ELF for the Arm Architecture), segments, symbols.
#include "image/cpu/elf_image.hpp"

#include <elf.h>

#include <cstring>
#include <fstream>
#include <iterator>

namespace stepdance::sim::image {
namespace {

template <typename T>
bool read_at(const std::vector<uint8_t>& file, uint64_t offset, T& value) {
  if (offset > file.size() || file.size() - offset < sizeof(T)) return false;
  std::memcpy(&value, file.data() + offset, sizeof(T));
  return true;
}

bool fail(std::string& error, const std::string& path, const std::string& why) {
  error = path + ": " + why;
  return false;
}

bool check_header(const Elf32_Ehdr& header, const std::string& path, std::string& error) {
  if (std::memcmp(header.e_ident, ELFMAG, SELFMAG) != 0) return fail(error, path, "not an ELF file");
  if (header.e_ident[EI_CLASS] != ELFCLASS32)
    return fail(error, path, "not a 32-bit ELF (a Teensy 4.x image is ELF32)");
  if (header.e_ident[EI_DATA] != ELFDATA2LSB) return fail(error, path, "not little-endian");
  if (header.e_machine != EM_ARM) {
    return fail(error, path, "built for machine " + std::to_string(header.e_machine) + ", not ARM (40)");
  }
  if (header.e_type != ET_EXEC) return fail(error, path, "not an executable (a relocatable or shared object?)");
  if (header.e_phentsize != sizeof(Elf32_Phdr) || header.e_phnum == 0) {
    return fail(error, path, "no program headers");
  }
  return true;
}

bool read_segments(const std::vector<uint8_t>& file, const Elf32_Ehdr& header, ElfImage& image, const std::string& path,
                   std::string& error) {
  for (unsigned i = 0; i < header.e_phnum; ++i) {
    Elf32_Phdr segment;
    if (!read_at(file, header.e_phoff + uint64_t{i} * sizeof segment, segment)) {
      return fail(error, path, "program header " + std::to_string(i) + " lies outside the file");
    }
    if (segment.p_type != PT_LOAD || segment.p_memsz == 0) continue;
    if (segment.p_filesz > segment.p_memsz || uint64_t{segment.p_offset} + segment.p_filesz > file.size()) {
      return fail(error, path, "segment " + std::to_string(i) + " lies outside the file");
    }
    ElfSegment loaded;
    loaded.physical_address = segment.p_paddr;
    loaded.virtual_address = segment.p_vaddr;
    loaded.memory_bytes = segment.p_memsz;
    loaded.bytes.assign(file.begin() + segment.p_offset, file.begin() + segment.p_offset + segment.p_filesz);
    image.segments.push_back(std::move(loaded));
  }
  if (image.segments.empty()) return fail(error, path, "no loadable segment");
  return true;
}

// The symbol table (SHT_SYMTAB) and its string table; a stripped image simply has no names.
void read_symbols(const std::vector<uint8_t>& file, const Elf32_Ehdr& header, ElfSymbols& symbols) {
  for (unsigned i = 0; i < header.e_shnum; ++i) {
    Elf32_Shdr section, strings;
    if (!read_at(file, header.e_shoff + uint64_t{i} * sizeof section, section)) return;
    if (section.sh_type != SHT_SYMTAB || section.sh_entsize != sizeof(Elf32_Sym)) continue;
    if (!read_at(file, header.e_shoff + uint64_t{section.sh_link} * sizeof strings, strings)) return;
    for (uint32_t n = 1; n < section.sh_size / sizeof(Elf32_Sym); ++n) {
      Elf32_Sym entry;
      if (!read_at(file, section.sh_offset + uint64_t{n} * sizeof entry, entry)) return;
      const unsigned type = ELF32_ST_TYPE(entry.st_info);
      if (type != STT_FUNC && type != STT_OBJECT && type != STT_NOTYPE) continue;
      if (entry.st_name >= strings.sh_size || strings.sh_offset + entry.st_name >= file.size()) continue;
      const char* name = reinterpret_cast<const char*>(file.data() + strings.sh_offset + entry.st_name);
      const size_t limit = file.size() - (strings.sh_offset + entry.st_name);
      const std::string text(name, strnlen(name, limit));
      if (text.empty() || text[0] == '$') continue;  // mapping symbols ($t, $d)
      const bool function = type == STT_FUNC;
      symbols.add({function ? entry.st_value & ~1u : entry.st_value, entry.st_size, function, text});
    }
  }
  symbols.sort();
}

}  // namespace

bool ElfImage::load(const std::string& path, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(error, path, "cannot be opened");
  const std::vector<uint8_t> file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Elf32_Ehdr header;
  if (!read_at(file, 0, header)) return fail(error, path, "too short to be an ELF file");
  if (!check_header(header, path, error)) return false;
  ElfImage loaded;
  loaded.entry = header.e_entry;
  if (!read_segments(file, header, loaded, path, error)) return false;
  read_symbols(file, header, loaded.symbols);
  *this = std::move(loaded);
  return true;
}

}  // namespace stepdance::sim::image
