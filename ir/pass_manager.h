// The IR pass pipeline: the passes of ir/passes/passes.def run in the order
// of the default pipeline (pass_manager.cpp), each of which can be turned
// off by its cli name; the verifier may run after every pass.
#pragma once

#include "ir/ir.h"

#include <string>
#include <string_view>
#include <vector>

namespace mbc::ir {

#define PASS(Name, Cli, Function, Description) void Function(Module& m);
#include "ir/passes/passes.def"

struct PassInfo {
  std::string_view name; // the cli name, e.g. "constfold"
  void (*run)(Module&);
  std::string_view description;
};

/// Every pass, in the order of passes.def.
const std::vector<PassInfo>& allPasses();

/// Whether `name` is the cli name of a pass.
bool isPassName(std::string_view name);

/// The cli names, comma separated ("mem2ssa, copyprop, ...").
std::string passNameList();

struct PassOptions {
  std::vector<std::string> disabled; // cli names of passes not to run
  bool verifyEach = false;           // run the verifier after every pass
};

/// Runs the default pipeline. With verifyEach, a pass that leaves invalid IR
/// stops it: false, and `error` names the pass and the first problem.
bool runPasses(Module& m, const PassOptions& options, std::string& error);

} // namespace mbc::ir
