// IR -> LLVM IR for a whole module: the program bodies, the dispatcher that
// turns a program number into a call (mbc.call), the program table and the
// C entry points.
#include "codegen/emit_module.h"

#include "codegen/emitter.h"
#include "codegen/entry_points.h"
#include <mbc/addresses.h>
#include <mbc/engine.h>

#include <llvm/IR/Intrinsics.h>

namespace mbc::codegen {

namespace detail {

llvm::GlobalVariable* ModuleState::constantData(llvm::Constant* init,
                                                const char* name) {
  auto* global =
      new llvm::GlobalVariable(abi.module, init->getType(), true,
                               llvm::GlobalValue::PrivateLinkage, init, name);
  global->setUnnamedAddr(llvm::GlobalValue::UnnamedAddr::Global);
  return global;
}

llvm::Constant* ModuleState::cstring(const std::string& text) {
  auto it = strings.find(text);
  if (it != strings.end()) {
    return it->second;
  }
  llvm::GlobalVariable* global = constantData(
      llvm::ConstantDataArray::getString(abi.context, text, true), ".str");
  global->setAlignment(llvm::Align(1));
  return strings.emplace(text, global).first->second;
}

llvm::Constant*
ModuleState::constantWords(const std::vector<llvm::Constant*>& words) {
  llvm::Constant* init = llvm::ConstantArray::get(
      llvm::ArrayType::get(abi.word, words.size()), words);
  auto [it, added] = wordLists.emplace(init, nullptr);
  if (added) {
    it->second = constantData(init, ".words");
  }
  return it->second;
}

namespace {

// Glue calls bodies, which the inliner may merge into it: with -g it needs
// a subprogram and locations of its own. Code that serves no one program
// is put at the start of the first, as a C compiler's would be in its main
// file: line 0 would make debuggers show the line before it in the file.
void attribute(ModuleState& m, llvm::Function* fn, llvm::IRBuilder<>& b,
               const ir::Function* program) {
  if (program == nullptr && !m.ir.functions.empty()) {
    program = &m.ir.functions[0];
  }
  if (m.debug) {
    llvm::DISubprogram* sp = m.debug->artificial(fn, program);
    b.SetCurrentDebugLocation(m.debug->location(sp->getLine(), sp));
  }
}

// i32 mbc.call(ptr ctx, double p, i32 kind, ptr args, i64 count,
//              double repeat, double start, ptr out): the program numbered
// round(p), called round(repeat) times from sequence number `start` (0: its
// top), or PS0076 (evaluator findProgram and call).
llvm::Function* emitDispatch(ModuleState& m) {
  const Abi& abi = m.abi;
  auto* type = llvm::FunctionType::get(
      abi.i32,
      {abi.ptr, abi.f64, abi.i32, abi.ptr, abi.i64, abi.f64, abi.f64, abi.ptr},
      false);
  auto* fn = llvm::Function::Create(type, llvm::GlobalValue::InternalLinkage,
                                    "mbc.call", abi.module);
  fn->addFnAttr(llvm::Attribute::NoUnwind);
  // A call costs a new call level in the runtime anyway; inlined at every
  // G65 the dispatcher only made the optimiser's work grow with the calls.
  fn->addFnAttr(llvm::Attribute::NoInline);
  llvm::Value* ctx = fn->getArg(0);
  llvm::Value* p = fn->getArg(1);
  auto* entry = llvm::BasicBlock::Create(abi.context, "entry", fn);
  auto* lookup = llvm::BasicBlock::Create(abi.context, "lookup", fn);
  auto* missing = llvm::BasicBlock::Create(abi.context, "missing", fn);
  llvm::IRBuilder<> b(entry);
  attribute(m, fn, b, nullptr);
  llvm::Value* n = b.CreateUnaryIntrinsic(llvm::Intrinsic::round, p);
  llvm::Value* valid = b.CreateAnd(
      b.CreateFCmpOGE(n, llvm::ConstantFP::get(abi.f64, 0)),
      b.CreateFCmpOLE(n, llvm::ConstantFP::get(abi.f64, kMaxCallNumber)));
  b.CreateCondBr(valid, lookup, missing);
  b.SetInsertPoint(lookup);
  llvm::SwitchInst* sw = b.CreateSwitch(b.CreateFPToSI(n, abi.i32), missing);
  for (std::size_t i = 0; i < m.ir.functions.size(); ++i) {
    const ir::Function& callee = m.ir.functions[i];
    if (callee.number < 0) {
      continue;
    }
    auto* bb = llvm::BasicBlock::Create(abi.context, "call", fn);
    sw->addCase(llvm::ConstantInt::get(abi.i32, callee.number), bb);
    b.SetInsertPoint(bb);
    llvm::Value* repeat = b.CreateIntrinsic(
        llvm::Intrinsic::fptosi_sat, {abi.i64, abi.f64},
        {b.CreateUnaryIntrinsic(llvm::Intrinsic::round, fn->getArg(5))});
    b.CreateRet(
        b.CreateCall(abi.fn(Rt::mbrt_run_call),
                     {ctx, m.cstring(callee.name), fn->getArg(2), fn->getArg(3),
                      fn->getArg(4), repeat, fn->getArg(6), m.bodies[i],
                      llvm::ConstantPointerNull::get(abi.ptr), fn->getArg(7)}));
  }
  b.SetInsertPoint(missing);
  b.CreateRet(b.CreateCall(abi.fn(Rt::mbrt_raise_program_not_found), {ctx, p}));
  return fn;
}

// int main(int argc, char** argv) { return mbc_aot_main(argc, argv, &table); }
void emitAotMain(ModuleState& m, llvm::GlobalVariable* table) {
  const Abi& abi = m.abi;
  llvm::FunctionCallee runner = abi.module.getOrInsertFunction(
      "mbc_aot_main",
      llvm::FunctionType::get(abi.i32, {abi.i32, abi.ptr, abi.ptr}, false));
  auto* fn = llvm::Function::Create(
      llvm::FunctionType::get(abi.i32, {abi.i32, abi.ptr}, false),
      llvm::GlobalValue::ExternalLinkage, "main", abi.module);
  llvm::IRBuilder<> b(llvm::BasicBlock::Create(abi.context, "entry", fn));
  attribute(m, fn, b, nullptr);
  b.CreateRet(b.CreateCall(runner, {fn->getArg(0), fn->getArg(1), table}));
}

// i32 mbc.resume(ptr ctx, ptr flow, ptr leave): what an NC block's flow asks
// for (evaluator resumeNc). Out of line, so that every NC block of a
// program costs one call whatever its case table.
llvm::Function* emitResume(ModuleState& m) {
  const Abi& abi = m.abi;
  auto* fn = llvm::Function::Create(
      llvm::FunctionType::get(abi.i32, {abi.ptr, abi.ptr, abi.ptr}, false),
      llvm::GlobalValue::InternalLinkage, "mbc.resume", abi.module);
  fn->addFnAttr(llvm::Attribute::NoUnwind);
  fn->addFnAttr(llvm::Attribute::NoInline);
  llvm::Value* ctx = fn->getArg(0);
  llvm::Value* flow = fn->getArg(1);
  auto block = [&](const char* name) {
    return llvm::BasicBlock::Create(abi.context, name, fn);
  };
  llvm::BasicBlock* entry = block("entry");
  llvm::BasicBlock* next = block("next");
  llvm::BasicBlock* sub = block("call");
  llvm::BasicBlock* ret = block("m99");
  llvm::BasicBlock* end = block("end");
  llvm::IRBuilder<> b(entry);
  attribute(m, fn, b, nullptr);
  auto field = [&](llvm::Type* type, unsigned index) {
    return b.CreateLoad(type, b.CreateStructGEP(abi.flow, flow, index));
  };
  auto i32 = [&](int v) { return llvm::ConstantInt::get(abi.i32, v); };
  // NEXT, or after the call: the M99 P of the callee, if any.
  auto answerSeq = [&] {
    b.CreateRet(
        b.CreateSelect(b.CreateICmpNE(field(abi.i32, kFlowHasSeq), i32(0)),
                       i32(kResumeSeq), i32(0)));
  };
  llvm::SwitchInst* sw = b.CreateSwitch(field(abi.i32, kFlowKind), next, 3);
  sw->addCase(i32(MBRT_FLOW_CALL), sub);
  sw->addCase(i32(MBRT_FLOW_RETURN), ret);
  sw->addCase(i32(MBRT_FLOW_END), end);

  b.SetInsertPoint(next);
  answerSeq();

  b.SetInsertPoint(sub);
  llvm::Value* status = b.CreateCall(
      m.dispatch, {ctx, b.CreateSIToFP(field(abi.i32, kFlowProgram), abi.f64),
                   field(abi.i32, kFlowCallKind), field(abi.ptr, kFlowArgs),
                   field(abi.i64, kFlowArgCount),
                   b.CreateSIToFP(field(abi.i64, kFlowRepeat), abi.f64),
                   field(abi.f64, kFlowStartSeq), flow});
  llvm::BasicBlock* called = block("called");
  llvm::BasicBlock* failed = block("failed");
  b.CreateCondBr(b.CreateICmpEQ(status, i32(0)), called, failed);
  b.SetInsertPoint(failed);
  b.CreateRet(status);
  b.SetInsertPoint(called);
  answerSeq();

  // M99 P in the main program jumps to that N of it (spec §5.8); M99
  // ends a batch run (spec Part A).
  b.SetInsertPoint(ret);
  llvm::Value* depth = b.CreateCall(abi.fn(Rt::mbrt_call_depth), {ctx});
  llvm::BasicBlock* inMain = block("main");
  llvm::BasicBlock* mainEnd = block("main.end");
  llvm::BasicBlock* inCall = block("call");
  b.CreateCondBr(b.CreateICmpEQ(depth, i32(0)), inMain, inCall);
  b.SetInsertPoint(inMain);
  llvm::BasicBlock* mainSeq = block("main.seq");
  b.CreateCondBr(b.CreateICmpNE(field(abi.i32, kFlowHasSeq), i32(0)), mainSeq,
                 mainEnd);
  b.SetInsertPoint(mainSeq);
  b.CreateRet(i32(kResumeSeq));
  b.SetInsertPoint(mainEnd);
  b.CreateCall(abi.fn(Rt::mbrt_finish), {ctx, i32(MBRT_END_MAIN_M99)});
  b.CreateRet(i32(MBRT_STOP));
  b.SetInsertPoint(inCall);
  llvm::Value* leave = fn->getArg(2);
  b.CreateStore(field(abi.i32, kFlowHasSeq),
                b.CreateStructGEP(abi.flow, leave, kFlowHasSeq));
  b.CreateStore(field(abi.f64, kFlowSeq),
                b.CreateStructGEP(abi.flow, leave, kFlowSeq));
  b.CreateRet(i32(kResumeLeave));

  b.SetInsertPoint(end);
  llvm::Value* counts = b.CreateICmpNE(field(abi.i32, kFlowCountsPart), i32(0));
  b.CreateCall(abi.fn(Rt::mbrt_finish),
               {ctx, b.CreateSelect(counts, i32(MBRT_END_M02_M30),
                                    i32(MBRT_END_PROGRAM))});
  b.CreateRet(i32(MBRT_STOP));
  return fn;
}

struct Table {
  llvm::GlobalVariable* programs; // the rows
  llvm::GlobalVariable* table;    // the mbrt_program_table of the rows
};

Table emitTable(ModuleState& m) {
  const Abi& abi = m.abi;
  std::vector<llvm::Constant*> rows;
  for (std::size_t i = 0; i < m.ir.functions.size(); ++i) {
    const ir::Function& f = m.ir.functions[i];
    rows.push_back(llvm::ConstantStruct::get(
        abi.program, {m.cstring(f.name),
                      llvm::ConstantInt::get(abi.i32, f.number), m.bodies[i]}));
  }
  auto* arrayType = llvm::ArrayType::get(abi.program, rows.size());
  auto* programs = new llvm::GlobalVariable(
      abi.module, arrayType, true, llvm::GlobalValue::PrivateLinkage,
      llvm::ConstantArray::get(arrayType, rows), "mbc.programs");
  auto* table = new llvm::GlobalVariable(
      abi.module, abi.table, true, llvm::GlobalValue::ExternalLinkage,
      llvm::ConstantStruct::get(
          abi.table, {programs, llvm::ConstantInt::get(abi.i64, rows.size())}),
      m.options.tableName);
  if (m.options.aotMain) {
    emitAotMain(m, table);
  }
  return {programs, table};
}

// mbrt_status mbc_O1000(mbrt_ctx*, const mbrt_word*, size_t).
void emitEntryPoints(ModuleState& m, const Table& table) {
  const Abi& abi = m.abi;
  auto* type =
      llvm::FunctionType::get(abi.i32, {abi.ptr, abi.ptr, abi.i64}, false);
  for (std::size_t i = 0; i < m.ir.functions.size(); ++i) {
    const ir::Function& f = m.ir.functions[i];
    if (!hasEntryPoint(f)) {
      continue;
    }
    auto* fn = llvm::Function::Create(type, llvm::GlobalValue::ExternalLinkage,
                                      entryPointName(f.number), abi.module);
    fn->addFnAttr(llvm::Attribute::NoUnwind);
    llvm::IRBuilder<> b(llvm::BasicBlock::Create(abi.context, "entry", fn));
    attribute(m, fn, b, &f);
    b.CreateCall(abi.fn(Rt::mbrt_name_programs), {fn->getArg(0), table.table});
    llvm::Value* row = b.CreateConstInBoundsGEP2_64(
        table.programs->getValueType(), table.programs, 0, i);
    b.CreateRet(
        b.CreateCall(abi.fn(Rt::mbrt_run_main),
                     {fn->getArg(0), row, fn->getArg(1), fn->getArg(2)}));
  }
}

} // namespace

} // namespace detail

bool hasUnoptimizedBody(const ir::Module& module) {
  for (const ir::Function& f : module.functions) {
    if (f.insts.size() > detail::kOptimizedSizeLimit) {
      return true;
    }
  }
  return false;
}

std::unique_ptr<llvm::Module> emitModule(const ir::Module& module,
                                         llvm::LLVMContext& context,
                                         const EmitOptions& options) {
  auto out = std::make_unique<llvm::Module>(options.moduleName, context);
  detail::ModuleState m(module, *out, options);
  if (options.debugInfo) {
    m.debug = std::make_unique<DebugInfo>(*out, module);
  }
  bool inParts = !options.bodiesHere.empty();
  for (const ir::Function& f : module.functions) {
    auto* body = llvm::Function::Create(
        m.abi.body,
        inParts ? llvm::GlobalValue::ExternalLinkage
                : llvm::GlobalValue::InternalLinkage,
        (inParts ? options.tableName + ".body." : "mbc.body.") + f.name, *out);
    if (inParts) {
      body->setVisibility(llvm::GlobalValue::HiddenVisibility);
    }
    body->addFnAttr(llvm::Attribute::NoUnwind);
    m.bodies.push_back(body);
  }
  m.dispatch = detail::emitDispatch(m);
  m.resume = detail::emitResume(m);
  for (std::size_t i = 0; i < module.functions.size(); ++i) {
    if (inParts && options.bodiesHere[i] == 0) {
      continue;
    }
    detail::FunctionEmitter(m, module.functions[i], m.bodies[i]).emit();
    // LLVM's loop and value passes grow faster than linearly on one huge
    // function (a long part program: thousands of NC blocks that M99 P
    // landings make one loop), so such a body is compiled as at -O0; its
    // time goes to the runtime's NC blocks anyway.
    if (module.functions[i].insts.size() > detail::kOptimizedSizeLimit) {
      m.bodies[i]->addFnAttr(llvm::Attribute::OptimizeNone);
      m.bodies[i]->addFnAttr(llvm::Attribute::NoInline);
    }
  }
  if (options.home) {
    const detail::Table table = detail::emitTable(m);
    if (options.entryPoints) {
      detail::emitEntryPoints(m, table);
    }
  }
  if (m.debug) {
    m.debug->finalize();
  }
  return out;
}

} // namespace mbc::codegen
