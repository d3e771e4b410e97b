// The operation table, generated from opcodes.def.
#include "ir/ir.h"

#include <array>

namespace mbc::ir {

namespace {

constexpr std::array kOps = {
#define OP(Name, Mnemonic, Result, Operands, Flags)                            \
  OpInfo{Mnemonic, Type::Result, Operands, static_cast<unsigned>(Flags)},
#include "ir/opcodes.def"
};

} // namespace

const OpInfo& opInfo(Op op) {
  return kOps[static_cast<std::size_t>(op)];
}

bool opFromMnemonic(const std::string& mnemonic, Op& out) {
  for (std::size_t i = 0; i < kOps.size(); ++i) {
    if (mnemonic == kOps[i].mnemonic) {
      out = static_cast<Op>(i);
      return true;
    }
  }
  return false;
}

} // namespace mbc::ir
