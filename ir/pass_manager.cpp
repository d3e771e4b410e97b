// The pass manager (see pass_manager.h).
#include "ir/pass_manager.h"

#include "ir/verifier.h"

#include <fmt/format.h>

#include <algorithm>

namespace mbc::ir {

namespace {

// The default pipeline. mem2ssa first: every later pass sees SSA values
// instead of memory. Cleanups run again after the passes that create work
// for them (folded branches leave unreachable blocks and dead constants,
// forwarded loads leave foldable arithmetic).
constexpr std::string_view kPipeline[] = {
    "mem2ssa",     "copyprop",  "constfold", "dce",
    "simplifycfg", "loadelim",  "vacancy",   "cse",
    "copyprop",    "constfold", "dce",       "simplifycfg"};

const PassInfo* findPass(std::string_view name) {
  for (const PassInfo& p : allPasses()) {
    if (p.name == name) {
      return &p;
    }
  }
  return nullptr;
}

} // namespace

const std::vector<PassInfo>& allPasses() {
  static const std::vector<PassInfo> passes = {
#define PASS(Name, Cli, Function, Description)                                 \
  PassInfo{Cli, &Function, Description},
#include "ir/passes/passes.def"
  };
  return passes;
}

bool isPassName(std::string_view name) {
  return findPass(name) != nullptr;
}

std::string passNameList() {
  std::string out;
  for (const PassInfo& p : allPasses()) {
    out += out.empty() ? "" : ", ";
    out += p.name;
  }
  return out;
}

bool runPasses(Module& m, const PassOptions& options, std::string& error) {
  for (std::string_view name : kPipeline) {
    if (std::find(options.disabled.begin(), options.disabled.end(), name) !=
        options.disabled.end()) {
      continue;
    }
    findPass(name)->run(m);
    if (!options.verifyEach) {
      continue;
    }
    std::vector<std::string> problems = verify(m);
    if (!problems.empty()) {
      error = fmt::format("invalid IR after pass {}: {}{}", name, problems[0],
                          problems.size() > 1 ? fmt::format(" (and {} more)",
                                                            problems.size() - 1)
                                              : "");
      return false;
    }
  }
  return true;
}

} // namespace mbc::ir
