// The page of `mbc run --html` with three.js inside, written at build time
// by tools/html/make_page.py and kept in the executable.
#pragma once

#include <string_view>

namespace mbc::runner {

/// The page, with @TITLE@ and @TOOLPATH@ for the run to fill in.
std::string_view toolpathPage();

/// Why the page is empty, when it is.
inline constexpr const char* kNoPageReason =
    "--html is not available: this mbc was built without its page (npm could "
    "not fetch three.js from the npm registry; see the build's warning)";

} // namespace mbc::runner
