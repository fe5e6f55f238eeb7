// share_read_only_pages on an ELF host: a copy's read-only segments mapped again from the original.
#include <dlfcn.h>
#include <fcntl.h>
#include <link.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>

#include "board/loader/shared_code_pages.hpp"

namespace stepdance::sim {
namespace {

/// A read-only segment's pages: where they are mapped, where they start in the file, how many
/// bytes (a whole number of pages) and their protection.
struct PageSpan {
  uintptr_t address = 0;
  off_t file_offset = 0;
  size_t length = 0;
  int protection = 0;
};

struct SpanSearch {
  static constexpr int kMax = 4;
  uintptr_t base = 0;
  size_t page_bytes = 0;
  PageSpan spans[kMax];
  int count = 0;
};

int protection_of(ElfW(Word) flags) {
  return ((flags & PF_R) != 0 ? PROT_READ : 0) | ((flags & PF_X) != 0 ? PROT_EXEC : 0);
}

// Whether another PT_LOAD segment of `info` has bytes in the pages [begin, end) (offsets from
// the load address): those pages are not one segment's to map again.
bool shares_pages(const dl_phdr_info* info, int self, uintptr_t begin, uintptr_t end, size_t page) {
  for (int i = 0; i < info->dlpi_phnum; ++i) {
    const ElfW(Phdr)& other = info->dlpi_phdr[i];
    if (i == self || other.p_type != PT_LOAD) continue;
    const uintptr_t other_begin = other.p_vaddr / page * page;
    const uintptr_t other_end = other.p_vaddr + other.p_memsz;
    if (other_begin < end && begin < other_end) return true;
  }
  return false;
}

// The read-only PT_LOAD segments of the object loaded at `search.base`, widened to whole pages
// as the dynamic loader maps them (the last page holds file bytes past the segment's end), that
// share no page with another segment.
int collect_spans(dl_phdr_info* info, size_t, void* data) {
  auto& search = *static_cast<SpanSearch*>(data);
  if (info->dlpi_addr != search.base) return 0;
  const size_t page = search.page_bytes;
  for (int i = 0; i < info->dlpi_phnum && search.count < SpanSearch::kMax; ++i) {
    const ElfW(Phdr)& segment = info->dlpi_phdr[i];
    if (segment.p_type != PT_LOAD || (segment.p_flags & PF_W) != 0 || segment.p_filesz != segment.p_memsz) continue;
    const uintptr_t page_begin = segment.p_vaddr / page * page;
    const uintptr_t page_end = (segment.p_vaddr + segment.p_filesz + page - 1) / page * page;
    if (shares_pages(info, i, page_begin, page_end, page)) continue;
    const uintptr_t start = info->dlpi_addr + segment.p_vaddr;
    const size_t lead = start % page;
    if (segment.p_offset % page != lead) continue;
    const size_t length = (lead + segment.p_filesz + page - 1) / page * page;
    search.spans[search.count++] =
        PageSpan{start - lead, static_cast<off_t>(segment.p_offset - lead), length, protection_of(segment.p_flags)};
  }
  return 1;
}

// Compares two runs of whole pages word by word. They are mapped memory, not C++ objects: a sketch
// built with AddressSanitizer keeps poisoned redzones between its constants, inside these very
// pages, so the sanitizer (and its memcmp interceptor) must not check these reads.
__attribute__((no_sanitize("address"))) bool same_pages(const void* a, const void* b, size_t length) {
  const auto* left = static_cast<const uint64_t*>(a);
  const auto* right = static_cast<const uint64_t*>(b);
  for (size_t i = 0; i < length / sizeof(uint64_t); ++i) {
    if (left[i] != right[i]) return false;
  }
  return true;
}

// Maps `span` from `fd` over the copy if the file's bytes are the copy's; returns the bytes mapped.
size_t remap_if_equal(const PageSpan& span, int fd) {
  void* file_pages = mmap(nullptr, span.length, PROT_READ, MAP_PRIVATE, fd, span.file_offset);
  if (file_pages == MAP_FAILED) return 0;
  const auto* live = reinterpret_cast<const void*>(span.address);
  const bool equal = same_pages(file_pages, live, span.length);
  munmap(file_pages, span.length);
  if (!equal) return 0;
  // MAP_FIXED replaces the copy's pages in one step: nothing else runs on this thread meanwhile,
  // and the bytes at every address stay the same.
  void* placed = mmap(reinterpret_cast<void*>(span.address), span.length, span.protection, MAP_PRIVATE | MAP_FIXED, fd,
                      span.file_offset);
  return placed == MAP_FAILED ? 0 : span.length;
}

}  // namespace

size_t share_read_only_pages(void* handle, const std::string& original_path) {
  link_map* map = nullptr;
  if (dlinfo(handle, RTLD_DI_LINKMAP, &map) != 0 || map == nullptr) return 0;
  SpanSearch search;
  search.base = map->l_addr;
  search.page_bytes = static_cast<size_t>(sysconf(_SC_PAGESIZE));
  dl_iterate_phdr(&collect_spans, &search);
  const int fd = open(original_path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return 0;
  size_t shared = 0;
  for (int i = 0; i < search.count; ++i) shared += remap_if_equal(search.spans[i], fd);
  close(fd);
  return shared;
}

}  // namespace stepdance::sim
