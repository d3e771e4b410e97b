// The page's bytes are assembled into the object as they are (.incbin),
// rather than as a string literal the compiler would parse: it is a
// megabyte of JavaScript. MBC_TOOLPATH_PAGE is its path in the build tree.
#include "runner/html_page.h"

__asm__(".section .rodata\n"
        ".global mbc_toolpath_page\n"
        ".hidden mbc_toolpath_page\n"
        "mbc_toolpath_page:\n"
        ".incbin \"" MBC_TOOLPATH_PAGE "\"\n"
        ".global mbc_toolpath_page_end\n"
        ".hidden mbc_toolpath_page_end\n"
        "mbc_toolpath_page_end:\n"
        ".byte 0\n"
        ".previous\n");

extern "C" __attribute__((visibility("hidden"))) const char mbc_toolpath_page[];
extern "C" __attribute__((visibility("hidden")))
const char mbc_toolpath_page_end[];

namespace mbc::runner {

std::string_view toolpathPage() {
  return {mbc_toolpath_page,
          static_cast<std::size_t>(mbc_toolpath_page_end - mbc_toolpath_page)};
}

} // namespace mbc::runner
