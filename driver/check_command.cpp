// `mbc check` (see check_command.h).
#include "driver/check_command.h"

#include "driver/options.h"
#include <mbc/engine.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

#include "runner/run_session.h"
#include "toolchain/compile_unit.h"

namespace mbc::driver {

namespace {

/// mbc check --machine --arg: the box the tool may reach, as a line.
void reportReach(const toolchain::CompiledUnit& cu,
                 const toolchain::MachineFacts& machine) {
  if (!cu.reachDecided) {
    std::fputs("mbc: where the tool goes is not decided (see the "
               "-Wstroke-undecided warnings)\n",
               stderr);
    return;
  }
  std::string text;
  for (std::size_t i = 0; i < cu.reachBox.size(); ++i) {
    const auto [lo, hi] = cu.reachBox[i];
    if (lo > hi) {
      continue; // no move
    }
    const auto bound = [](double v) {
      return std::isfinite(v) ? fmt::format("{:.3f}", v)
                              : std::string(v < 0 ? "-inf" : "+inf");
    };
    text += fmt::format("{}{} {}..{}", text.empty() ? "" : ", ",
                        machine.axes[i], bound(lo), bound(hi));
  }
  std::fprintf(stderr, "mbc: the tool may reach, in machine coordinates: %s\n",
               text.empty() ? "nothing (no move)" : text.c_str());
}

} // namespace

int checkCommand(const Options& o) {
  toolchain::CompiledUnit cu;
  // A profile given is checked too, and the checks defer to it.
  toolchain::LoadOptions load = loadOptions(o);
  if (!o.run.machinePath.empty()) {
    const runner::CtxPtr machine = runner::createContext(o.run);
    if (!machine) {
      return 2;
    }
    load.latheSystem = static_cast<char>(mbrt_lathe_system(machine.get()));
    mbrt_stats stats{};
    mbrt_get_stats(machine.get(), &stats);
    load.inch = std::string_view(stats.unit) == "inch";
    load.decimalPointInput =
        (static_cast<long>(mbrt_parameter(machine.get(), 3401)) & 1) != 0;
    if (load.alarmRanges) {
      load.machine = toolchain::machineFacts(machine.get());
    }
  }
  load.checkWarnings = true;
  if (!toolchain::loadUnit(o.files, load, cu)) {
    return 1;
  }
  if (load.machine) {
    reportReach(cu, *load.machine);
  }
  if (o.prove) {
    // The verdict after the findings, as the last line.
    const int blocks = cu.blocksThatMayAlarm + cu.strokeFindings;
    if (blocks > 0) {
      std::fprintf(stderr, "mbc: not proved: %d block%s may raise an alarm%s\n",
                   blocks, blocks == 1 ? "" : "s",
                   cu.strokeFindings > 0
                       ? " or take the tool past a stroke (or the analysis "
                         "could not follow it)"
                       : "");
      return 1;
    }
    std::fputs(load.machine ? "mbc: proved: no block can raise an alarm "
                              "the range analysis decides, nor take the "
                              "tool past a stroke\n"
                            : "mbc: proved: no block can raise an alarm "
                              "the range analysis decides\n",
               stderr);
  }
  return 0;
}

} // namespace mbc::driver
