// Context lifetime, sinks and run bookkeeping (blocks, limits, finish,
// statistics): the parts of the C ABI that are not about variables, calls,
// NC blocks, alarms or output.
#include <mbc/compiled.h>
#include <mbc/read_file.h>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <new>

#include "context.h"
#include "corner_state.h"
#include "cutter_comp.h"
#include "cutter_comp_state.h"
#include "flat_gcode.h"
#include "frames.h"
#include "lathe_corners.h"
#include "lathe_state.h"
#include "sysvars.h"
#include "tool_moves.h"

namespace mbc::rt {

namespace {

/// Machine data from the profile: offsets to counts, commons, axes.
void loadProfile(mbrt_ctx& ctx) {
  const Profile& profile = ctx.profile;
  ctx.axisIndex.fill(-1);
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    ctx.axisIndex[profile.axes[axis] - 'A'] = static_cast<std::int8_t>(axis);
  }
  ctx.machine.modal.inch = profile.inch;
  ctx.data.workOffsets.assign(kWorkOffsetCount, AxisCounts{});
  for (int index = 0; index < kWorkOffsetCount; ++index) {
    for (int axis = 0; axis < MBRT_MAX_AXES; ++axis) {
      ctx.data.workOffsets[index][axis] = static_cast<Counts>(
          roundToAxisCounts(ctx, axis, profile.workOffsets[index][axis]));
    }
  }
  ctx.data.toolOffsets = profile.toolOffsets;
  ctx.data.latheOffsets = profile.latheOffsets;
  ctx.data.commons.fill(vacant());
  ctx.data.commons98000.fill(vacant());
  for (const auto& [number, value] : profile.variables) {
    ctx.data.commons[number] = value;
  }
  ctx.data.partsCount = profile.partsCount;
  ctx.data.partsRequired = profile.partsRequired;
  ctx.data.inputWords = {};
  for (const auto& [number, value] : profile.inputSignals) {
    setInputSignal(ctx, number, value);
  }
  // Call levels never outgrow this, so pushing one does not allocate.
  ctx.stack.levels.reserve(profile.macroNesting + 2);
  ctx.stack.calls.reserve(profile.totalNesting + 2);
}

/// The machine's power-on state (MachineState::reset), no held moves, the
/// output signals off and no lathe cycle settings or shapes. Machine data
/// (commons, offsets, part counters, #3002, settings) stays.
void resetMachineState(mbrt_ctx& ctx) {
  ctx.machine.reset(ctx.profile);
  *ctx.compensation = CompensationState{};
  *ctx.corner = CornerInsertion{};
  ctx.lathe->reset();
  ctx.run.shapeCycle = 0;    // the shape being read went with the lathe's state
  ctx.data.outputWords = {}; // the output signals #1100+ are off at power-on
  switchUnits(ctx, ctx.profile.inch); // offsets back to the profile's unit
}

/// A run begins as a control starts a program after RESET: a new call
/// stack, locals and counters; the machine stays where the last run left it
/// (MachineState::startRun), and RESET cancels modal calls (G66), held
/// moves and #3003/#3004.
void startRun(mbrt_ctx& ctx, const char* mainProgram) {
  ctx.stack.startRun(mainProgram);
  ctx.machine.startRun(ctx.profile);
  *ctx.compensation = CompensationState{};
  *ctx.corner = CornerInsertion{};
  resyncProgram(ctx);
  // A main program the machine cannot have alarms at its first block.
  ctx.run.startRun(ctx.profile.programNumberDigits == 4 &&
                   ctx.stack.mainProgramNumber > kMaxProgramNumber4Digits);
  ctx.host.startRun();
}

/// A new context's state from its profile: what mbrt_create makes, and
/// mbrt_reset again.
void powerOn(mbrt_ctx& ctx, Profile profile) {
  ctx.data.profileParameters = profile.parameters;
  ctx.data.profileAxisParameters = profile.axisParameters;
  ctx.profile = std::move(profile);
  loadProfile(ctx);
  resetMachineState(ctx);
  startRun(ctx, "MAIN");
}

/// What the host set on a context, which a reset keeps: where the output
/// goes, the limits and the block skip switches.
void keepHostSettings(mbrt_ctx& from, mbrt_ctx& to) {
  to.host = std::move(from.host);
  to.run.keepHostSettings(from.run);
}

} // namespace

} // namespace mbc::rt

using namespace mbc;
using namespace mbc::rt;

