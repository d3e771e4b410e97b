// The columns of ir/opcodes.def agree with each other: a row that says add
// computes BinOp::Sub, or a terminator outside the Control class, fails
// here rather than as a miscompile in one engine.
#include "ir/ir.h"

#include <gtest/gtest.h>

#include <array>
#include <string>

namespace mbc::ir {
namespace {

constexpr std::array kOps = {
#define OP(Name, Mnemonic, Result, Operands, Flags, Class, Math) Op::Name,
#include "ir/opcodes.def"
};

// The mnemonics of add ... xor and eq ... le are the names of the runtime
// operations they compute, in the order of <mbc/arith.h>.
constexpr std::array<const char*, 8> kBinaryNames = {
    "add", "sub", "mul", "div", "mod", "and", "or", "xor"};
constexpr std::array<const char*, 6> kRelationNames = {"eq", "ne", "gt",
                                                       "ge", "lt", "le"};

TEST(IrOpcodes, MathIsWhatTheMnemonicSays) {
  int binaries = 0;
  int relations = 0;
  for (Op op : kOps) {
    const OpInfo& info = opInfo(op);
    if (const std::optional<BinOp> b = binaryOf(op)) {
      ++binaries;
      EXPECT_STREQ(info.mnemonic, kBinaryNames.at(static_cast<int>(*b)));
      EXPECT_EQ(info.operands, 2) << info.mnemonic;
      EXPECT_EQ(info.result, Type::Num) << info.mnemonic;
    }
    if (const std::optional<RelOp> r = relationOf(op)) {
      ++relations;
      EXPECT_STREQ(info.mnemonic, kRelationNames.at(static_cast<int>(*r)));
      EXPECT_EQ(info.operands, 2) << info.mnemonic;
      EXPECT_EQ(info.result, Type::Bool) << info.mnemonic;
    }
  }
  EXPECT_EQ(binaries, 8);
  EXPECT_EQ(relations, 6);
}

TEST(IrOpcodes, ClassesAndFlagsAgree) {
  for (Op op : kOps) {
    const OpInfo& info = opInfo(op);
    const bool terminator = (info.flags & Terminator) != 0;
    EXPECT_EQ(terminator, info.cls == OpClass::Control) << info.mnemonic;
    if (info.flags & Commutative) {
      EXPECT_TRUE(info.flags & Cseable) << info.mnemonic;
      EXPECT_EQ(info.operands, 2) << info.mnemonic;
    }
    if (info.flags & Cseable) {
      // One value may stand for another only if nothing else decides it.
      EXPECT_EQ(info.cls, OpClass::Value) << info.mnemonic;
      EXPECT_FALSE(info.flags & (ReadsState | ReadsVars | SideEffect))
          << info.mnemonic;
      EXPECT_NE(info.result, Type::None) << info.mnemonic;
    }
    if (info.cls == OpClass::Variable) {
      EXPECT_TRUE(info.flags & (ReadsVars | WritesVars)) << info.mnemonic;
    }
  }
}

} // namespace
} // namespace mbc::ir
