// IR -> LLVM IR for a whole module: the program bodies, the dispatcher that
// turns a program number into a call (mbc.call), the program table and the
// C entry points.
#include "codegen/emit_module.h"

#include "codegen/emitter.h"

#include <fmt/format.h>
#include <llvm/IR/Intrinsics.h>

namespace mbc::codegen {

namespace detail {

llvm::Constant* ModuleState::cstring(const std::string& text) {
  auto it = strings.find(text);
  if (it != strings.end()) {
    return it->second;
  }
  llvm::Constant* init =
      llvm::ConstantDataArray::getString(abi.context, text, true);
  auto* global =
      new llvm::GlobalVariable(abi.module, init->getType(), true,
                               llvm::GlobalValue::PrivateLinkage, init, ".str");
  global->setUnnamedAddr(llvm::GlobalValue::UnnamedAddr::Global);
  global->setAlignment(llvm::Align(1));
  return strings.emplace(text, global).first->second;
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

// i32 mbc.call(ptr ctx, double p, i32 macro, ptr args, i64 count,
//              double repeat, ptr out): the program numbered round(p), called
// round(repeat) times, or PS0076 (evaluator findProgram and call).
llvm::Function* emitDispatch(ModuleState& m) {
  const Abi& abi = m.abi;
  auto* type = llvm::FunctionType::get(
      abi.i32, {abi.ptr, abi.f64, abi.i32, abi.ptr, abi.i64, abi.f64, abi.ptr},
      false);
  auto* fn = llvm::Function::Create(type, llvm::GlobalValue::InternalLinkage,
                                    "mbc.call", abi.module);
  fn->addFnAttr(llvm::Attribute::NoUnwind);
  llvm::Value* ctx = fn->getArg(0);
  llvm::Value* p = fn->getArg(1);
  auto* entry = llvm::BasicBlock::Create(abi.context, "entry", fn);
  auto* lookup = llvm::BasicBlock::Create(abi.context, "lookup", fn);
  auto* missing = llvm::BasicBlock::Create(abi.context, "missing", fn);
  llvm::IRBuilder<> b(entry);
  attribute(m, fn, b, nullptr);
  llvm::Value* n = b.CreateUnaryIntrinsic(llvm::Intrinsic::round, p);
  llvm::Value* valid =
      b.CreateAnd(b.CreateFCmpOGE(n, llvm::ConstantFP::get(abi.f64, 0)),
                  b.CreateFCmpOLE(n, llvm::ConstantFP::get(abi.f64, 1e8)));
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
                      fn->getArg(4), repeat, m.bodies[i],
                      llvm::ConstantPointerNull::get(abi.ptr), fn->getArg(6)}));
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

llvm::GlobalVariable* emitTable(ModuleState& m) {
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
  return programs;
}

// mbrt_status mbc_O1000(mbrt_ctx*, const mbrt_word*, size_t).
void emitEntryPoints(ModuleState& m, llvm::GlobalVariable* programs) {
  const Abi& abi = m.abi;
  auto* type =
      llvm::FunctionType::get(abi.i32, {abi.ptr, abi.ptr, abi.i64}, false);
  for (std::size_t i = 0; i < m.ir.functions.size(); ++i) {
    const ir::Function& f = m.ir.functions[i];
    if (f.number < 0) {
      continue;
    }
    auto* fn = llvm::Function::Create(type, llvm::GlobalValue::ExternalLinkage,
                                      entryPointName(f.number), abi.module);
    fn->addFnAttr(llvm::Attribute::NoUnwind);
    llvm::IRBuilder<> b(llvm::BasicBlock::Create(abi.context, "entry", fn));
    attribute(m, fn, b, &f);
    llvm::Value* row =
        b.CreateConstInBoundsGEP2_64(programs->getValueType(), programs, 0, i);
    b.CreateRet(
        b.CreateCall(abi.fn(Rt::mbrt_run_main),
                     {fn->getArg(0), row, fn->getArg(1), fn->getArg(2)}));
  }
}

} // namespace

} // namespace detail

std::string entryPointName(int number) {
  return fmt::format("mbc_O{}", number);
}

std::unique_ptr<llvm::Module> emitModule(const ir::Module& module,
                                         llvm::LLVMContext& context,
                                         const EmitOptions& options) {
  auto out = std::make_unique<llvm::Module>(options.moduleName, context);
  detail::ModuleState m(module, *out, options);
  if (options.debugInfo) {
    m.debug = std::make_unique<DebugInfo>(*out, module);
  }
  for (const ir::Function& f : module.functions) {
    auto* body =
        llvm::Function::Create(m.abi.body, llvm::GlobalValue::InternalLinkage,
                               "mbc.body." + f.name, *out);
    body->addFnAttr(llvm::Attribute::NoUnwind);
    m.bodies.push_back(body);
  }
  m.dispatch = detail::emitDispatch(m);
  for (std::size_t i = 0; i < module.functions.size(); ++i) {
    detail::FunctionEmitter(m, module.functions[i], m.bodies[i]).emit();
  }
  llvm::GlobalVariable* programs = detail::emitTable(m);
  if (options.entryPoints) {
    detail::emitEntryPoints(m, programs);
  }
  if (m.debug) {
    m.debug->finalize();
  }
  return out;
}

} // namespace mbc::codegen
