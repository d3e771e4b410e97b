// The columns of ir/opcodes.def agree with each other: a row that says add
// computes BinOp::Sub, or a branch that is no terminator, fails here rather
// than as a miscompile in one engine.
#include "ir/ir.h"

#include <gtest/gtest.h>

#include <array>
#include <string>

namespace mbc::ir {
namespace {

constexpr std::array kOps = {
#define OP(Name, Mnemonic, Result, Operands, Takes, Flags, Math, Format)       \
  Op::Name,
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

bool takesTargets(Format f) {
  return f == Format::Jump || f == Format::Branch || f == Format::Table ||
         f == Format::Resumption;
}

TEST(IrOpcodes, FormatsAndFlagsAgree) {
  for (Op op : kOps) {
    const OpInfo& info = opInfo(op);
    const bool terminator = (info.flags & Terminator) != 0;
    if (takesTargets(info.format) || info.format == Format::Alarm) {
      EXPECT_TRUE(terminator) << info.mnemonic;
    }
    if (terminator) {
      EXPECT_EQ(info.result, Type::None) << info.mnemonic;
    }
    if (info.flags & Commutative) {
      EXPECT_TRUE(info.flags & Cseable) << info.mnemonic;
      EXPECT_EQ(info.operands, 2) << info.mnemonic;
    }
    if (info.flags & Cseable) {
      // One value may stand for another only if nothing else decides it.
      EXPECT_FALSE(info.flags & (ReadsState | ReadsVars | WritesVars |
                                 SideEffect | Terminator))
          << info.mnemonic;
      EXPECT_NE(info.result, Type::None) << info.mnemonic;
      // cse keys a value by its op, operands and fn's builtin: no other
      // payload would tell two such values apart.
      EXPECT_TRUE(info.format == Format::Plain ||
                  info.format == Format::Function)
          << info.mnemonic;
    }
  }
}

// A new instruction starts with the payload its row names, and only that
// one fits.
TEST(IrOpcodes, PayloadOfFitsItsOpAlone) {
  for (Op op : kOps) {
    const Payload p = payloadOf(op);
    EXPECT_TRUE(payloadFits(op, p)) << opInfo(op).mnemonic;
    const Payload other =
        std::holds_alternative<NoData>(p) ? Payload{Number{}} : Payload{};
    EXPECT_FALSE(payloadFits(op, other)) << opInfo(op).mnemonic;
  }
  EXPECT_TRUE(std::holds_alternative<Words>(payloadOf(Op::CallMacro)));
  EXPECT_TRUE(std::holds_alternative<SequenceCases>(payloadOf(Op::Resume)));
}

} // namespace
} // namespace mbc::ir
