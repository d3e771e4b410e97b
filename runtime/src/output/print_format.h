// DPRNT and BPRNT formatting (spec §7.3, §7.4), separate from the context so
// that it is unit-testable on its own.
#pragma once

#include <mbc/value.h>

#include <string>

namespace mbc::rt {

/// The DPRNT text of one value with format [c d]: sign position, c integer
/// digits from the low-order end (leading zeros as spaces when prt is false,
/// dropped when true), '.' and d decimals when d > 0. Vacant prints as 0.
std::string formatDprntValue(Num value, int intDigits, int fracDigits,
                             bool prt);

/// DPRNT/BPRNT literal text: '*' becomes a space.
std::string formatPrintText(const char* text);

/// The four BPRNT bytes of one value with format [d]: value x 10^d rounded,
/// 32-bit two's complement, most significant byte first; vacant is 0.
/// Returns false (nothing appended) when the scaled value does not fit.
bool appendBprntValue(std::string& out, Num value, int fracDigits);

} // namespace mbc::rt
