// What the Macro B fuzz targets share: the input bytes as a file through the
// parser and the semantic checks, with mbc check's review.
#pragma once

#include "frontend/diagnostics.h"
#include "frontend/parser.h"
#include "frontend/sema.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace mbc::fuzz {

struct CheckedInput {
  SourceManager sources;
  DiagnosticEngine diags{sources};
  Unit unit;

  CheckedInput(const std::uint8_t* data, std::size_t size) {
    const std::uint32_t file = sources.add(
        "fuzz.nc", std::string(reinterpret_cast<const char*>(data), size));
    // As mbc check reads: the review's analyses run too.
    ParseOptions parse;
    parse.checkWarnings = true;
    parseFile(sources, file, diags, parse, unit);
    checkUnit(unit, diags, SemaOptions{true, 0, true});
  }
};

} // namespace mbc::fuzz
