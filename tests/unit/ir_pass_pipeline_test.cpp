// The pass manager and the passes on whole programs: every pass, alone, in
// the pipeline or left out of it, keeps the IR valid and the run identical
// under the IR evaluator (variables, output, block count, alarm). The
// programs are the raw lowering (`mbc emit-ir --no-opt`) of small sources.
#include "ir/evaluator.h"
#include "ir/ir_parser.h"
#include "ir/pass_manager.h"
#include "ir/printer.h"
#include "ir/verifier.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

#include "ir_test_support.h"
#include "runtime_test_support.h"

namespace mbc::ir {
namespace {

using mbc::test::Machine;

// G65 P2000 A1 B2. / M30; O2000: IF [#2 GT 1] THEN #1 = 7 / M98 P3000 /
// #100 = #1 + #2 / M99; O3000: #101 = ADP[#1] * 10 + ADP[#2] / #2 = #2 + 1 /
// M99. The M98 subprogram shares O2000's locals and sees how they were set.
constexpr std::string_view kSharedFrame = R"mbir(
func @O1000 #1000 "shared_frame.nc" {
b0:
  br b1
b1:
  begin 2
  %2 = const 2000
  %3 = const 1
  %4 = const 1
  %5 = const 2
  %6 = call.macro %2, %3, A:int %4, B:dec %5
  resume %6, b2 []
b2:
  begin 3
  %9 = const 30
  %10 = nc M:int %9
  resume %10, b3 []
b3:
  ret !3
}

func @O2000 #2000 "shared_frame.nc" {
b0:
  br b1
b1:
  begin 5
  %2 = ldvar #2
  %3 = const 1
  %23 = tonum %2
  %4 = gt %23, %3
  condbr %4, b6, b2
b2:
  begin 6
  %10 = const 98
  %11 = const 3000
  %12 = nc M:int %10, P:int %11
  resume %12, b3 []
b3:
  begin 7
  %15 = ldvar #1
  %16 = ldvar #2
  %24 = tonum %15
  %25 = tonum %16
  %17 = add %24, %25
  stvar #100, %17
  br b4
b4:
  begin 8
  %21 = const 99
  %22 = nc M:int %21
  resume %22, b5 []
b5:
  ret !8
b6:
  %6 = const 7 !5
  stvar #1, %6 !5
  br b2 !5
}

func @O3000 #3000 "shared_frame.nc" {
b0:
  br b1
b1:
  begin 10
  %2 = const 1
  %3 = adp %2
  %4 = const 10
  %20 = tonum %3
  %5 = mul %20, %4
  %6 = const 2
  %7 = adp %6
  %21 = tonum %7
  %8 = add %5, %21
  stvar #101, %8
  br b2
b2:
  begin 11
  %12 = ldvar #2
  %13 = const 1
  %22 = tonum %12
  %14 = add %22, %13
  stvar #2, %14
  br b3
b3:
  begin 12
  %18 = const 99
  %19 = nc M:int %18
  resume %19, b4 []
b4:
  ret !12
}
)mbir";

// #1 = 0 / #2 = 3 / WHILE [#1 LT 5] DO1 / #100 = #100 + 10 / [#2 - #1] /
// #1 = #1 + 1 / END1 / M30: PS0112 in the fourth round.
constexpr std::string_view kLoopAlarm = R"mbir(
func @O1000 #1000 "loop_alarm.nc" {
b0:
  br b1
b1:
  begin 2
  %2 = const 0
  stvar #1, %2
  br b2
b2:
  begin 3
  %6 = const 3
  stvar #2, %6
  br b3
b3:
  begin 4
  %10 = ldvar #1
  %11 = const 5
  %35 = tonum %10
  %12 = lt %35, %11
  condbr %12, b4, b7
b4:
  begin 5
  %15 = ldvar #100
  %16 = const 10
  %17 = ldvar #2
  %18 = ldvar #1
  %36 = tonum %17
  %37 = tonum %18
  %19 = sub %36, %37
  %20 = div %16, %19
  %38 = tonum %15
  %21 = add %38, %20
  stvar #100, %21
  br b5
b5:
  begin 6
  %25 = ldvar #1
  %26 = const 1
  %39 = tonum %25
  %27 = add %39, %26
  stvar #1, %27
  br b6
b6:
  begin 7
  br b3
