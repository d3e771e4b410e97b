#include "ir/arguments_read.h"

#include <mbc/calling_codes.h>

#include <optional>
#include <set>

namespace mbc::ir {

namespace {

constexpr std::int64_t kLocals = 33;

/// The constant an operand is, if it is one.
std::optional<double> constant(const Function& f, ValueId v) {
  const Inst& inst = f.insts[v];
  return inst.op == Op::Const ? std::optional(inst.get<Number>().value)
                              : std::nullopt;
}

/// The subprogram an nc block calls with M98 or M198 P, nullptr for none;
/// `computed` when its P is no constant or names no program of the module.
const Function* subprogramCalled(const Module& module, const Function& f,
                                 const Inst& nc, bool& computed) {
  const auto& words = nc.get<Words>().words;
  bool calls = false;
  std::optional<double> p;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::optional<double> value = constant(f, nc.ops[i]);
    if (words[i].letter == 'M' && value && isSubprogramCall('M', *value)) {
      calls = true;
    } else if (words[i].letter == 'P') {
      p = value;
    }
  }
  if (!calls) {
    return nullptr;
  }
  const Function* callee = p ? module.numbered(static_cast<int>(*p)) : nullptr;
  computed = computed || callee == nullptr;
  return callee;
}

/// Marks #n in `locals` when n is a local's number.
void mark(std::bitset<kLocals>& locals, double n) {
  if (n >= 1 && n <= kLocals) {
    locals.set(static_cast<std::size_t>(n - 1));
  }
}

void collect(const Module& module, const Function& f, ArgumentsRead& read,
             std::set<const Function*>& seen) {
  if (!seen.insert(&f).second) {
    return;
  }
  for (const Inst& inst : f.insts) {
    switch (inst.op) {
      case Op::LdVar:
        mark(read.locals, static_cast<double>(inst.get<VarNumber>().number));
        break;
      case Op::LdInd:
      case Op::Adp:
        read.computed = read.computed || !constant(f, inst.ops[0]);
        if (const std::optional<double> n = constant(f, inst.ops[0])) {
          mark(read.locals, *n);
        }
        break;
      case Op::StVar:
        mark(read.written, static_cast<double>(inst.get<VarNumber>().number));
        break;
      case Op::StInd:
        if (const std::optional<double> n = constant(f, inst.ops[0])) {
          mark(read.written, *n);
        } else {
          read.computedWrite = true;
        }
        break;
      case Op::Nc:
        if (const Function* callee =
                subprogramCalled(module, f, inst, read.computed)) {
          collect(module, *callee, read, seen);
        }
        break;
      default:
        break;
    }
  }
}

} // namespace

ArgumentsRead argumentsRead(const Module& module, const Function& f) {
  ArgumentsRead read;
  std::set<const Function*> seen;
  collect(module, f, read, seen);
  return read;
}

} // namespace mbc::ir