mbrt_ctx::mbrt_ctx()
    : compensation(std::make_unique<CompensationState>()),
      corner(std::make_unique<CornerInsertion>()),
      lathe(std::make_unique<LatheState>()) {
}

mbrt_ctx::~mbrt_ctx() = default;
mbrt_ctx::mbrt_ctx(mbrt_ctx&&) noexcept = default;
mbrt_ctx& mbrt_ctx::operator=(mbrt_ctx&&) noexcept = default;

mbrt_ctx* mbrt_create(const char* profile_json, char* err, size_t err_size) {
  try {
    std::string error;
    auto profile = profile_json != nullptr
                       ? parseProfile(profile_json, error)
                       : std::optional<Profile>(defaultProfile());
    if (!profile) {
      copyText(error, err, err_size);
      return nullptr;
    }
    auto* ctx = new mbrt_ctx;
    powerOn(*ctx, std::move(*profile));
    return ctx;
  } catch (const std::bad_alloc&) {
    // No allocation here: there is no memory for one.
    copyText("cannot create the runtime: out of memory", err, err_size);
    return nullptr;
  } catch (const std::exception& e) {
    copyText(std::string("cannot create the runtime: ") + e.what(), err,
             err_size);
    return nullptr;
  }
}

mbrt_ctx* mbrt_create_from_file(const char* path, char* err, size_t err_size) {
  std::string text;
  if (int error = mbc::readFile(path != nullptr ? path : "", text)) {
    copyText(fmt::format("cannot read machine profile {}: {}",
                         path != nullptr ? path : "(null)",
                         std::strerror(error)),
             err, err_size);
    return nullptr;
  }
  return mbrt_create(text.c_str(), err, err_size);
}

void mbrt_destroy(mbrt_ctx* ctx) {
  if (ctx == nullptr || refuseInSink(*ctx, "mbrt_destroy")) {
    return;
  }
  delete ctx;
}

void mbrt_set_motion_sink(mbrt_ctx* ctx, mbrt_motion_fn fn, void* user) {
  ctx->host.motionSink = {fn, user};
}

void mbrt_set_print_sink(mbrt_ctx* ctx, mbrt_text_fn fn, void* user) {
  ctx->host.printSink = {fn, user};
}

void mbrt_set_message_sink(mbrt_ctx* ctx, mbrt_text_fn fn, void* user) {
  ctx->host.messageSink = {fn, user};
}

void mbrt_set_trace_sink(mbrt_ctx* ctx, mbrt_text_fn fn, void* user) {
  ctx->host.traceSink = {fn, user};
  ctx->run.block.tracing = fn != nullptr ? 1 : 0;
}

void mbrt_set_gcode_sink(mbrt_ctx* ctx, mbrt_text_fn fn, void* user) {
  ctx->host.gcodeSink = {fn, user};
}

void mbrt_interrupt(mbrt_ctx* ctx) {
  ctx->run.interrupted = true;
  ctx->run.setBlockLimit(0);
}

void mbrt_out_of_memory(mbrt_ctx* ctx) {
  ctx->run.outOfMemory = true;
  ctx->run.setBlockLimit(0);
}

void mbrt_set_max_blocks(mbrt_ctx* ctx, uint64_t max_blocks) {
  ctx->run.maxBlocks = max_blocks != 0 ? max_blocks : kDefaultMaxBlocks;
  ctx->run.setBlockLimit(ctx->run.maxBlocks);
}

double mbrt_parameter(const mbrt_ctx* ctx, int number) {
  return ctx->profile.parameter(number);
}

int mbrt_lathe_system(const mbrt_ctx* ctx) {
  return ctx->profile.lathe() ? ctx->profile.gCodeSystem : 0;
}

int mbrt_block_skip(const mbrt_ctx* ctx) {
  return ctx->profile.blockSkip;
}

void mbrt_set_block_skip(mbrt_ctx* ctx, unsigned mask) {
  ctx->run.skipMask = mask;
}

int mbrt_skip_switch(const mbrt_ctx* ctx, int n) {
  if (n == 1 && ctx->profile.blockSkip) {
    return 1;
  }
  return n > 0 && n < 32 && ((ctx->run.skipMask >> n) & 1U) != 0;
}

void mbrt_start(mbrt_ctx* ctx, const char* main_program) {
  if (!refuseInSink(*ctx, "mbrt_start")) {
    startRun(*ctx, main_program);
    flattenProgramStart(*ctx);
  }
}