b7:
  begin 8
  %33 = const 30
  %34 = nc M:int %33
  resume %34, b8 []
b8:
  ret !8
}
)mbir";

// What a run leaves behind that any engine must reproduce, as text.
std::string run(const Module& m) {
  Machine machine;
  mbrt_status status = evaluate(m, 0, machine.ctx());
  mbrt_stats stats{};
  mbrt_get_stats(machine.ctx(), &stats);
  std::string out = "status " + std::to_string(status) + ", " +
                    std::to_string(stats.blocks) + " blocks\n";
  if (status) {
    out += machine.report();
  }
  out += machine.printed();
  for (int n = 100; n <= 102; ++n) {
    double v = machine.read(n);
    out += "#" + std::to_string(n) + "=" +
           (isVacant(v) ? std::string("vacant") : formatNumber(v)) + "\n";
  }
  return out;
}

std::vector<std::string> allBut(std::string_view keep) {
  std::vector<std::string> names;
  for (const PassInfo& p : allPasses()) {
    if (p.name != keep) {
      names.emplace_back(p.name);
    }
  }
  return names;
}

// Runs the pipeline with `disabled` off, verifying after every pass.
Module optimise(std::string_view text, std::vector<std::string> disabled) {
  Module m = parseText(text);
  std::string error;
  EXPECT_TRUE(runPasses(m, PassOptions{std::move(disabled), true}, error))
      << error;
  return m;
}

void expectSameRuns(std::string_view text) {
  std::string reference = run(parseText(text));
  EXPECT_EQ(run(optimise(text, {})), reference) << "all passes";
  for (const PassInfo& p : allPasses()) {
    EXPECT_EQ(run(optimise(text, {std::string(p.name)})), reference)
        << "without " << p.name;
    EXPECT_EQ(run(optimise(text, allBut(p.name))), reference)
        << "only " << p.name;
  }
}

TEST(IrPasses, NamesComeFromPassesDef) {
  EXPECT_TRUE(isPassName("mem2ssa"));
  EXPECT_TRUE(isPassName("dce"));
  EXPECT_FALSE(isPassName("nosuchpass"));
  EXPECT_EQ(passNameList(), "mem2ssa, copyprop, constfold, vacancy, "
                            "cse, loadelim, dce, simplifycfg");
}

TEST(IrPasses, EveryPassDisabledLeavesTheModuleAlone) {
  Module m = optimise(kLoopAlarm, allBut(""));
  EXPECT_EQ(print(m), print(parseText(kLoopAlarm)));
}

TEST(IrPasses, SharedFrameRunsTheSame) {
  EXPECT_EQ(run(parseText(kSharedFrame)),
            "status 0, 9 blocks\n#100=10\n#101=72\n#102=vacant\n");
  expectSameRuns(kSharedFrame);
}

TEST(IrPasses, AlarmInALoopRunsTheSame) {
  EXPECT_EQ(run(parseText(kLoopAlarm)).find("status 0"), std::string::npos);
  expectSameRuns(kLoopAlarm);
}

// The loop's locals become phis: no ldvar or stvar of #1 or #2 is left in
// the loop, and the division stays (it alarms).
TEST(IrPasses, LoopLocalsLeaveMemory) {
  std::string text = print(optimise(kLoopAlarm, {}));
  EXPECT_NE(text.find("phi"), std::string::npos) << text;
  EXPECT_EQ(text.find("ldvar #1\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("ldvar #2\n"), std::string::npos) << text;
  EXPECT_NE(text.find("div"), std::string::npos) << text;
}

// ADP reads how a local was set, so O3000 keeps its memory form.
TEST(IrPasses, AdpKeepsMemoryForm) {
  Module m = optimise(kSharedFrame, {});
  std::string text = print(m, m.functions[2]);
  EXPECT_NE(text.find("ldvar #2\n"), std::string::npos) << text;
  EXPECT_NE(text.find("stvar #2"), std::string::npos) << text;
}

TEST(IrPasses, VerifyEachNamesNoPassOnValidIr) {
  Module m = parseText(kSharedFrame);
  std::string error;
  EXPECT_TRUE(runPasses(m, PassOptions{{}, true}, error));
  EXPECT_EQ(error, "");
  EXPECT_TRUE(verify(m).empty());
}

} // namespace
} // namespace mbc::ir
