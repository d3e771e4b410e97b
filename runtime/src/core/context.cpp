// What each part of the context does at power-on, reset and the start of a
// run: one place for each part's life, so that no field of it is left
// behind when a run ends (api/lifetime.cpp calls them in order).
#include "context.h"

namespace mbc::rt {

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

void LatheState::reset() {
  *this = LatheState{};
}

void LatheState::startRun() {
  shapeReading.code = 0;
}

} // namespace mbc::rt
