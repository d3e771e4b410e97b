// The struct types generated code builds or reads (codegen/abi.cpp) lay out
// as the runtime's C declarations do on this target: a field reordered,
// added or retyped on one side fails here, not as corrupted memory. (The
// runtime functions' signatures are checked at compile time in abi.cpp.)
#include "codegen/abi.h"
#include "codegen/native_target.h"
#include <mbc/compiled.h>
#include <mbc/engine.h>

#include <gtest/gtest.h>
#include <llvm/IR/DataLayout.h>
#include <llvm/MC/TargetRegistry.h>
#include <llvm/Support/Host.h>
#include <llvm/Target/TargetMachine.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace mbc::codegen {
namespace {

class CodegenAbi : public ::testing::Test {
protected:
  void SetUp() override {
    initializeNativeTarget();
    std::string error;
    const std::string triple = llvm::sys::getProcessTriple();
    const llvm::Target* target =
        llvm::TargetRegistry::lookupTarget(triple, error);
    ASSERT_NE(target, nullptr) << error;
    std::unique_ptr<llvm::TargetMachine> machine(target->createTargetMachine(
        triple, "generic", "", llvm::TargetOptions(), llvm::Reloc::PIC_));
    ASSERT_NE(machine, nullptr);
    layout_ = std::make_unique<llvm::DataLayout>(machine->createDataLayout());
  }

  /// The field offsets and the size of an LLVM struct type.
  std::vector<std::size_t> shape(llvm::StructType* type) const {
    const llvm::StructLayout* s = layout_->getStructLayout(type);
    std::vector<std::size_t> out;
    for (unsigned i = 0; i < type->getNumElements(); ++i) {
      out.push_back(s->getElementOffset(i));
    }
    out.push_back(s->getSizeInBytes());
    return out;
  }

  std::unique_ptr<llvm::LLVMContext> context_ = makeContext();
  llvm::Module module_{"abi", *context_};
  Abi abi_{module_};
  std::unique_ptr<llvm::DataLayout> layout_;
};

// Offsets of each field in declaration order, then sizeof.
#define SHAPE(T, ...) (std::vector<std::size_t>{__VA_ARGS__, sizeof(T)})

TEST_F(CodegenAbi, StructsLayOutAsTheRuntimeDeclaresThem) {
  EXPECT_EQ(shape(abi_.word),
            SHAPE(mbrt_word, offsetof(mbrt_word, letter),
                  offsetof(mbrt_word, kind), offsetof(mbrt_word, value)));
  EXPECT_EQ(shape(abi_.printItem),
            SHAPE(mbrt_print_item, offsetof(mbrt_print_item, text),
                  offsetof(mbrt_print_item, value),
                  offsetof(mbrt_print_item, int_digits),
                  offsetof(mbrt_print_item, frac_digits)));
  EXPECT_EQ(
      shape(abi_.flow),
      SHAPE(mbrt_flow, offsetof(mbrt_flow, kind), offsetof(mbrt_flow, program),
            offsetof(mbrt_flow, repeat), offsetof(mbrt_flow, has_seq),
            offsetof(mbrt_flow, seq), offsetof(mbrt_flow, counts_part),
            offsetof(mbrt_flow, call_kind), offsetof(mbrt_flow, args),
            offsetof(mbrt_flow, arg_count), offsetof(mbrt_flow, start_seq)));
  EXPECT_EQ(shape(abi_.level), SHAPE(mbrt_level, offsetof(mbrt_level, value),
                                     offsetof(mbrt_level, adp_mask)));
  EXPECT_EQ(shape(abi_.blockState),
            SHAPE(mbrt_block_state, offsetof(mbrt_block_state, file),
                  offsetof(mbrt_block_state, line),
                  offsetof(mbrt_block_state, tracing),
                  offsetof(mbrt_block_state, blocks),
                  offsetof(mbrt_block_state, max_blocks)));
  EXPECT_EQ(shape(abi_.program),
            SHAPE(mbrt_program, offsetof(mbrt_program, name),
                  offsetof(mbrt_program, number),
                  offsetof(mbrt_program, body)));
  EXPECT_EQ(shape(abi_.table),
            SHAPE(mbrt_program_table, offsetof(mbrt_program_table, programs),
                  offsetof(mbrt_program_table, count)));
  EXPECT_EQ(shape(abi_.ncRun),
            SHAPE(mbrt_nc_run, offsetof(mbrt_nc_run, file),
                  offsetof(mbrt_nc_run, steps), offsetof(mbrt_nc_run, codes),
                  offsetof(mbrt_nc_run, values), offsetof(mbrt_nc_run, count)));
}

// The field numbers codegen uses name the fields they say.
TEST_F(CodegenAbi, FieldNumbersNameTheirFields) {
  const auto offset = [&](llvm::StructType* t, unsigned i) {
    return layout_->getStructLayout(t)->getElementOffset(i);
  };
  EXPECT_EQ(offset(abi_.word, kWordValue), offsetof(mbrt_word, value));
  EXPECT_EQ(offset(abi_.flow, kFlowSeq), offsetof(mbrt_flow, seq));
  EXPECT_EQ(offset(abi_.flow, kFlowHasSeq), offsetof(mbrt_flow, has_seq));
  EXPECT_EQ(offset(abi_.flow, kFlowCountsPart),
            offsetof(mbrt_flow, counts_part));
  EXPECT_EQ(offset(abi_.flow, kFlowArgCount), offsetof(mbrt_flow, arg_count));
  EXPECT_EQ(offset(abi_.level, kLevelAdpMask), offsetof(mbrt_level, adp_mask));
  EXPECT_EQ(offset(abi_.blockState, kBlockCount),
            offsetof(mbrt_block_state, blocks));
  EXPECT_EQ(offset(abi_.blockState, kBlockMax),
            offsetof(mbrt_block_state, max_blocks));
  EXPECT_EQ(offset(abi_.printItem, kItemFracDigits),
            offsetof(mbrt_print_item, frac_digits));
}

} // namespace
} // namespace mbc::codegen
