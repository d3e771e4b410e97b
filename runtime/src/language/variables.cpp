// #n dispatch of the C ABI (spec §2.1, §2.2): #0, the current level's
// locals and the common variables are handled here on the hot path; every
// number from #1000 up goes to the system variable table (sysvars.cpp).
#include <mbc/arith.h>
#include <mbc/signals.h>

#include <fmt/format.h>

#include "calls.h"
#include "context.h"
#include "sysvars.h"

using namespace mbc;
using namespace mbc::rt;

namespace {

/// #[number] rounds half away from zero (spec §2.2). Numbers beyond any
/// variable become -1, which fails every range check.
long variableNumber(double number) {
  const double value = numeric(number);
  if (!(std::fabs(value) < kBeyondAnyVariable)) {
    return -1;
  }
  const auto whole = static_cast<long>(value);
  if (static_cast<double>(whole) == value) {
    return whole; // the usual case: no rounding needed
  }
  return static_cast<long>(roundHalfAway(value));
}

bool isCommon(const mbrt_ctx& ctx, long n) {
  if (isFixedCommon(n)) {
    return true;
  }
  return ctx.profile.extendedCommon && n >= kFirstExtendedCommon &&
         n <= kLastExtendedCommon;
}

mbrt_status outOfRange(mbrt_ctx& ctx, long n) {
  return raise(ctx, AlarmId::VariableOutOfRange, fmt::format("#{}", n));
}

} // namespace

mbrt_num mbrt_vacant(void) {
  return mbc::vacant();
}

int mbrt_is_vacant(mbrt_num v) {
  return mbc::isVacant(v) ? 1 : 0;
}

mbrt_status mbrt_read_var(mbrt_ctx* ctx, double number, mbrt_num* out) {
  const long n = variableNumber(number);
  if (isLocal(n)) {
    *out = ctx->locals().value[n - 1];
    return 0;
  }
  if (isCommon(*ctx, n)) {
    *out = ctx->data.commons[n];
    return 0;
  }
  if (n == 0) {
    *out = vacant();
    return 0;
  }
  if (n >= 1000) {
    return readSystemVariable(*ctx, n, out);
  }
  return outOfRange(*ctx, n);
}

mbrt_status mbrt_write_var(mbrt_ctx* ctx, double number, mbrt_num value,
                           const char* comment) {
  const long n = variableNumber(number);
  if (isLocal(n)) {
    LocalLevel& level = ctx->locals();
    level.value[n - 1] = value;
    level.adp_mask &= ~(std::uint64_t{1} << (n - 1));
    return 0;
  }
  if (isCommon(*ctx, n)) {
    ctx->data.commons[n] = value;
    return 0;
  }
  if (n == 0) {
    return raise(*ctx, AlarmId::WriteProtectedVariable, "#0");
  }
  if (n >= 1000) {
    return writeSystemVariable(*ctx, n, value, comment);
  }
  return outOfRange(*ctx, n);
}

mbrt_status mbrt_preset_var(mbrt_ctx* ctx, double number, mbrt_num value) {
  const long n = variableNumber(number);
  if (n >= kFirstInputSignal && n <= kLastInputWord) {
    if (!setInputSignal(*ctx, static_cast<int>(n), numeric(value))) {
      return raise(*ctx, AlarmId::ArgumentOutOfRange,
                   fmt::format("#{} = {}: an input signal takes 0 or 1, a "
                               "word of 32 signals a 32-bit number",
                               n, numeric(value)));
    }
    return 0;
  }
  return mbrt_write_var(ctx, number, value, nullptr);
}

mbrt_status mbrt_adp(mbrt_ctx* ctx, double number, mbrt_num* out) {
  const long n = variableNumber(number);
  if (isLocal(n)) {
    const LocalLevel& level = ctx->locals();
    const Num value = level.value[n - 1];
    const bool fromLiteral = (level.adp_mask >> (n - 1)) & 1;
    // The argument was literal / scale with an integer literal, so this
    // gives the literal back exactly.
    *out = fromLiteral
               ? roundHalfAway(value * argumentScale(*ctx, static_cast<int>(n)))
               : value;
    return 0;
  }
  return mbrt_read_var(ctx, number, out);
}

int mbrt_tool_offset_count(const mbrt_ctx* ctx) {
  return ctx->profile.toolOffsetCount;
}

size_t mbrt_set_commons(const mbrt_ctx* ctx, int* numbers, mbrt_num* values,
                        size_t capacity) {
  size_t count = 0;
  // Range by range: an embedder may read them after every short run.
  const auto scan = [&](int first, int last, const mbrt_num* storage) {
    for (int n = first; n <= last; ++n) {
      const mbrt_num value = storage[n - first];
      if (isVacant(value)) {
        continue;
      }
      if (count < capacity) {
        numbers[count] = n;
        values[count] = value;
      }
      ++count;
    }
  };
  const auto commons = [&](int first, int last) {
    scan(first, last, &ctx->data.commons[static_cast<std::size_t>(first)]);
  };
  commons(kFirstCommon, kLastCommon);
  if (ctx->profile.extendedCommon) {
    commons(kFirstExtendedCommon, kLastExtendedCommon);
  }
  commons(kFirstNonvolatile, kLastNonvolatile);
  if (ctx->profile.commons98000) {
    scan(kFirstCommon98000, kLastCommon98000, ctx->data.commons98000.data());
  }
  return count;
}

int mbrt_peek_common(const mbrt_ctx* ctx, int number, mbrt_num* out) {
  if (ctx->profile.commons98000 && number >= kFirstCommon98000 &&
      number <= kLastCommon98000) {
    *out =
        ctx->data
            .commons98000[static_cast<std::size_t>(number - kFirstCommon98000)];
    return 1;
  }
  if (!isCommon(*ctx, number)) {
    return 0;
  }
  *out = ctx->data.commons[number];
  return 1;
}