void mbrt_reset_state(mbrt_ctx* ctx) {
  if (!refuseInSink(*ctx, "mbrt_reset_state")) {
    resetMachineState(*ctx);
    startRun(*ctx, "MAIN");
  }
}

void mbrt_reset(mbrt_ctx* ctx) {
  if (refuseInSink(*ctx, "mbrt_reset")) {
    return;
  }
  // A new context in the old one's place: no state of a run (a clock, a
  // setting, a signal, whatever is added later) can outlive the reset, so
  // that runs after it never see each other.
  mbrt_ctx fresh;
  keepHostSettings(*ctx, fresh);
  Profile profile = std::move(ctx->profile);
  profile.parameters = std::move(ctx->data.profileParameters); // undo G10 L52
  profile.axisParameters = std::move(ctx->data.profileAxisParameters);
  deriveParameterFields(profile);
  powerOn(fresh, std::move(profile));
  *ctx = std::move(fresh);
}

mbrt_status mbrt_begin_block(mbrt_ctx* ctx, const char* file, int line) {
  ctx->run.block.file = file;
  ctx->run.block.line = line;
  if (++ctx->run.block.blocks > std::atomic_ref(ctx->run.block.max_blocks)
                                    .load(std::memory_order_relaxed)) {
    return mbrt_block_limit(ctx);
  }
  return 0;
}

mbrt_status mbrt_block_limit(mbrt_ctx* ctx) {
  if (ctx->run.illegalMainNumber) {
    return checkProgramNumber(*ctx, ctx->stack.mainProgramNumber);
  }
  if (ctx->run.outOfMemory) {
    return raise(*ctx, AlarmId::OutOfMemory,
                 "memory ran out; the run was stopped before this block");
  }
  if (ctx->run.refusedInSink != nullptr) {
    return raise(*ctx, AlarmId::CalledFromSink,
                 fmt::format("{} was called from inside a sink (a motion, "
                             "text or alarm callback); the run was stopped "
                             "before this block",
                             ctx->run.refusedInSink));
  }
  if (ctx->run.interrupted) {
    return raise(*ctx, AlarmId::Interrupted,
                 "the run was stopped before this block");
  }
  if (ctx->run.output.passed()) {
    return raiseOutputLimit(*ctx);
  }
  return raise(*ctx, AlarmId::ExecutionLimit,
               fmt::format("more than {} blocks executed (--max-blocks)",
                           ctx->run.maxBlocks));
}

void mbrt_finish(mbrt_ctx* ctx, int end_kind) {
  releaseCornerMove(*ctx);       // a chamfer block the run ended after
  releaseHeldMoves(*ctx, false); // the last move of a compensated contour
  if (end_kind == MBRT_END_M02_M30) {
    ctx->data.partsCount += 1.0;
  } else if (end_kind == MBRT_END_MAIN_M99) {
    ctx->run.mainM99 = true;
  }
}

void mbrt_get_stats(const mbrt_ctx* ctx, mbrt_stats* out) {
  out->blocks = ctx->run.block.blocks;
  out->moves = ctx->machine.moves;
  out->optional_stops = ctx->run.optionalStops;
  out->main_m99 = ctx->run.mainM99;
  // Lengths are kept in mm, the box in counts: the summary speaks the
  // profile's unit.
  const double unit = ctx->profile.inch ? 25.4 : 1.0;
  const RunStats& stats = ctx->machine.stats;
  out->unit = ctx->profile.inch ? "inch" : "mm";
  out->feed_length = stats.feedLength / unit;
  out->rapid_length = stats.rapidLength / unit;
  out->cycle_time = stats.seconds;
  out->axis_count = ctx->axisCount();
  out->axis_names = ctx->profile.axes.c_str();
  for (int axis = 0; axis < ctx->axisCount(); ++axis) {
    double low = 0.0;
    double high = 0.0;
    bool any = false;
    for (const bool inch : {false, true}) {
      const CountsBox& box = stats.box[inch];
      if (box.any) {
        const double scale = ctx->boxScale(axis, inch);
        low =
            any ? std::min(low, box.low[axis] / scale) : box.low[axis] / scale;
        high = any ? std::max(high, box.high[axis] / scale)
                   : box.high[axis] / scale;
        any = true;
      }
    }
    const double axisUnit = ctx->isRotary(axis) ? 1.0 : unit; // degrees
    out->box_min[axis] = low / axisUnit;
    out->box_max[axis] = high / axisUnit;
  }
}
