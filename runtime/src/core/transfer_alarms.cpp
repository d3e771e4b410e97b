// The alarms of GOTO, M99 P and calls, in one place so that the interpreter,
// the IR evaluator and compiled code word them identically.
#include <mbc/arith.h>
#include <mbc/engine.h>
#include <mbc/limits.h>

#include <fmt/format.h>

#include "context.h"

using namespace mbc;

mbrt_status mbrt_raise_sequence(mbrt_ctx* ctx, const char* jump, double seq,
                                const char* program) {
  double n = roundHalfAway(seq);
  std::string detail = !isSequenceNumber(n)
                           ? fmt::format("{}{}", jump, seq)
                           : fmt::format("N{} not found in {}", n, program);
  return rt::raise(*ctx, AlarmId::IllegalMacroSequenceNumber, detail);
}

mbrt_status mbrt_raise_start_sequence(mbrt_ctx* ctx, double seq,
                                      const char* program) {
  double n = roundHalfAway(seq);
  std::string detail = !isSequenceNumber(n)
                           ? fmt::format("M98 Q{}", seq)
                           : fmt::format("N{} not found in {}", n, program);
  return rt::raise(*ctx, AlarmId::SequenceNumberNotFound, detail);
}

mbrt_status mbrt_raise_program_not_found(mbrt_ctx* ctx, double number) {
  double n = roundHalfAway(number);
  if (const mbrt_status status = rt::checkProgramNumber(*ctx, n)) {
    return status;
  }
  std::string detail = n >= 0 && n <= kMaxCallNumber
                           ? programName(static_cast<int>(n))
                           : fmt::format("O{}", number);
  return rt::raise(*ctx, AlarmId::ProgramNotFound, detail);
}
