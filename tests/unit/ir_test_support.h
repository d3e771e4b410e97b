// Helpers shared by the IR unit tests.
#pragma once

#include "ir/ir_parser.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>

namespace mbc::ir {

/// Parses IR text that the test expects to be valid syntax.
inline Module parseText(std::string_view text) {
  Module m;
  std::string error;
  EXPECT_TRUE(parseModule(text, m, error)) << error;
  return m;
}

} // namespace mbc::ir
