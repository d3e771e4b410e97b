// ORC LLJIT: the runtime's functions are given to the JIT by address from
// runtime_functions.def (the mbc executable exports no symbols), the C
// library's from the process.
#include "codegen/jit.h"

#include "codegen/abi.h"
#include "codegen/emit_module.h"
#include "codegen/native_target.h"
#include "codegen/optimize.h"
#include "codegen/out_of_memory.h"
#include "codegen/verify.h"
#include <mbc/compiled.h>

#include <llvm/Config/llvm-config.h>
#include <llvm/ExecutionEngine/JITEventListener.h>
#include <llvm/ExecutionEngine/Orc/ExecutionUtils.h>
#include <llvm/ExecutionEngine/Orc/LLJIT.h>
#include <llvm/ExecutionEngine/Orc/RTDyldObjectLinkingLayer.h>
#include <llvm/ExecutionEngine/SectionMemoryManager.h>

namespace mbc::codegen {

namespace {

struct RuntimeSymbol {
  const char* name;
  void* address;
};

const RuntimeSymbol kRuntimeSymbols[] = {
#define RT(Name, ...) {#Name, reinterpret_cast<void*>(&Name)},
#include "codegen/runtime_functions.def"
};

std::string message(llvm::Error e) {
  return llvm::toString(std::move(e));
}

llvm::Error defineRuntime(llvm::orc::LLJIT& jit) {
  llvm::orc::MangleAndInterner mangle(jit.getExecutionSession(),
                                      jit.getDataLayout());
  llvm::orc::SymbolMap symbols;
  for (const RuntimeSymbol& s : kRuntimeSymbols) {
#if LLVM_VERSION_MAJOR >= 17
    symbols[mangle(s.name)] = {llvm::orc::ExecutorAddr::fromPtr(s.address),
                               llvm::JITSymbolFlags::Exported};
#else
    symbols[mangle(s.name)] =
        llvm::JITEvaluatedSymbol(llvm::pointerToJITTargetAddress(s.address),
                                 llvm::JITSymbolFlags::Exported);
#endif
  }
  llvm::orc::JITDylib& lib = jit.getMainJITDylib();
  if (llvm::Error e = lib.define(llvm::orc::absoluteSymbols(symbols))) {
    return e;
  }
  auto process = llvm::orc::DynamicLibrarySearchGenerator::GetForCurrentProcess(
      jit.getDataLayout().getGlobalPrefix());
  if (!process) {
    return process.takeError();
  }
  lib.addGenerator(std::move(*process));
  return llvm::Error::success();
}

// RuntimeDyld with gdb's JIT registration: gdb then reads the DWARF of
// the objects it is told about. The creator's and the memory manager's
// parameters differ between LLVM versions and are not needed here.
auto debuggableObjectLayer =
    [](llvm::orc::ExecutionSession& session,
       auto&&...) -> llvm::Expected<std::unique_ptr<llvm::orc::ObjectLayer>> {
  auto layer = std::make_unique<llvm::orc::RTDyldObjectLinkingLayer>(
      session,
      [](auto&&...) -> std::unique_ptr<llvm::RuntimeDyld::MemoryManager> {
        return std::make_unique<llvm::SectionMemoryManager>();
      });
  layer->registerJITEventListener(
      *llvm::JITEventListener::createGDBRegistrationListener());
  return layer;
};

} // namespace

Jit::~Jit() = default;

std::unique_ptr<Jit> Jit::compile(const ir::Module& module,
                                  const JitOptions& options,
                                  std::string& error) {
  ExitOnOutOfMemory exitOnOutOfMemory;
  int optLevel = options.optLevel;
  initializeNativeTarget();
  auto builder = llvm::orc::JITTargetMachineBuilder::detectHost();
  if (!builder) {
    error = message(builder.takeError());
    return nullptr;
  }
  auto tm = builder->createTargetMachine();
  if (!tm) {
    error = message(tm.takeError());
    return nullptr;
  }
  auto context = makeContext();
  EmitOptions emit;
  emit.entryPoints = false;
  emit.debugInfo = options.debugInfo;
  std::unique_ptr<llvm::Module> m = emitModule(module, *context, emit);
  m->setDataLayout((*tm)->createDataLayout());
  m->setTargetTriple((*tm)->getTargetTriple().str());
  if (!verifyEmitted(*m, error)) {
    return nullptr;
  }
  optimize(*m, **tm, optLevel);
  builder->setCodeGenOptLevel(codeGenLevel(optLevel, *m));

  llvm::orc::LLJITBuilder jitBuilder;
  jitBuilder.setJITTargetMachineBuilder(*builder);
  if (options.debugInfo) {
    jitBuilder.setObjectLinkingLayerCreator(debuggableObjectLayer);
  }
  auto lljit = jitBuilder.create();
  if (!lljit) {
    error = message(lljit.takeError());
    return nullptr;
  }
  if (llvm::Error e = defineRuntime(**lljit)) {
    error = message(std::move(e));
    return nullptr;
  }
  if (llvm::Error e = (*lljit)->addIRModule(
          llvm::orc::ThreadSafeModule(std::move(m), std::move(context)))) {
    error = message(std::move(e));
    return nullptr;
  }
  auto symbol = (*lljit)->lookup(emit.tableName);
  if (!symbol) {
    error = message(symbol.takeError());
    return nullptr;
  }
  std::unique_ptr<Jit> jit(new Jit);
#if LLVM_VERSION_MAJOR >= 15
  jit->table_ = symbol->toPtr<const mbrt_program_table*>();
#else
  jit->table_ = llvm::jitTargetAddressToPointer<const mbrt_program_table*>(
      symbol->getAddress());
#endif
  jit->jit_ = std::move(*lljit);
  return jit;
}

} // namespace mbc::codegen
