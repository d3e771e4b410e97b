// The operation table, generated from opcodes.def.
#include "ir/ir.h"

#include <array>

namespace mbc::ir {

namespace {

constexpr OpMath NoMath{};
#define Bin(Id)                                                                \
  OpMath {                                                                     \
    OpMath::Binary, static_cast<std::uint8_t>(BinOp::Id)                       \
  }
#define Rel(Id)                                                                \
  OpMath {                                                                     \
    OpMath::Relation, static_cast<std::uint8_t>(RelOp::Id)                     \
  }

constexpr std::array kOps = {
#define OP(Name, Mnemonic, Result, Operands, Takes, Flags, Math, Shape)        \
  OpInfo{Mnemonic,                                                             \
         Type::Result,                                                         \
         Operands,                                                             \
         OperandRule::Takes,                                                   \
         static_cast<unsigned>(Flags),                                         \
         Math,                                                                 \
         Format::Shape},
#include "ir/opcodes.def"
};

#undef Bin
#undef Rel

} // namespace

const OpInfo& opInfo(Op op) {
  return kOps[static_cast<std::size_t>(op)];
}

std::optional<BinOp> binaryOf(Op op) {
  const OpMath& m = opInfo(op).math;
  return m.kind == OpMath::Binary ? std::optional(static_cast<BinOp>(m.op))
                                  : std::nullopt;
}

std::optional<RelOp> relationOf(Op op) {
  const OpMath& m = opInfo(op).math;
  return m.kind == OpMath::Relation ? std::optional(static_cast<RelOp>(m.op))
                                    : std::nullopt;
}

Payload payloadOf(Op op) {
  switch (opInfo(op).format) {
#define FORMAT(Name, Payload)                                                  \
  case Format::Name:                                                           \
    return Payload{};
#include "ir/formats.def"
  }
  return NoData{};
}

bool payloadFits(Op op, const Payload& p) {
  switch (opInfo(op).format) {
#define FORMAT(Name, Payload)                                                  \
  case Format::Name:                                                           \
    return std::holds_alternative<Payload>(p);
#include "ir/formats.def"
  }
  return false;
}

const Function* Module::numbered(int number) const {
  for (const Function& f : functions) {
    if (f.number == number) {
      return &f;
    }
  }
  return nullptr;
}

StringRef Module::intern(const std::string& s) {
  for (std::size_t i = 0; i < strings.size(); ++i) {
    if (strings[i] == s) {
      return static_cast<StringRef>(i + 1);
    }
  }
  strings.push_back(s);
  return static_cast<StringRef>(strings.size());
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
