// find_board_code on an ELF host: the library's executable segments, from the dynamic loader.
#include "board/loader/board_code_ranges.hpp"

#include <dlfcn.h>
#include <link.h>

namespace stepdance::sim {
namespace {

// The executable segments of the object loaded at `base`.
struct CodeSearch {
  uintptr_t base;
  CodeRanges* ranges;
};

int find_code(dl_phdr_info* info, size_t, void* data) {
  auto& search = *static_cast<CodeSearch*>(data);
  if (info->dlpi_addr != search.base) return 0;
  for (int i = 0; i < info->dlpi_phnum && search.ranges->count < CodeRanges::kMax; ++i) {
    const ElfW(Phdr)& segment = info->dlpi_phdr[i];
    if (segment.p_type != PT_LOAD || (segment.p_flags & PF_X) == 0) continue;
    const int n = search.ranges->count++;
    search.ranges->begin[n] = info->dlpi_addr + segment.p_vaddr;
    search.ranges->end[n] = search.ranges->begin[n] + segment.p_memsz;
  }
  return 1;
}

}  // namespace

void find_board_code(void* handle, uintptr_t& load_base, CodeRanges& code) {
  link_map* map = nullptr;
  if (dlinfo(handle, RTLD_DI_LINKMAP, &map) != 0 || map == nullptr) return;
  load_base = map->l_addr;
  CodeSearch search{load_base, &code};
  dl_iterate_phdr(&find_code, &search);
}

}  // namespace stepdance::sim
