// elf_symbol.cpp: looks up a symbol's address in an ELF file's symbol table (libelf).
#include "elf_symbol.h"

#include <fcntl.h>   // open
#include <gelf.h>    // GElf_Shdr, GElf_Sym, gelf_getshdr, gelf_getsym
#include <libelf.h>  // elf_begin, elf_nextscn, elf_strptr
#include <unistd.h>  // close

#include <cstring>

namespace servo_sim {
namespace {

// Searches one SHT_SYMTAB section.
std::optional<std::uint32_t> find_in_symtab(Elf* elf, Elf_Scn* section, const GElf_Shdr& header,
                                            const std::string& name) {
  Elf_Data* data = elf_getdata(section, nullptr);
  if (data == nullptr || header.sh_entsize == 0) {
    return std::nullopt;
  }
  const std::size_t count = header.sh_size / header.sh_entsize;
  for (std::size_t i = 0; i < count; ++i) {
    GElf_Sym symbol;
    if (gelf_getsym(data, static_cast<int>(i), &symbol) == nullptr) {
      continue;
    }
    const char* symbol_name = elf_strptr(elf, header.sh_link, symbol.st_name);
    if (symbol_name != nullptr && name == symbol_name) {
      return static_cast<std::uint32_t>(symbol.st_value);
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::uint32_t> elf_symbol_address(const std::string& elf_path, const std::string& name) {
  if (elf_version(EV_CURRENT) == EV_NONE) {
    return std::nullopt;
  }
  const int fd = open(elf_path.c_str(), O_RDONLY);
  if (fd < 0) {
    return std::nullopt;
  }
  std::optional<std::uint32_t> address;
  if (Elf* elf = elf_begin(fd, ELF_C_READ, nullptr)) {
    for (Elf_Scn* section = elf_nextscn(elf, nullptr); section != nullptr && !address;
         section = elf_nextscn(elf, section)) {
      GElf_Shdr header;
      if (gelf_getshdr(section, &header) != nullptr && header.sh_type == SHT_SYMTAB) {
        address = find_in_symtab(elf, section, header, name);
      }
    }
    elf_end(elf);
  }
  close(fd);
  return address;
}

}  // namespace servo_sim
