// share_read_only_pages where code is not mapped from files (WebAssembly): nothing to share.
#include "board/loader/shared_code_pages.hpp"

namespace stepdance::sim {

size_t share_read_only_pages(void*, const std::string&) { return 0; }

}  // namespace stepdance::sim
