// What each part of the context does at power-on, reset and the start of a
// run: one place for each part's life, so that no field of it is left
// behind when a run ends (api/lifetime.cpp calls them in order).
#include "context.h"

#include <cstdlib>
#include <ctime>

namespace mbc::rt {

namespace {

/// #3011/#3012 are fixed for the whole run. SOURCE_DATE_EPOCH makes them
/// reproducible (UTC); otherwise they are the local date and time.
void takeDateAndTime(RunControl& run) {
  std::tm tm{};
  const char* epoch = std::getenv("SOURCE_DATE_EPOCH");
  if (epoch != nullptr && *epoch != '\0') {
    const auto seconds =
        static_cast<std::time_t>(std::strtoll(epoch, nullptr, 10));
    gmtime_r(&seconds, &tm);
  } else {
    const std::time_t now = std::time(nullptr);
    localtime_r(&now, &tm);
  }
  run.date =
      (tm.tm_year + 1900) * 10000.0 + (tm.tm_mon + 1) * 100.0 + tm.tm_mday;
  run.timeOfDay = tm.tm_hour * 10000.0 + tm.tm_min * 100.0 + tm.tm_sec;
}

} // namespace

void MachineState::clearModalCodes(const Profile& profile) {
  const bool inch = modal.inch;
  modal = ModalState{};
  modal.inch = inch;
  if (profile.lathe()) {
    // A lathe starts in G18, and feeds per revolution unless 3402#4 FPM.
    modal.plane = 18;
    modal.feedMode = profile.parameterBit(3402, 4) ? 94 : 95;
  }
  lastWords = {};
}

void MachineState::reset(const Profile& profile) {
  const double hours = clockHours;
  const bool inch = modal.inch;
  *this = MachineState{};
  clockHours = hours;
  modal.inch = inch;
  clearModalCodes(profile);
}

void MachineState::startRun(const Profile& profile) {
  if (profile.clearOnReset) {
    clearModalCodes(profile);
  } else {
    const ModalState powerOn;
    modal.compensation = powerOn.compensation;
    modal.cycle = powerOn.cycle;
    modal.cycleData = powerOn.cycleData;
    modal.rigidTapping = powerOn.rigidTapping;
    modal.seriesFifteenTap = powerOn.seriesFifteenTap;
  }
  moves = 0;
  stats = RunStats{};
}

void CallStack::startRun(const char* program) {
  mainProgram = program != nullptr ? program : "MAIN";
  mainProgramNumber = parseProgramNumber(mainProgram.c_str());
  entrySequence = 0.0;
  // Cleared, not replaced: the levels keep the room reserved for the
  // deepest nesting, so that a call allocates nothing.
  calls.clear();
  modalCalls.clear();
  blockCalls.clear();
  macroDepth = 0;
  subDepth = 0;
  levels.assign(1, LocalLevel{});
}

void RunControl::keepHostSettings(const RunControl& from) {
  block.tracing = from.block.tracing;
  maxBlocks = from.maxBlocks;
  output.limit = from.output.limit;
  skipMask = from.skipMask;
}

void RunControl::startRun(bool illegalMain) {
  // Field by field, not from a fresh RunControl: another thread or a
  // signal handler may lower the block limit at any time (mbrt_interrupt),
  // so the limit is only ever stored atomically.
  block.file = nullptr;
  block.line = 0;
  block.blocks = 0;
  blockSequence = -1.0;
  cycleLabel = 0;
  cycleBlock = BlockPlace{};
  shapeCycle = 0;
  dryRun = false;
  interrupted = false;
  outOfMemory = false;
  illegalMainNumber = illegalMain;
  refusedInSink = nullptr;
  output = OutputBudget{0, output.limit};
  optionalStops = 0;
  mainM99 = false;
  alarm = PendingAlarm{};
  parameterInput = false;
  singleBlockBits = 0.0;
  feedHoldBits = 0.0;
  takeDateAndTime(*this);
  setBlockLimit(illegalMain ? 0 : maxBlocks);
}

void HostOutputs::startRun() {
  motionBuffer.clear();
}

} // namespace mbc::rt
