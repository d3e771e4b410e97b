// Program numbers as the machine has them: the number of a program's name
// and the check of one a call or a run asks for (declared in context.h,
// used by the machine's M98, the language's calls and the API's runs).
#include <mbc/limits.h>

#include <fmt/format.h>

#include "context.h"

namespace mbc::rt {

int parseProgramNumber(const char* name) {
  if (name == nullptr || name[0] != 'O' || name[1] == '\0') {
    return 0;
  }
  int number = 0;
  for (const char* digit = name + 1; *digit != '\0'; ++digit) {
    if (*digit < '0' || *digit > '9' || number > kMaxProgramNumber) {
      return 0;
    }
    number = number * 10 + (*digit - '0');
  }
  return number;
}

mbrt_status checkProgramNumber(mbrt_ctx& ctx, double number) {
  if (ctx.profile.programNumberDigits == 4 &&
      number > kMaxProgramNumber4Digits && !isNamedProgramNumber(number)) {
    return raise(ctx, AlarmId::IllegalProgramNumber,
                 fmt::format("O{}: this machine has program numbers O1 to "
                             "O{} (profile program_number_digits)",
                             number, kMaxProgramNumber4Digits));
  }
  return 0;
}

} // namespace mbc::rt
